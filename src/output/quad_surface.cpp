#include "output/quad_surface.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <bit>

#include "core/error.hpp"
#include "output/atomic_file.hpp"

namespace plyimpact::output {
namespace fs = std::filesystem;

namespace {

void check_surface(const QuadSurface& s, const fs::path& path) {
  const auto fail = [&](const std::string& what) {
    throw RunError(msg() << "cannot write '" << path.string() << "': " << what);
  };
  if (s.points.size() % 3 != 0) fail(msg() << "points has " << s.points.size() << " values, not a multiple of 3");
  if (s.quads.size() % 4 != 0) fail(msg() << "quads has " << s.quads.size() << " values, not a multiple of 4");
  const auto np = std::int64_t(s.num_points());
  for (std::size_t i = 0; i < s.quads.size(); ++i)
    if (s.quads[i] < 0 || s.quads[i] >= np)
      fail(msg() << "quad " << i / 4 << " refers to point " << s.quads[i] << " but there are " << np << " points");
  const auto check = [&](const char* where, std::size_t count, const std::vector<Field>& fields,
                         const std::vector<IntField>& ints) {
    for (const Field& f : fields)
      if (f.components < 1 || f.values.size() != count * std::size_t(f.components))
        fail(msg() << where << " field '" << f.name << "' has " << f.values.size() << " values for " << count << " x "
                   << f.components);
    for (const IntField& f : ints)
      if (f.values.size() != count)
        fail(msg() << where << " int field '" << f.name << "' has " << f.values.size() << " values for " << count);
  };
  check("point", s.num_points(), s.point_fields, s.point_int_fields);
  check("cell", s.num_quads(), s.cell_fields, s.cell_int_fields);
}

vtkNew<vtkUnstructuredGrid> make_grid(const QuadSurface& s) {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkDoubleArray> coords;
  coords->SetNumberOfComponents(3);
  coords->SetNumberOfTuples(vtkIdType(s.num_points()));
  std::copy(s.points.begin(), s.points.end(), coords->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coords);
  grid->SetPoints(points);

  const auto nq = vtkIdType(s.num_quads());
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(nq + 1);
  for (vtkIdType c = 0; c <= nq; ++c) offsets->SetValue(c, 4 * c);
  connectivity->SetNumberOfTuples(vtkIdType(s.quads.size()));
  std::copy(s.quads.begin(), s.quads.end(), connectivity->GetPointer(0));
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  grid->SetCells(VTK_QUAD, cells);

  const auto add = [](vtkDataSetAttributes* to, const std::vector<Field>& fields, const std::vector<IntField>& ints) {
    for (const Field& f : fields) {
      vtkNew<vtkDoubleArray> a;
      a->SetName(f.name.c_str());
      a->SetNumberOfComponents(f.components);
      a->SetNumberOfTuples(vtkIdType(f.values.size() / std::size_t(f.components)));
      std::copy(f.values.begin(), f.values.end(), a->GetPointer(0));
      to->AddArray(a);
    }
    for (const IntField& f : ints) {
      vtkNew<vtkIntArray> a;
      a->SetName(f.name.c_str());
      a->SetNumberOfTuples(vtkIdType(f.values.size()));
      std::copy(f.values.begin(), f.values.end(), a->GetPointer(0));
      to->AddArray(a);
    }
  };
  add(grid->GetPointData(), s.point_fields, s.point_int_fields);
  add(grid->GetCellData(), s.cell_fields, s.cell_int_fields);

  vtkNew<vtkDoubleArray> time;
  time->SetName("TimeValue");
  time->SetNumberOfTuples(1);
  time->SetValue(0, s.time);
  grid->GetFieldData()->AddArray(time);
  vtkNew<vtkTypeInt64Array> cycle;
  cycle->SetName("Cycle");
  cycle->SetNumberOfTuples(1);
  cycle->SetValue(0, s.cycle);
  grid->GetFieldData()->AddArray(cycle);
  if (!s.units.empty()) {
    vtkNew<vtkStringArray> units;
    units->SetName("units");
    units->SetNumberOfValues(vtkIdType(s.units.size()));
    for (std::size_t i = 0; i < s.units.size(); ++i)
      units->SetValue(vtkIdType(i), s.units[i].first + ": " + s.units[i].second);
    grid->GetFieldData()->AddArray(units);
  }
  return grid;
}

void append_xml_attribute(std::string& out, std::string_view text) {
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
}

}  // namespace

void write_quad_vtu(const QuadSurface& surface, const fs::path& path) {
  check_surface(surface, path);
  vtkNew<vtkUnstructuredGrid> grid = make_grid(surface);
  write_file_atomically(path, [&](const fs::path& tmp) {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetInputData(grid);
    writer->SetFileName(tmp.c_str());
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetHeaderTypeToUInt64();
    writer->SetCompressorTypeToNone();
    writer->Write();
    // Write() returns 1 even when it failed; the error code is the real status.
    if (const unsigned long code = writer->GetErrorCode(); code != vtkErrorCode::NoError)
      throw RunError(msg() << "VTK writer failed on '" << tmp.string()
                           << "': " << vtkErrorCode::GetStringFromErrorCode(code));
  });
}

void write_vtm(const fs::path& path, const std::vector<MultiBlockEntry>& blocks) {
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" byte_order=\"";
  xml += std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  xml += "\" header_type=\"UInt64\">\n  <vtkMultiBlockDataSet>\n";
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    xml += "    <DataSet index=\"" + std::to_string(i) + "\" name=\"";
    append_xml_attribute(xml, blocks[i].name);
    xml += "\" file=\"";
    append_xml_attribute(xml, blocks[i].file);
    xml += "\"/>\n";
  }
  xml += "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
  write_text_atomically(path, xml);
}

}  // namespace plyimpact::output
