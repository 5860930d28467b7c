// write_vtu: what VTK's own reader gets back is bit-for-bit the Frame that was written (raw binary
// appended data), uncompressed, zlib and lz4, hexahedra and quadrilaterals, with its field data;
// bad frames and bad paths fail loudly and cleanly.
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "output/vtu_writer.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using plyimpact::RunError;
using plyimpact::output::Compression;
using plyimpact::output::Field;
using plyimpact::output::Frame;
using plyimpact::output::IntField;
using plyimpact::output::StringField;
using plyimpact::output::write_vtu;
using plyimpact::output::WriteOptions;

using plyimpact::test::ScratchDir;
using plyimpact::test::slurp;

namespace {

// Values with full 53-bit mantissas, so a lossy (ASCII or float) path would show.
std::vector<double> awkward_values(std::size_t n, double scale) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = scale * (std::sin(1.0 + static_cast<double>(i)) + 1.0 / 3.0);
  return v;
}

// Two hexes sharing a face: a 3 x 2 x 2 lattice of nodes, node = i + 3 j + 6 k.
Frame two_hex_frame() {
  Frame f;
  f.time = 1.2345678901234567e-4;
  f.cycle = 4242;
  for (int k = 0; k < 2; ++k) {
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 3; ++i) {
        f.points.insert(f.points.end(), {0.1 * i + 1e-7 / 3.0, 0.2 * j, 0.3 * k + 1e-9});
      }
    }
  }
  f.hex_connectivity = {0, 1, 4, 3, 6, 7, 10, 9, 1, 2, 5, 4, 7, 8, 11, 10};
  const std::vector<std::string> voigt{"xx", "yy", "zz", "xy", "yz", "zx"};
  f.point_fields.push_back({"temperature", 1, awkward_values(12, 300.0), {}});
  f.point_fields.push_back({"velocity", 3, awkward_values(36, -12.5), {"x", "y", "z"}});
  f.point_fields.push_back({"point_stress", 6, awkward_values(72, 1e8), voigt});
  f.cell_fields.push_back({"damage", 1, {0.0, 0.75}, {}});
  f.cell_fields.push_back({"fibre_direction", 3, awkward_values(6, 1.0), {}});
  f.cell_fields.push_back({"stress", 6, awkward_values(12, -3e9), voigt});
  f.point_int_fields.push_back({"node_id", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, -11}});
  f.cell_int_fields.push_back({"ply_id", {3, 2147483647}});
  return f;
}

// The same lattice with two hexahedra and, after them, a quadrilateral on the top face; units and
// field-data strings (one with a character XML must escape).
Frame mixed_frame() {
  Frame f = two_hex_frame();
  f.quad_connectivity = {6, 7, 10, 9};
  f.point_fields[0].unit = "K";
  f.cell_fields[0].values.push_back(0.5);
  f.cell_fields[0].unit = "1";
  f.cell_fields[1].values.insert(f.cell_fields[1].values.end(), {1.0, 2.0, 3.0});
  f.cell_fields[2].values.insert(f.cell_fields[2].values.end(), 6, -1.0);
  f.cell_fields[2].unit = "Pa";
  f.cell_int_fields[0].values.push_back(-1);
  f.field_strings.push_back({"legend_ply_id", {"3: ply <three> & more", "-1: none"}});
  f.field_strings.push_back({"notes", {"a single note"}});
  return f;
}

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const fs::path& p) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(p.c_str());
  reader->Update();
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  return reader->GetOutput();
}

// Exact comparisons on purpose: the data goes through raw binary, so every bit must survive.
void expect_field(vtkDataSetAttributes* data, const Field& f) {
  SCOPED_TRACE(f.name);
  auto* a = vtkDoubleArray::SafeDownCast(data->GetAbstractArray(f.name.c_str()));
  ASSERT_NE(a, nullptr) << "missing or not double";
  ASSERT_EQ(a->GetNumberOfComponents(), f.components);
  ASSERT_EQ(static_cast<std::size_t>(a->GetNumberOfValues()), f.values.size());
  for (std::size_t i = 0; i < f.values.size(); ++i) {
    EXPECT_EQ(a->GetValue(static_cast<vtkIdType>(i)), f.values[i]) << "value " << i;
  }
  for (std::size_t c = 0; c < f.component_names.size(); ++c) {
    const char* name = a->GetComponentName(static_cast<vtkIdType>(c));
    ASSERT_NE(name, nullptr) << "component " << c;
    EXPECT_EQ(std::string(name), f.component_names[c]);
  }
}

void expect_int_field(vtkDataSetAttributes* data, const IntField& f) {
  SCOPED_TRACE(f.name);
  auto* a = vtkIntArray::SafeDownCast(data->GetAbstractArray(f.name.c_str()));
  ASSERT_NE(a, nullptr) << "missing or not int";
  ASSERT_EQ(static_cast<std::size_t>(a->GetNumberOfValues()), f.values.size());
  for (std::size_t i = 0; i < f.values.size(); ++i) {
    EXPECT_EQ(a->GetValue(static_cast<vtkIdType>(i)), f.values[i]);
  }
}

