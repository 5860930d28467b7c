// A frame of output: an unstructured grid of hexahedra (and, after them, quadrilaterals) with named
// point and cell fields, as plain arrays, and field data that describes the file: each array's
// unit, legends of coded values, notes. The solver (and the mesher) fill it; the writers turn it
// into VTU/PVD. Keeping this independent of the solver's internals means output/ never reaches into
// the model.
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
  // Optional, e.g. "Pa", "1" (dimensionless): listed in the file's `units`. The "= {}" keeps
  // aggregate initializations that stop before it free of -Wmissing-field-initializers.
  std::string unit = {};
};

struct IntField {
  std::string name;
  std::vector<std::int32_t> values;  // one per cell or point
  std::string unit = {};             // optional, as Field::unit
};

// A field-data array of strings (one tuple per entry): legends ("0: alive"), notes, names.
struct StringField {
  std::string name;
  std::vector<std::string> values;
};

struct Frame {
  double time = 0;
  long cycle = 0;
  std::vector<double> points;             // (num_points, 3) current coordinates, SI
  std::vector<std::int64_t> hex_connectivity;   // (num_hexes, 8), VTK_HEXAHEDRON node order
  std::vector<std::int64_t> quad_connectivity;  // (num_quads, 4), VTK_QUAD order; cells after the hexes
  std::vector<Field> point_fields;
  std::vector<Field> cell_fields;
  std::vector<IntField> point_int_fields;
  std::vector<IntField> cell_int_fields;
  std::vector<StringField> field_strings;  // field data (not per point or cell)
  std::size_t num_points() const { return points.size() / 3; }
  std::size_t num_hexes() const { return hex_connectivity.size() / 8; }
  std::size_t num_quads() const { return quad_connectivity.size() / 4; }
  std::size_t num_cells() const { return num_hexes() + num_quads(); }
};

}  // namespace plyimpact::output
