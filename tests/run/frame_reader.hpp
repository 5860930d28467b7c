// Test support: a written VTU frame read back with VTK's own XML reader, as ParaView would read it.
// Fields are returned by name as plain arrays, so tests compare the numbers a user sees.
#pragma once

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <string>
#include <vector>

namespace plyimpact::test {

struct ReadFrame {
  std::vector<double> points;  // (n, 3)
  vtkSmartPointer<vtkUnstructuredGrid> grid;

  // Tuple `i` of a point or cell array, all its components; fails the test if the array is missing.
  std::vector<double> point(const std::string& name, vtkIdType i) const { return tuple(grid->GetPointData(), name, i); }
  std::vector<double> cell(const std::string& name, vtkIdType i) const { return tuple(grid->GetCellData(), name, i); }
  std::size_t num_points() const { return points.size() / 3; }

 private:
  static std::vector<double> tuple(vtkFieldData* data, const std::string& name, vtkIdType i) {
    vtkDataArray* a = data->GetArray(name.c_str());
    if (a == nullptr) {
      ADD_FAILURE() << "field '" << name << "' is not in the frame";
      return {};
    }
    std::vector<double> out(std::size_t(a->GetNumberOfComponents()));
    for (int c = 0; c < a->GetNumberOfComponents(); ++c) out[std::size_t(c)] = a->GetComponent(i, c);
    return out;
  }
};

inline ReadFrame read_vtu(const std::filesystem::path& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  ReadFrame f;
  f.grid = reader->GetOutput();
  const vtkIdType n = f.grid->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i) {
    double p[3];
    f.grid->GetPoint(i, p);
    f.points.insert(f.points.end(), p, p + 3);
  }
  return f;
}

}  // namespace plyimpact::test
