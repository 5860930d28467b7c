// The ballistic-limit search run by `plyimpact study` end to end, with an injected case function:
// the study's child program is a shell script standing in for `plyimpact run` that writes the
// history.csv and summary.json of a deformable impactor following the Lambert-Jonas law
// v_r = 0.8 (v^2 - 250^2)^(1/2) (a 10 % rebound below 250 m/s) and logs each velocity it is given.
// The base scene is the shipped high-velocity scene (loaded and validated for every case as for a
// real study, and the source of the gap + plate thickness of the perforation criterion). Checked:
// the limit and its bracket in study.json, ballistic_limit.csv and study.csv; the number of cases
// run (the bracket's ends, then two a round: ceil(log3(300 / 10)) = 4 rounds); a second
// invocation runs nothing and gives the same answer; a sweep's finished cases narrow the bracket;
// a bracket that does not bracket is refused with the study line; the residual-velocity plot.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <sstream>

#include "output/csv_plot.hpp"
#include "output/json_reader.hpp"
#include "study/study.hpp"
#include "study/study_spec.hpp"
#include "study_support.hpp"

namespace plyimpact::study {
namespace {

namespace fs = std::filesystem;

std::string fake_program(const fs::path& log) {
  return "#!/bin/sh\n"
         "v=''; out=''\n"
         "while [ $# -gt 0 ]; do\n"
         "  case \"$1\" in\n"
         "    --set) case \"$2\" in impactor.velocity=*) v=\"${2#impactor.velocity=}\"; v=\"${v%% *}\";; esac; shift 2;;\n"
         "    -o) out=\"$2\"; shift 2;;\n"
         "    *) shift;;\n"
         "  esac\n"
         "done\n"
         "echo \"$v\" >> '" + log.string() + "'\n"
         "mkdir -p \"$out\"\n"
         "awk -v v=\"$v\" 'BEGIN {\n"
         "  vr = v > 250 ? 0.8 * sqrt(v * v - 250 * 250) : -0.1 * v; z = vr > 0 ? -1 : 0.0061\n"
         "  print \"time,impactor_x,impactor_y,impactor_z,impactor_vx,impactor_vy,impactor_vz\"\n"
         "  printf \"0,0,0,0.0061,0,0,%.10g\\n\", -v\n"
         "  printf \"5e-5,0,0,%.10g,0,0,%.10g\\n\", z, -vr\n"
         "  printf \"1e-4,0,0,%.10g,0,0,%.10g\\n\", z, -vr }' > \"$out/history.csv\"\n"
         "echo '{\"status\": \"completed\", \"wall_seconds\": 0.01}' > \"$out/summary.json\"\n";
}

struct Fixture {
  fs::path dir, program, log;
  explicit Fixture(const fs::path& d) : dir(d), program(d / "fake_plyimpact"), log(d / "velocities.log") {
    test::write_file(program, fake_program(log));
    ::chmod(program.c_str(), 0755);
  }
  StudyOutcome run(const std::string& study_tail) const {
    const auto file = test::write_file(dir / "study.yaml",
                                       "scene: " PLYIMPACT_SOURCE_DIR "/configs/high_velocity_impact.yaml\n"
                                       "set: {laminate.interfaces: none}\n"
                                       "quantities: [residual_velocity]\n" + study_tail);
    StudyOptions o;
    o.program = program;
    o.output_dir = dir / "out";
    o.jobs = 2;
    o.cores = 2;
    o.threads = 1;
    std::ostringstream out;
    return run_study(read_study(file), o, out);
  }
  std::size_t runs() const {
    std::size_t n = 0;
    for (char c : test::slurp(log)) n += c == '\n';
    return n;
  }
};

const char* kSearch =
    "lambert_jonas: {velocity: impactor.velocity}\n"
    "ballistic_limit: {parameter: impactor.velocity, bracket: [100, 400], unit: m/s, tolerance: 10}\n";

TEST(BallisticStudy, SearchesResumesAndReports) {
  test::ScratchDir d;
  const Fixture f(d.path());
  auto r = f.run(kSearch);
  EXPECT_TRUE(r.errors.empty()) << r.errors.front();
  EXPECT_EQ(r.failed, 0u);
  EXPECT_EQ(f.runs(), 2u + 2 * 4) << "the two ends, then 4 rounds of 2";
  EXPECT_EQ(r.ran, f.runs());
  const output::Json j = output::read_json_file(d.path() / "out" / "study.json");
  const output::Json& bl = *j.find("ballistic_limit");
  const auto& br = bl.find("bracket")->as_array();
  const double lo = br[0].as_number(), hi = br[1].as_number();
  EXPECT_LT(lo, 250);
  EXPECT_GT(hi, 250);
  EXPECT_LE(hi - lo, 10);
  EXPECT_NEAR(bl.find("ballistic_limit_si")->as_number(), 250, 5);
  EXPECT_EQ(bl.find("rounds")->as_number(), 4);
  EXPECT_NE(bl.find("criterion")->as_string().find("gap + plate thickness"), std::string::npos);
  const std::string shots = test::slurp(d.path() / "out" / "ballistic_limit.csv");
  EXPECT_EQ(shots.substr(0, shots.find('\n')), "impactor.velocity,residual_velocity,perforated,case");
  EXPECT_NE(shots.find("\n400,249.799"), std::string::npos) << "0.8 sqrt(400^2 - 250^2) = 249.7999:\n" << shots;
  const std::string csv = test::slurp(d.path() / "out" / "study.csv");
  std::size_t rows = 0;
  for (char c : csv) rows += c == '\n';
  EXPECT_EQ(rows, 1 + f.runs()) << "every case of the search is a row of the study table:\n" << csv;
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);  // header: case,status,impactor.velocity,...
  double previous = 0;
  while (std::getline(lines, line)) {
    const auto first = line.find(',', line.find(',') + 1) + 1;
    const double v = std::stod(line.substr(first));
    EXPECT_GT(v, previous) << "rows listed by velocity:\n" << csv;
    previous = v;
  }

