// The plotting path, headless: a CSV (shaped like a run's history.csv) to a PNG through gnuplot,
// by the library call and by `plyimpact plot`. A valid PNG starts with the 8-byte signature and an
// IHDR chunk whose width and height are the requested size. Skipped, saying why, only when gnuplot
// is not installed (tools/install-deps.sh installs gnuplot-nox, so CI has it).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/application.hpp"
#include "core/error.hpp"
#include "output/csv_plot.hpp"

namespace plyimpact {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("plyimpact_plot_" + std::to_string(::getpid()) + "_" +
                                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

fs::path history(const fs::path& dir) {
  const fs::path p = dir / "history.csv";
  std::ofstream f(p);
  f << "time,kinetic_energy,contact_impactor_plate_normal\n";
  for (int i = 0; i <= 200; ++i) {
    const double t = i * 1e-5;
    f << t << "," << 26.8 * std::cos(t * 500) * std::cos(t * 500) << "," << 5e3 * std::sin(t * 1500) << "\n";
  }
  return p;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

unsigned be32(const std::string& s, std::size_t at) {
  return (unsigned(static_cast<unsigned char>(s[at])) << 24) | (unsigned(static_cast<unsigned char>(s[at + 1])) << 16) |
         (unsigned(static_cast<unsigned char>(s[at + 2])) << 8) | unsigned(static_cast<unsigned char>(s[at + 3]));
}

void expect_png(const fs::path& p, unsigned width, unsigned height) {
  const std::string png = slurp(p);
  ASSERT_GT(png.size(), 2000u) << p << ": a plot with axes, labels and curves is not a few bytes";
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << "PNG signature";
  EXPECT_EQ(png.substr(12, 4), "IHDR");
  EXPECT_EQ(be32(png, 16), width);
  EXPECT_EQ(be32(png, 20), height);
}

#define REQUIRE_GNUPLOT()                                                                                 \
  if (!output::find_gnuplot())                                                                            \
  GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox; run tools/install-deps.sh)"

TEST(CsvPlot, LibraryWritesPngOfNamedColumns) {
  REQUIRE_GNUPLOT();
  const fs::path dir = scratch();
  output::CsvPlot plot;
  plot.csv = history(dir);
  plot.x_column = "time";
  plot.x_scale = 1e3;
  plot.series = {{"kinetic_energy", "kinetic energy"}};
  plot.title = "it's a test";  // a quote in a gnuplot string
  plot.width = 640;
  plot.height = 480;
  output::plot_csv_png(plot, dir / "ke.png");
  expect_png(dir / "ke.png", 640, 480);
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "temporaries removed";
  fs::remove_all(dir);
}

TEST(CsvPlot, UnknownColumnNamesTheColumns) {
  const fs::path dir = scratch();
  output::CsvPlot plot;
  plot.csv = history(dir);
  plot.x_column = "time";
  plot.series = {{"contact_force", ""}};
  try {
    output::plot_csv_png(plot, dir / "x.png");
    FAIL() << "unknown column accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no column 'contact_force'; allowed one of time, kinetic_energy"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  fs::remove_all(dir);
}

TEST(CsvPlot, PlotCommandOnHistory) {
  REQUIRE_GNUPLOT();
  const fs::path dir = scratch();
  const fs::path csv = history(dir);
  std::ostringstream out, err;
  const int code = app::run_application({"plot", csv.string(), "--y", "contact_impactor_plate_normal,kinetic_energy"},
                                        out, err);
  ASSERT_EQ(code, 0) << err.str();
  expect_png(dir / "history_contact_impactor_plate_normal.png", 1000, 700);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace plyimpact
