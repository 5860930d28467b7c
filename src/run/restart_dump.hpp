// Restart dumps, LS-DYNA's *DATABASE_BINARY_D3DUMP in our terms: the whole run state in one binary
// file (core/state_io records) so a run can be continued after a stop or extended past its
// termination time, and continues exactly as if it had never stopped. The file holds, in order:
//   dump/      format number, program version, the scene's identity, time and cycle;
//   solver/    Solver::visit_state (kinematics, stresses, material history, alive masks, rigid
//              bodies, contact springs and search state, interfaces, energy accumulators);
//   run/       every observer's state (history rows, frame times, the samplers' next marks, the
//              checks' extremes).
// The scene's identity is a digest of the effective scene (file plus overrides) without the keys a
// continuation may change (config/scene_digest.hpp) and of the mesh the model was built from, so a
// dump is refused by another scene, by the same scene edited, and by another program version or
// dump format, each with a message that says which. Raw native doubles: a dump is read back on the
// machine type that wrote it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "run/run_observer.hpp"
#include "solver/solver.hpp"

namespace plyimpact::run {

inline constexpr const char* kDumpFileName = "restart.dump";

// The scene digest combined with the model's reference coordinates and connectivity (a mesh read
// from a file changes the model without changing the scene text).
std::uint64_t run_identity(std::uint64_t scene_digest, const model::Model& model);

// An identity as 16 hex digits (messages, the output folder's marker).
std::string identity_text(std::uint64_t identity);

struct DumpInfo {
  std::string version;      // program version that wrote it
  std::uint64_t format = 0;
  std::uint64_t identity = 0;
  double time = 0;          // s
  long cycle = 0;
};

// A dump read into memory with its header checked (the file itself may then be replaced).
struct LoadedDump {
  std::filesystem::path file;
  DumpInfo info;
  std::string bytes;
};

// Reads `dump` and refuses (InputError naming the file and what differs) a dump of another format,
// program version or scene.
LoadedDump load_dump(const std::filesystem::path& dump, std::uint64_t identity);

// The run state at the end of a cycle (after the observers' after_cycle), written atomically.
void write_dump(const std::filesystem::path& dump, std::uint64_t identity, solver::Solver& solver,
                const std::vector<RunObserver*>& observers);

// Reads a dump written by write_dump for the same scene into a solver freshly built from the model
// and into the same observers. Throws InputError when the file does not match or is truncated.
void read_dump(const LoadedDump& dump, solver::Solver& solver, const std::vector<RunObserver*>& observers);

}  // namespace plyimpact::run