  r = f.run(kSearch);
  EXPECT_EQ(r.ran, 0u) << "a repeated search replays its rounds from the finished cases";
  EXPECT_EQ(f.runs(), 10u);
  const output::Json again = output::read_json_file(d.path() / "out" / "study.json");
  EXPECT_EQ(again.find("ballistic_limit")->find("ballistic_limit")->as_number(),
            bl.find("ballistic_limit")->as_number());
  if (output::find_gnuplot()) {
    EXPECT_GT(fs::file_size(d.path() / "out" / "plots" / "residual_velocity_lambert_jonas.png"), 1000u);
  }
}

TEST(BallisticStudy, ASweepNarrowsTheBracket) {
  test::ScratchDir d;
  const Fixture f(d.path());
  const auto r = f.run("parameters:\n  impactor.velocity: {start: 100, stop: 400, step: 100, unit: m/s}\n" +
                       std::string(kSearch));
  EXPECT_TRUE(r.errors.empty()) << r.errors.front();
  // The sweep (4 cases) holds the ends; [200, 300] then needs ceil(log3(100 / 10)) = 3 rounds of 2.
  EXPECT_EQ(f.runs(), 4u + 2 * 3);
}

TEST(BallisticStudy, RefusesABracketThatDoesNotBracket) {
  test::ScratchDir d;
  const Fixture f(d.path());
  const auto r = f.run("ballistic_limit: {parameter: impactor.velocity, bracket: [300, 400], unit: m/s, tolerance: 10}\n");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_NE(r.errors[0].find("study.yaml:4:18: ballistic_limit"), std::string::npos) << r.errors[0];
  EXPECT_NE(r.errors[0].find("does not bracket"), std::string::npos) << r.errors[0];
  EXPECT_EQ(f.runs(), 2u);
  const output::Json j = output::read_json_file(d.path() / "out" / "study.json");
  EXPECT_NE(j.find("ballistic_limit")->find("error")->as_string().find("does not bracket"), std::string::npos);
}

}  // namespace
}  // namespace plyimpact::study