void expect_same_as_frame(vtkUnstructuredGrid* grid, const Frame& f) {
  ASSERT_NE(grid, nullptr);
  ASSERT_EQ(static_cast<std::size_t>(grid->GetNumberOfPoints()), f.num_points());
  ASSERT_EQ(grid->GetPoints()->GetDataType(), VTK_DOUBLE);
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p) {
    double x[3];
    grid->GetPoint(p, x);
    for (int d = 0; d < 3; ++d) EXPECT_EQ(x[d], f.points[3 * p + d]) << "point " << p;
  }
  ASSERT_EQ(static_cast<std::size_t>(grid->GetNumberOfCells()), f.num_cells());
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    const bool hex = c < static_cast<vtkIdType>(f.num_hexes());
    EXPECT_EQ(grid->GetCellType(c), hex ? VTK_HEXAHEDRON : VTK_QUAD);
    grid->GetCellPoints(c, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), hex ? 8 : 4);
    for (vtkIdType n = 0; n < ids->GetNumberOfIds(); ++n) {
      const std::int64_t want = hex ? f.hex_connectivity[8 * c + n]
                                    : f.quad_connectivity[4 * (c - static_cast<vtkIdType>(f.num_hexes())) + n];
      EXPECT_EQ(ids->GetId(n), want) << "cell " << c << " node " << n;
    }
  }
  for (const Field& field : f.point_fields) expect_field(grid->GetPointData(), field);
  for (const Field& field : f.cell_fields) expect_field(grid->GetCellData(), field);
  for (const IntField& field : f.point_int_fields) expect_int_field(grid->GetPointData(), field);
  for (const IntField& field : f.cell_int_fields) expect_int_field(grid->GetCellData(), field);
  EXPECT_EQ(grid->GetPointData()->GetNumberOfArrays(),
            static_cast<int>(f.point_fields.size() + f.point_int_fields.size()));
  EXPECT_EQ(grid->GetCellData()->GetNumberOfArrays(),
            static_cast<int>(f.cell_fields.size() + f.cell_int_fields.size()));

  auto* time = vtkDoubleArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("TimeValue"));
  ASSERT_NE(time, nullptr);
  ASSERT_EQ(time->GetNumberOfValues(), 1);
  EXPECT_EQ(time->GetValue(0), f.time);

  for (const StringField& field : f.field_strings) {
    auto* a = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray(field.name.c_str()));
    ASSERT_NE(a, nullptr) << field.name;
    ASSERT_EQ(static_cast<std::size_t>(a->GetNumberOfValues()), field.values.size()) << field.name;
    for (std::size_t i = 0; i < field.values.size(); ++i) EXPECT_EQ(a->GetValue(vtkIdType(i)), field.values[i]);
  }
}

// The field data `units`: "<array>: <unit>" for exactly the arrays that name a unit.
std::vector<std::string> units_of(vtkUnstructuredGrid* grid) {
  std::vector<std::string> out;
  if (auto* a = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("units")))
    for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i) out.push_back(a->GetValue(i));
  return out;
}

class VtuRoundTrip : public ::testing::TestWithParam<Compression> {};

const char* compressor_name(Compression c) {
  return c == Compression::zlib ? "vtkZLibDataCompressor" : c == Compression::lz4 ? "vtkLZ4DataCompressor" : "";
}

}  // namespace

TEST_P(VtuRoundTrip, ReaderGetsBackEveryValueExactly) {
  ScratchDir dir;
  const Frame frame = two_hex_frame();
  const fs::path file = dir.path() / "plate_000001.vtu";
  WriteOptions options;
  options.compression = GetParam();
  write_vtu(frame, file, options);

  expect_same_as_frame(read_vtu(file), frame);
  EXPECT_TRUE(units_of(read_vtu(file)).empty());  // no field names a unit: no `units` array

  // Appended raw binary with 64-bit block headers (toolchain V6); compressed only when asked for.
  const std::string text = slurp(file);
  EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
  EXPECT_EQ(text.find("format=\"ascii\""), std::string::npos);
  if (GetParam() == Compression::none) {
    EXPECT_EQ(text.find("compressor="), std::string::npos);
  } else {
    EXPECT_NE(text.find(compressor_name(GetParam())), std::string::npos);
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"plate_000001.vtu"});
}

TEST_P(VtuRoundTrip, HexahedraThenQuadrilateralsWithUnitsAndFieldStrings) {
  ScratchDir dir;
  const Frame frame = mixed_frame();
  WriteOptions options;
  options.compression = GetParam();
  write_vtu(frame, dir.path() / "mixed.vtu", options);
  const auto grid = read_vtu(dir.path() / "mixed.vtu");
  expect_same_as_frame(grid, frame);
  ASSERT_EQ(grid->GetNumberOfCells(), 3);
  EXPECT_EQ(grid->GetCellType(0), VTK_HEXAHEDRON);
  EXPECT_EQ(grid->GetCellType(1), VTK_HEXAHEDRON);
  EXPECT_EQ(grid->GetCellType(2), VTK_QUAD);
  EXPECT_EQ(units_of(grid), (std::vector<std::string>{"temperature: K", "damage: 1", "stress: Pa"}));
}

