// `plyimpact dcb-reduce`: the files it writes (CSV columns, fits summary, PNG when gnuplot is
// there) and its refusals (non-positive width, missing options, missing column) with exit codes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/application.hpp"
#include "beam_theory_dcb.hpp"
#include "output/csv_plot.hpp"

namespace plyimpact {
namespace {

namespace fs = std::filesystem;

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("plyimpact_dcb_" + std::to_string(::getpid()) + "_" +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
  Scratch() {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

fs::path write_record(const fs::path& dir) {
  test::BeamTheoryDcb dcb;
  const fs::path p = dir / "specimen.csv";
  std::ofstream f(p);
  f << "load,opening,crack_length\n";
  f << "0,0,0.05\n";  // loading starts at the pre-crack length
  for (double a = 50e-3; a <= 90e-3 + 1e-12; a += 4e-3) {
    const auto pt = dcb.at(a + 1e-3);
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g\n", pt.P, pt.delta, pt.a);
    f << buf;
  }
  return p;
}

int run(const std::vector<std::string>& args, std::string& out, std::string& err) {
  std::ostringstream o, e;
  const int code = app::run_application(args, o, e);
  out = o.str();
  err = e.str();
  return code;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(DcbReduceCommand, WritesCurveFitsAndPlot) {
  Scratch s;
  const fs::path data = write_record(s.dir);
  std::string out, err;
  const int code = run({"dcb-reduce", data.string(), "--width", "25 mm", "--thickness", "0.003", "-o",
                        (s.dir / "out").string()},
                       out, err);
  ASSERT_EQ(code, 0) << err;
  EXPECT_NE(out.find("11 propagation points"), std::string::npos) << out;
  EXPECT_NE(out.find("mean G_Ic: MBT 300, CC"), std::string::npos) << out;
  const std::string csv = slurp(s.dir / "out" / "dcb_reduction.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "a,P,delta,C,G_MBT,G_CC,G_MCC,source_line");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 12);
  const std::string json = slurp(s.dir / "out" / "dcb_fits.json");
  for (const char* key : {"\"MBT\"", "\"Delta\"", "\"CC\"", "\"n\"", "\"MCC\"", "\"A1\"", "\"r2\"", "\"slope\"",
                          "\"intercept\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
  if (output::find_gnuplot()) {
    const std::string png = slurp(s.dir / "out" / "dcb_r_curve.png");
    ASSERT_GT(png.size(), 1000u);
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  } else {
    EXPECT_NE(err.find("gnuplot is not on PATH"), std::string::npos) << err;
  }
}

TEST(DcbReduceCommand, RefusesBadSpecimenAndUsage) {
  Scratch s;
  const fs::path data = write_record(s.dir);
  std::string out, err;
  EXPECT_EQ(run({"dcb-reduce", data.string(), "--width", "0 mm", "--thickness", "3 mm", "-o", s.dir.string()}, out,
                err),
            1);
  EXPECT_NE(err.find("--width 0 mm: must be > 0"), std::string::npos) << err;
  EXPECT_EQ(run({"dcb-reduce", data.string(), "--width", "25 mm", "--thickness", "3 kg"}, out, err), 1);
  EXPECT_NE(err.find("--thickness 3 kg"), std::string::npos) << err;
  EXPECT_EQ(run({"dcb-reduce", data.string(), "--thickness", "3 mm"}, out, err), 64);
  EXPECT_EQ(run({"dcb-reduce", data.string(), "--width", "25 mm", "--thickness", "3 mm", "--crack", "a_mm", "-o",
                 s.dir.string()},
                out, err),
            1);
  EXPECT_NE(err.find("specimen.csv:1: no column 'a_mm'"), std::string::npos) << err;
}

}  // namespace
}  // namespace plyimpact
