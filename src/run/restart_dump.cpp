#include "run/restart_dump.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/state_io.hpp"
#include "output/atomic_file.hpp"

namespace plyimpact::run {

namespace {

// Raised whenever the layout of the run state changes in a way the block names do not show.
constexpr std::uint64_t kDumpFormat = 1;

struct Header {
  std::uint64_t format = kDumpFormat;
  std::vector<char> version;
  std::uint64_t identity = 0;
  double time = 0;
  long cycle = 0;

  void visit(StateVisitor& v) {
    StateGroup group(v, "dump");
    v.scalar("format", format);
    v.array("program_version", version);
    v.scalar("run_identity", identity);
    v.scalar("time", time);
    v.scalar("cycle", cycle);
  }
};

std::vector<char> this_version() {
  const std::string v = PLYIMPACT_VERSION;
  return {v.begin(), v.end()};
}

void visit_run(StateVisitor& v, solver::Solver& solver, const std::vector<RunObserver*>& observers) {
  solver.visit_state(v);
  StateGroup group(v, "run");
  for (RunObserver* o : observers) o->visit_state(v);
}

// Header read and checked; the reader is left at the solver's first block.
DumpInfo read_header(StateReader& reader, const std::filesystem::path& dump, std::uint64_t identity) {
  Header h;
  h.visit(reader);
  DumpInfo info{std::string(h.version.begin(), h.version.end()), h.format, h.identity, h.time, h.cycle};
  if (info.version != PLYIMPACT_VERSION || h.format != kDumpFormat)
    throw InputError(msg() << dump.string() << ": restart dump written by plyimpact " << info.version << " (dump format "
                           << h.format << "); this is plyimpact " << PLYIMPACT_VERSION << " (dump format "
                           << kDumpFormat << "); allowed a dump written by this program version: rerun the scene");
  if (h.identity != identity)
    throw InputError(msg() << dump.string() << ": restart dump of another scene (run identity " << identity_text(h.identity)
                           << ", this scene " << identity_text(identity)
                           << "); allowed a dump of this scene with the same settings and mesh: only "
                              "control.termination_time, control.max_cycles, control.threads and the output "
                              "intervals may change on a restart");
  return info;
}

}  // namespace

std::string identity_text(std::uint64_t identity) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(identity));
  return buf;
}

std::uint64_t run_identity(std::uint64_t scene_digest, const model::Model& model) {
  StateDigest d;
  d.scalar("scene", scene_digest);
  // StateDigest only reads the blocks it is given.
  d.block("X", sizeof(double), model.X.size(), const_cast<double*>(model.X.data()), nullptr, nullptr);
  for (const auto& b : model.blocks)
    d.block("conn", sizeof(Index), b.conn.size(), const_cast<Index*>(b.conn.data()), nullptr, nullptr);
  return d.value();
}

LoadedDump load_dump(const std::filesystem::path& dump, std::uint64_t identity) {
  std::ifstream in(dump, std::ios::binary);
  if (!in)
    throw InputError(msg() << dump.string() << ": cannot open the restart dump; allowed a readable " << kDumpFileName
                           << " written by `plyimpact run`");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  LoadedDump loaded{dump, {}, bytes.str()};
  std::istringstream text(loaded.bytes);
  StateReader reader(text, dump.string());
  loaded.info = read_header(reader, dump, identity);
  return loaded;
}

void write_dump(const std::filesystem::path& dump, std::uint64_t identity, solver::Solver& solver,
                const std::vector<RunObserver*>& observers) {
  std::ostringstream out(std::ios::binary);
  StateWriter writer(out);
  Header h;
  h.version = this_version();
  h.identity = identity;
  h.time = solver.state().time;
  h.cycle = solver.state().cycle;
  h.visit(writer);
  visit_run(writer, solver, observers);
  output::write_text_atomically(dump, out.view());
}

void read_dump(const LoadedDump& dump, solver::Solver& solver, const std::vector<RunObserver*>& observers) {
  std::istringstream in(dump.bytes);
  StateReader reader(in, dump.file.string());
  read_header(reader, dump.file, dump.info.identity);
  visit_run(reader, solver, observers);
  if (in.peek() != std::char_traits<char>::eof())
    throw InputError(msg() << dump.file.string() << ": the restart dump has more run state than this scene "
                           << "(written by another scene or program version)");
}

}  // namespace plyimpact::run
