// A frame of output: an unstructured hexahedral grid with named point and cell fields, as plain
// arrays. The solver (and the mesher) fill it; the writers turn it into VTU/PVD. Keeping this
// independent of the solver's internals means output/ never reaches into the model.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace plyimpact::output {

struct Field {
  std::string name;
  int components = 1;         // 1 scalar, 3 vector, 6 symmetric tensor (xx yy zz xy yz zx), 9 ...
  std::vector<double> values; // (count, components) row-major
  std::vector<std::string> component_names;  // optional, e.g. {"xx","yy","zz","xy","yz","zx"}
};

struct IntField {
  std::string name;
  std::vector<std::int32_t> values;  // one per cell or point
};

struct Frame {
  double time = 0;
  long cycle = 0;
  std::vector<double> points;             // (num_points, 3) current coordinates, SI
  std::vector<std::int64_t> hex_connectivity;  // (num_cells, 8), VTK_HEXAHEDRON node order
  std::vector<Field> point_fields;
  std::vector<Field> cell_fields;
  std::vector<IntField> point_int_fields;
  std::vector<IntField> cell_int_fields;
  std::size_t num_points() const { return points.size() / 3; }
  std::size_t num_cells() const { return hex_connectivity.size() / 8; }
};

}  // namespace plyimpact::output
