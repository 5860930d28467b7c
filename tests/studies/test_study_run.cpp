// A study of tiny scenes end to end, through child `plyimpact run` processes: the table's rows and
// columns, reuse of finished cases (a second invocation runs nothing, an extended list runs only
// the new case, an interrupted case runs again), errors that point at the study file's line, the
// Slurm and GNU parallel hand-off (a line of the emitted job list, run by the shell as a scheduler
// would, gives a case that --collect then finds), and non-empty PNG plots.
#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>

#include "core/error.hpp"
#include "output/csv_plot.hpp"
#include "output/history_table.hpp"
#include "study/study.hpp"
#include "study/study_spec.hpp"
#include "study_support.hpp"

namespace plyimpact::study {
namespace {

namespace fs = std::filesystem;
using test::kProgram;
using test::slurp;
using test::ScratchDir;

// 64 elements, about 20 cycles: a case takes a fraction of a second.
const char* kBlock =
    "units: SI\ncontrol: {termination_time: 2.0e-6}\noutput: {interval: 1.0e-6}\nmaterials:\n"
    "  m: {card: MAT_001, RO: 7800, E: 200e9, PR: 0.3}\nsections:\n  s: {ELFORM: 1, IHQ: 4}\n"
    "parts:\n  block: {material: m, section: s}\nmesh:\n  boxes:\n    - {part: block, size: [0.01, 0.01, 0.01], elements: [4, 4, 4]}\n"
    "node_sets:\n  base: {plane: {axis: z, value: 0}}\nboundary_conditions:\n  - {node_set: base, fix: [x, y, z]}\n"
    "initial_velocity:\n  - {part: block, velocity: [0, 0, -1]}\n";

std::string study_text(const std::string& tssfac_list, const std::string& extra = "") {
  return "scene: block.yaml\n"
         "parameters:\n"
         "  control.tssfac: " + tssfac_list + "\n"
         "quantities: [energy_ratio_deviation, hourglass_ratio, wall_time, elements]\n"
         "threads: 1\n" + extra;
}

StudyOutcome run(const ScratchDir& d, const std::string& text, StudyOptions o = {}) {
  const auto file = test::write_file(d.path() / "study.yaml", text);
  o.program = kProgram;
  o.output_dir = d.path() / "out";
  std::ostringstream log;
  const StudyOutcome r = run_study(read_study(file), o, log);
  return r;
}

std::size_t lines(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

TEST(StudyRun, TableReuseAndExtension) {
  ScratchDir d;
  test::write_file(d.path() / "block.yaml", kBlock);
  auto r = run(d, study_text("[0.9, 0.6]"));
  EXPECT_EQ(r.cases, 2u);
  EXPECT_EQ(r.ran, 2u);
  EXPECT_EQ(r.failed, 0u);
  const std::string csv = slurp(d.path() / "out" / "study.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "case,status,control.tssfac,energy_ratio_deviation,hourglass_ratio,wall_time,elements");
  EXPECT_EQ(lines(csv), 3u);
  EXPECT_NE(csv.find(",completed,0.9,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",completed,0.6,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",64\n"), std::string::npos) << "element count column: " << csv;
  EXPECT_NE(slurp(d.path() / "out" / "study.json").find("\"control.tssfac\": \"0.6\""), std::string::npos);

  r = run(d, study_text("[0.9, 0.6]"));
  EXPECT_EQ(r.ran, 0u) << "finished cases must not run again";
  EXPECT_EQ(r.already_finished, 2u);

  r = run(d, study_text("[0.9, 0.6, 0.4]"));
  EXPECT_EQ(r.ran, 1u) << "only the new value runs";
  EXPECT_EQ(r.already_finished, 2u);
  EXPECT_EQ(lines(slurp(d.path() / "out" / "study.csv")), 4u);

  // A case that a signal interrupted (its summary says so) is not a result: it runs again.
  for (const auto& e : fs::directory_iterator(d.path() / "out")) {
    if (!e.path().filename().string().starts_with("tssfac-0.6_")) continue;
    std::string summary = slurp(e.path() / "summary.json");
    ASSERT_NE(summary.find("\"completed\""), std::string::npos) << summary;
    summary.replace(summary.find("\"completed\""), 11, "\"interrupted\"");
    test::write_file(e.path() / "summary.json", summary);
  }
  r = run(d, study_text("[0.9, 0.6, 0.4]"));
  EXPECT_EQ(r.ran, 1u) << "the interrupted case runs again, the others are reused";
  EXPECT_EQ(r.already_finished, 2u);

  // A comment added to the base scene changes no value: the finished case is reused.
  test::write_file(d.path() / "block.yaml", std::string(kBlock) + "# edited\n");
  r = run(d, study_text("[0.9]"));
  EXPECT_EQ(r.ran, 0u) << "a comment is not a different effective scene";
  // A changed value is: the case runs again.
  std::string changed = kBlock;
  changed.replace(changed.find("E: 200e9"), 8, "E: 210e9");
  test::write_file(d.path() / "block.yaml", changed);
  r = run(d, study_text("[0.9]"));
  EXPECT_EQ(r.ran, 1u);
}

TEST(StudyRun, OverrideErrorsPointAtTheStudyLine) {
  ScratchDir d;
  test::write_file(d.path() / "block.yaml", kBlock);
  try {
    run(d, study_text("[0.9,\n    1.7]"));  // tssfac must be in (0, 1]
    FAIL() << "an invalid value must be refused";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("study.yaml:4:5"), std::string::npos) << m;
    EXPECT_NE(m.find("control.tssfac"), std::string::npos) << m;
  }
  EXPECT_FALSE(fs::exists(d.path() / "out")) << "nothing runs when a case is invalid";
  try {
    run(d, "scene: block.yaml\nparameters:\n  control.tsfac: [0.5]\nquantities: [wall_time]\n");
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("study.yaml:3:19"), std::string::npos) << m;
    EXPECT_NE(m.find("did you mean 'tssfac'"), std::string::npos) << m;
  }
  try {
    run(d, "scene: block.yaml\nparameters:\n  control.tssfac: [0.5]\nquantities: [wall_tme]\n");
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("study.yaml:4:14: quantities[0]"), std::string::npos) << m;
    EXPECT_NE(m.find("did you mean 'wall_time'"), std::string::npos) << m;
  }
}

TEST(StudyRun, EmittedJobsRunAsASchedulerWouldAndAreCollected) {
  ScratchDir d;
  test::write_file(d.path() / "block.yaml", kBlock);
  StudyOptions o;
  o.emit = Emit::slurm;
  auto r = run(d, study_text("[0.9, 0.6]"), o);
  EXPECT_EQ(r.pending, 2u);
  const std::string script = slurp(d.path() / "out" / "slurm_array.sh");
  EXPECT_NE(script.find("#SBATCH --array=1-2\n"), std::string::npos) << script;
  EXPECT_NE(script.find("#SBATCH --cpus-per-task=1\n"), std::string::npos) << script;
  EXPECT_NE(script.find("${SLURM_ARRAY_TASK_ID}p"), std::string::npos) << script;
  const std::string list = slurp(d.path() / "out" / "pending_cases.txt");
  ASSERT_EQ(lines(list), 2u);
  EXPECT_NE(list.find("'run' '"), std::string::npos) << list;
  EXPECT_NE(list.find("'--set' 'control.tssfac=0.9'"), std::string::npos) << list;
  EXPECT_NE(list.find("'--threads' '1' '-o' '"), std::string::npos) << list;
  o.emit = Emit::parallel;
  run(d, study_text("[0.9, 0.6]"), o);
  EXPECT_EQ(slurp(d.path() / "out" / "parallel_jobs.txt"), list) << "the same commands for GNU parallel";

  // Run array task 1 the way the Slurm script does, then collect.
  const std::string task = "SLURM_ARRAY_TASK_ID=1 bash '" + (d.path() / "out" / "slurm_array.sh").string() + "'";
  ASSERT_EQ(std::system(task.c_str()), 0) << task;
  o.emit = Emit::none;
  o.collect = true;
  r = run(d, study_text("[0.9, 0.6]"), o);
  EXPECT_EQ(r.ran, 0u);
  EXPECT_EQ(r.already_finished, 1u);
  EXPECT_EQ(r.pending, 1u);
  const std::string csv = slurp(d.path() / "out" / "study.csv");
  EXPECT_NE(csv.find(",completed,0.9,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",pending,0.6,"), std::string::npos) << csv;
}

TEST(StudyRun, PlotsAreNonEmptyPngs) {
  if (!output::find_gnuplot()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
  ScratchDir d;
  test::write_file(d.path() / "block.yaml", kBlock);
  const auto r = run(d, study_text("[0.9, 0.6]", "case_plots: true\n"));
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  int pngs = 0;
  for (const auto& e : fs::recursive_directory_iterator(d.path() / "out")) {
    if (e.path().extension() != ".png") continue;
    ++pngs;
    EXPECT_GT(fs::file_size(e.path()), 1000u) << e.path();
    EXPECT_EQ(slurp(e.path()).substr(1, 3), "PNG") << e.path();
  }
  EXPECT_EQ(pngs, 4 + 2) << "4 quantities against tssfac, an energy plot per case (no contact: no force plot)";
}

}  // namespace
}  // namespace plyimpact::study
