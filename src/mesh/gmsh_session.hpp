// The one gmsh instance of the process (gmsh keeps global state and 4.8 cannot tell whether it is
// initialised, toolchain G3/G4). gmsh_model() starts gmsh on first use, silenced (G2: its messages
// are captured by its logger and attached to our errors; PLYIMPACT_GMSH_VERBOSE=1 prints them),
// and gmsh is finalised at exit. A GmshModel is one named gmsh model, removed when it goes out of
// scope. gmsh_call() runs API calls and turns gmsh's std::string exceptions (G1) into InputError.
// Not thread-safe (G5): mesh from one thread.
#pragma once

#include <string>

#include "core/error.hpp"

namespace plyimpact::mesh {

class GmshModel {
 public:
  explicit GmshModel(const std::string& name);  // initialises gmsh if needed, adds and selects the model
  ~GmshModel();
  GmshModel(const GmshModel&) = delete;
  GmshModel& operator=(const GmshModel&) = delete;
  // gmsh's messages since this model was created (for a report or a failure message).
  std::string log() const;

 private:
  std::string name_;
};

[[noreturn]] void throw_gmsh_error(const std::string& while_doing, const std::string& gmsh_message);

// Runs f() (gmsh API calls); a gmsh failure becomes
// InputError("meshing failed in gmsh while <what>: <gmsh message>").
template <class F>
auto gmsh_call(const std::string& what, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::string& e) {
    throw_gmsh_error(what, e);
  }
}

}  // namespace plyimpact::mesh