INSTANTIATE_TEST_SUITE_P(Compressions, VtuRoundTrip,
                         ::testing::Values(Compression::none, Compression::zlib, Compression::lz4),
                         [](const auto& info) {
                           return info.param == Compression::zlib  ? "zlib"
                                  : info.param == Compression::lz4 ? "lz4"
                                                                   : "raw";
                         });

TEST(VtuWriter, CompressShorthandIsZlib) {
  ScratchDir dir;
  WriteOptions options;
  options.compress = true;
  write_vtu(two_hex_frame(), dir.path() / "z.vtu", options);
  EXPECT_NE(slurp(dir.path() / "z.vtu").find("vtkZLibDataCompressor"), std::string::npos);
}

TEST(VtuWriter, EmptyFrameIsAValidFile) {
  ScratchDir dir;
  Frame frame;
  frame.time = 0.5;
  write_vtu(frame, dir.path() / "empty.vtu");
  expect_same_as_frame(read_vtu(dir.path() / "empty.vtu"), frame);
}

TEST(VtuWriter, MissingDirectoryThrowsNamingPathAndLeavesNothing) {
  ScratchDir dir;
  const fs::path file = dir.path() / "missing" / "frame.vtu";
  try {
    write_vtu(two_hex_frame(), file);
    FAIL() << "expected RunError";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file.string()), std::string::npos) << what;
    EXPECT_NE(what.find("No such file or directory"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(file));
  EXPECT_TRUE(dir.entries().empty());
}

TEST(VtuWriter, OverwritesExistingFileAtomically) {
  ScratchDir dir;
  const fs::path file = dir.path() / "frame.vtu";
  std::ofstream(file) << "not a vtu file";
  Frame frame = two_hex_frame();
  write_vtu(frame, file);
  frame.time = 2.0;
  frame.points[0] = -1.0;
  write_vtu(frame, file);
  expect_same_as_frame(read_vtu(file), frame);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"frame.vtu"});
}

TEST(VtuWriter, FieldSizeMismatchThrowsNamingField) {
  ScratchDir dir;
  const fs::path file = dir.path() / "frame.vtu";
  Frame frame = two_hex_frame();
  frame.point_fields[1].values.pop_back();  // velocity: 35 values for 12 x 3
  try {
    write_vtu(frame, file);
    FAIL() << "expected RunError";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("velocity"), std::string::npos) << what;
    EXPECT_NE(what.find(file.string()), std::string::npos) << what;
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(VtuWriter, OtherMalformedFramesThrow) {
  ScratchDir dir;
  const fs::path file = dir.path() / "frame.vtu";
  const auto expect_rejected = [&](Frame frame, const char* why) {
    SCOPED_TRACE(why);
    EXPECT_THROW(write_vtu(frame, file), RunError);
  };
  Frame f = two_hex_frame();
  f.cell_fields[2].values.push_back(0.0);
  expect_rejected(f, "cell tensor one value too many");
  f = two_hex_frame();
  f.cell_int_fields[0].values.pop_back();
  expect_rejected(f, "cell int field short");
  f = two_hex_frame();
  f.point_int_fields[0].values.push_back(1);
  expect_rejected(f, "point int field long");
  f = two_hex_frame();
  f.hex_connectivity[5] = 12;
  expect_rejected(f, "node index out of range");
  f = two_hex_frame();
  f.hex_connectivity.pop_back();
  expect_rejected(f, "connectivity not a multiple of 8");
  f = two_hex_frame();
  f.points.pop_back();
  expect_rejected(f, "points not a multiple of 3");
  f = two_hex_frame();
  f.point_fields[2].component_names.pop_back();
  expect_rejected(f, "component names count");
  f = two_hex_frame();
  f.point_int_fields[0].name = "temperature";
  expect_rejected(f, "duplicate name within point data");
  f = two_hex_frame();
  f.cell_fields[0].components = 0;
  expect_rejected(f, "zero components");
  f = mixed_frame();
  f.quad_connectivity.pop_back();
  expect_rejected(f, "quad connectivity not a multiple of 4");
  f = mixed_frame();
  f.quad_connectivity[2] = 12;
  expect_rejected(f, "quad node index out of range");
  f = two_hex_frame();
  f.quad_connectivity = {0, 1, 2, 3};
  expect_rejected(f, "a quad without its cell field values");
  f = mixed_frame();
  f.field_strings.push_back({"notes", {}});
  expect_rejected(f, "repeated field-data name");
  f = mixed_frame();
  f.field_strings.push_back({"TimeValue", {}});
  expect_rejected(f, "reserved field-data name");
  EXPECT_TRUE(dir.entries().empty());
}
