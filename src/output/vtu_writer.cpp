#include "output/vtu_writer.hpp"

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
#include <vtkTypeInt64Array.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <set>
#include <string>

#include "core/error.hpp"
#include "output/atomic_file.hpp"

namespace plyimpact::output {
namespace fs = std::filesystem;

namespace {

// A malformed Frame is a bug in the code that filled it, but it surfaces during a run, so it is
// reported like any other run failure: one line naming the file and the offending array.
void check_frame(const Frame& frame, const fs::path& path) {
  const auto fail = [&](const std::string& what) {
    throw RunError(msg() << "cannot write '" << path.string() << "': " << what);
  };
  if (frame.points.size() % 3 != 0) {
    fail(msg() << "points has " << frame.points.size() << " values, not a multiple of 3");
  }
  if (frame.hex_connectivity.size() % 8 != 0) {
    fail(msg() << "hex_connectivity has " << frame.hex_connectivity.size()
               << " values, not a multiple of 8");
  }
  const auto num_points = static_cast<std::int64_t>(frame.num_points());
  for (std::size_t i = 0; i < frame.hex_connectivity.size(); ++i) {
    const std::int64_t node = frame.hex_connectivity[i];
    if (node < 0 || node >= num_points) {
      fail(msg() << "cell " << i / 8 << " refers to node " << node << " but there are "
                 << num_points << " points");
    }
  }

  const auto check_set = [&](const char* where, std::size_t count, const std::vector<Field>& fields,
                             const std::vector<IntField>& int_fields) {
    // Point (or cell) double and int arrays share one vtkPointData (vtkCellData); a repeated name
    // would silently replace the earlier array.
    std::set<std::string> names;
    const auto check_name = [&](const std::string& name) {
      if (name.empty()) fail(msg() << where << " field with an empty name");
      if (!names.insert(name).second) fail(msg() << where << " field '" << name << "' repeated");
    };
    for (const Field& f : fields) {
      check_name(f.name);
      if (f.components < 1) {
        fail(msg() << where << " field '" << f.name << "' has " << f.components << " components");
      }
      const std::size_t expected = count * static_cast<std::size_t>(f.components);
      if (f.values.size() != expected) {
        fail(msg() << where << " field '" << f.name << "' has " << f.values.size()
                   << " values, expected " << count << " x " << f.components << " = " << expected);
      }
      if (!f.component_names.empty() &&
          f.component_names.size() != static_cast<std::size_t>(f.components)) {
        fail(msg() << where << " field '" << f.name << "' has " << f.component_names.size()
                   << " component names for " << f.components << " components");
      }
    }
    for (const IntField& f : int_fields) {
      check_name(f.name);
      if (f.values.size() != count) {
        fail(msg() << where << " int field '" << f.name << "' has " << f.values.size()
                   << " values, expected " << count);
      }
    }
  };
  check_set("point", frame.num_points(), frame.point_fields, frame.point_int_fields);
  check_set("cell", frame.num_cells(), frame.cell_fields, frame.cell_int_fields);
}

vtkNew<vtkDoubleArray> make_array(const Field& f) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(f.name.c_str());
  a->SetNumberOfComponents(f.components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(f.values.size() / f.components));
  std::copy(f.values.begin(), f.values.end(), a->GetPointer(0));
  for (std::size_t c = 0; c < f.component_names.size(); ++c) {
    a->SetComponentName(static_cast<vtkIdType>(c), f.component_names[c].c_str());
  }
  return a;
}

vtkNew<vtkIntArray> make_array(const IntField& f) {
  vtkNew<vtkIntArray> a;
  a->SetName(f.name.c_str());
  a->SetNumberOfComponents(1);
  a->SetNumberOfTuples(static_cast<vtkIdType>(f.values.size()));
  std::copy(f.values.begin(), f.values.end(), a->GetPointer(0));
  return a;
}

vtkNew<vtkUnstructuredGrid> make_grid(const Frame& frame) {
  vtkNew<vtkUnstructuredGrid> grid;

  vtkNew<vtkDoubleArray> coords;
  coords->SetNumberOfComponents(3);
  coords->SetNumberOfTuples(static_cast<vtkIdType>(frame.num_points()));
  std::copy(frame.points.begin(), frame.points.end(), coords->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coords);
  grid->SetPoints(points);

  const auto num_cells = static_cast<vtkIdType>(frame.num_cells());
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(num_cells + 1);
  for (vtkIdType c = 0; c <= num_cells; ++c) offsets->SetValue(c, 8 * c);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(frame.hex_connectivity.size()));
  std::copy(frame.hex_connectivity.begin(), frame.hex_connectivity.end(),
            connectivity->GetPointer(0));
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  grid->SetCells(VTK_HEXAHEDRON, cells);

  for (const Field& f : frame.point_fields) grid->GetPointData()->AddArray(make_array(f));
  for (const IntField& f : frame.point_int_fields) grid->GetPointData()->AddArray(make_array(f));
  for (const Field& f : frame.cell_fields) grid->GetCellData()->AddArray(make_array(f));
  for (const IntField& f : frame.cell_int_fields) grid->GetCellData()->AddArray(make_array(f));

  // "TimeValue" is the field-data name ParaView's readers look for; the cycle is kept alongside
  // so a lone file still says which step it came from.
  vtkNew<vtkDoubleArray> time;
  time->SetName("TimeValue");
  time->SetNumberOfTuples(1);
  time->SetValue(0, frame.time);
  grid->GetFieldData()->AddArray(time);
  vtkNew<vtkTypeInt64Array> cycle;
  cycle->SetName("Cycle");
  cycle->SetNumberOfTuples(1);
  cycle->SetValue(0, frame.cycle);
  grid->GetFieldData()->AddArray(cycle);
  return grid;
}

}  // namespace

void write_vtu(const Frame& frame, const fs::path& path, const WriteOptions& options) {
  check_frame(frame, path);
  vtkNew<vtkUnstructuredGrid> grid = make_grid(frame);

  write_file_atomically(path, [&](const fs::path& tmp) {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetInputData(grid);
    writer->SetFileName(tmp.c_str());
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();  // raw bytes, not base64: exact and 25% smaller
    writer->SetHeaderTypeToUInt64();
    if (options.compress) {
      writer->SetCompressorTypeToZLib();
    } else {
      writer->SetCompressorTypeToNone();  // VTK's default is zlib
    }
    writer->Write();
    // Write() returns 1 even when it failed (toolchain V3); the error code is the real status.
    const unsigned long code = writer->GetErrorCode();
    if (code != vtkErrorCode::NoError) {
      throw RunError(msg() << "VTK writer failed on '" << tmp.string()
                           << "': " << vtkErrorCode::GetStringFromErrorCode(code));
    }
  });
}

}  // namespace plyimpact::output
