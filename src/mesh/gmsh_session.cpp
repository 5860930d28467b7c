#include "mesh/gmsh_session.hpp"

#include <gmsh.h>
#include <omp.h>

#include <cstdlib>
#include <vector>

namespace plyimpact::mesh {
namespace {

// Initialised on first use, finalised by the static destructor at exit (after main returns).
struct GmshProcess {
  bool verbose = false;
  GmshProcess() {
    // gmsh::initialize applies its General.NumThreads (default 1) through omp_set_num_threads,
    // which would make every later OpenMP region of the process (the solver's element pass) serial
    // whatever OMP_NUM_THREADS or control.threads say. Meshing is serial anyway: put it back.
    const int threads = omp_get_max_threads();
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);  // never main's argv (G3)
    omp_set_num_threads(threads);
    const char* env = std::getenv("PLYIMPACT_GMSH_VERBOSE");
    verbose = env && *env && std::string(env) != "0";
    gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
    gmsh::option::setNumber("General.Verbosity", verbose ? 5 : 2);
    gmsh::logger::start();  // keep messages for our error reports
  }
  ~GmshProcess() {
    try {
      gmsh::logger::stop();
      gmsh::finalize();
    } catch (...) {
    }
  }
};

GmshProcess& process() {
  static GmshProcess p;
  return p;
}

}  // namespace

void throw_gmsh_error(const std::string& while_doing, const std::string& gmsh_message) {
  std::string last;
  try {
    gmsh::logger::getLastError(last);
  } catch (...) {
  }
  throw InputError(msg() << "meshing failed in gmsh while " << while_doing << ": " << gmsh_message
                         << (last.empty() || last == gmsh_message ? "" : " (" + last + ")"));
}

GmshModel::GmshModel(const std::string& name) : name_(name) {
  process();
  gmsh_call("creating model " + name, [&] {
    std::vector<std::string> old;
    gmsh::logger::get(old);  // drop messages of earlier models
    gmsh::model::add(name);
    gmsh::model::setCurrent(name);
  });
}

GmshModel::~GmshModel() {
  try {
    gmsh::model::setCurrent(name_);
    gmsh::model::remove();
  } catch (...) {
  }
}

std::string GmshModel::log() const {
  std::vector<std::string> lines;
  try {
    gmsh::logger::get(lines);
  } catch (...) {
  }
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

}  // namespace plyimpact::mesh
