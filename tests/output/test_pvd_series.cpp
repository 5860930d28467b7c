// PvdSeries: the .pvd is well-formed XML (checked with VTK's own XML parser) listing every frame
// with its exact time and its file name relative to the series directory.
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "output/pvd_series.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using plyimpact::RunError;
using plyimpact::output::PvdSeries;

using plyimpact::test::ScratchDir;
using plyimpact::test::slurp;

namespace {

struct DataSetEntry {
  double time;
  std::string file;
  int part = 0;
  std::string name;
};

// Parses the collection with a real XML parser; fails the test if the file is not well-formed.
std::vector<DataSetEntry> parse_pvd(const fs::path& p) {
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(p.c_str());
  EXPECT_EQ(parser->Parse(), 1) << "not well-formed XML: " << p;
  vtkXMLDataElement* root = parser->GetRootElement();
  if (root == nullptr) {
    ADD_FAILURE() << "no root element";
    return {};
  }
  EXPECT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  if (collection == nullptr) {
    ADD_FAILURE() << "no Collection element";
    return {};
  }
  // vtkXMLDataElement reports an empty attribute as absent, so check group="" in the text.
  std::ifstream in(p);
  std::stringstream text;
  text << in.rdbuf();
  std::size_t groups = 0;
  for (auto pos = text.str().find("group=\"\""); pos != std::string::npos;
       pos = text.str().find("group=\"\"", pos + 1)) {
    ++groups;
  }
  EXPECT_EQ(groups, static_cast<std::size_t>(collection->GetNumberOfNestedElements()));
  std::vector<DataSetEntry> entries;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* ds = collection->GetNestedElement(i);
    EXPECT_STREQ(ds->GetName(), "DataSet");
    const char* timestep = ds->GetAttribute("timestep");
    const char* file = ds->GetAttribute("file");
    const char* part = ds->GetAttribute("part");
    if (timestep == nullptr || file == nullptr || part == nullptr) {
      ADD_FAILURE() << "DataSet without timestep, part or file";
      continue;
    }
    const char* name = ds->GetAttribute("name");
    entries.push_back({std::strtod(timestep, nullptr), file, std::atoi(part), name ? name : ""});
  }
  return entries;
}

}  // namespace

TEST(PvdSeries, ListsFramesWithExactTimesAndRelativeFilesAndRewrites) {
  ScratchDir dir;
  PvdSeries series(dir.path(), "plate");
  EXPECT_EQ(series.path(), dir.path() / "plate.pvd");

  // 1/3 ms needs all 17 digits to survive the text round trip.
  const double t1 = 1.0 / 3.0 * 1e-3;
  series.add(0.0, "plate_000000.vtu");
  series.add(t1, "plate_000001.vtu");
  series.write();

  auto entries = parse_pvd(series.path());
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].time, 0.0);
  EXPECT_EQ(entries[0].file, "plate_000000.vtu");
  EXPECT_EQ(entries[1].time, t1);  // exact: %.17g round-trips every double
  EXPECT_EQ(entries[1].file, "plate_000001.vtu");

  const double t2 = 2.0 / 3.0 * 1e-3;
  series.add(t2, "frames/plate & co_000002.vtu");  // subdirectory and an XML special character
  series.write();
  entries = parse_pvd(series.path());
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[1].time, t1);
  EXPECT_EQ(entries[2].time, t2);
  EXPECT_EQ(entries[2].file, "frames/plate & co_000002.vtu");
  EXPECT_EQ(series.size(), 3u);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"plate.pvd"});  // no temporaries left
}

// Two named parts per time: what ParaView's PVD reader turns into a two-block multiblock per time.
TEST(PvdSeries, NamedPartsPerTime) {
  ScratchDir dir;
  PvdSeries series(dir.path(), "plate");
  for (int k = 0; k < 2; ++k) {
    const double t = 1e-5 * k;
    series.add(t, "plate_000" + std::to_string(k) + ".vtu", 0, "bodies");
    series.add(t, "plate_rigid_000" + std::to_string(k) + ".vtu", 1, "rigid <tup> & co");
  }
  series.write();
  const auto entries = parse_pvd(series.path());
  ASSERT_EQ(entries.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(entries[i].time, 1e-5 * double(i / 2));
    EXPECT_EQ(entries[i].part, int(i % 2));
    EXPECT_EQ(entries[i].name, i % 2 == 0 ? "bodies" : "rigid <tup> & co");
  }
  EXPECT_EQ(entries[3].file, "plate_rigid_0001.vtu");
  EXPECT_THROW(series.add(0.0, "a.vtu", -1, "x"), RunError);
}

TEST(PvdSeries, EmptySeriesIsValid) {
  ScratchDir dir;
  PvdSeries series(dir.path(), "impactor");
  series.write();
  EXPECT_TRUE(parse_pvd(series.path()).empty());
}

TEST(PvdSeries, RejectsBadInput) {
  ScratchDir dir;
  EXPECT_THROW(PvdSeries(dir.path(), ""), RunError);
  EXPECT_THROW(PvdSeries(dir.path(), "a/b"), RunError);
  PvdSeries series(dir.path(), "plate");
  EXPECT_THROW(series.add(std::numeric_limits<double>::quiet_NaN(), "a.vtu"), RunError);
  EXPECT_THROW(series.add(0.0, "/abs/a.vtu"), RunError);
  EXPECT_THROW(series.add(0.0, ""), RunError);
  EXPECT_EQ(series.size(), 0u);
}

TEST(PvdSeries, WriteIntoMissingDirectoryThrows) {
  ScratchDir dir;
  PvdSeries series(dir.path() / "missing", "plate");
  series.add(0.0, "plate_000000.vtu");
  EXPECT_THROW(series.write(), RunError);
  EXPECT_TRUE(dir.entries().empty());
}
