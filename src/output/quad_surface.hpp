// Quad surfaces as VTK XML unstructured grids (.vtu with VTK_QUAD cells), and a multiblock file
// (.vtm) that names a set of such files as the blocks of one dataset. Used for the delaminating
// interfaces (one block each, on their current mid-surface) and the C-scan plane. The hexahedral
// ply frames have their own writer (vtu_writer.hpp); this one shares its file conventions: binary
// appended raw data, UInt64 headers, a "TimeValue" field-data entry, atomic replacement.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "output/frame.hpp"

namespace plyimpact::output {

struct QuadSurface {
  double time = 0;
  long cycle = 0;
  std::vector<double> points;             // (num_points, 3) m
  std::vector<std::int64_t> quads;        // (num_quads, 4) point indices, VTK_QUAD order
  std::vector<Field> point_fields, cell_fields;
  std::vector<IntField> point_int_fields, cell_int_fields;
  // Field-data string array "units": one "<field>: <unit>" entry per pair, so the file says its units.
  std::vector<std::pair<std::string, std::string>> units;
  std::size_t num_points() const { return points.size() / 3; }
  std::size_t num_quads() const { return quads.size() / 4; }
};

/// Validates the sizes and indices of `surface` and writes it to `path` atomically. Throws
/// plyimpact::RunError naming the path and the offending array.
void write_quad_vtu(const QuadSurface& surface, const std::filesystem::path& path);

struct MultiBlockEntry {
  std::string name;  // block name ParaView shows
  std::string file;  // path relative to the .vtm's directory
};

/// Atomically writes a vtkMultiBlockDataSet file (.vtm, XML version 1.0) listing `blocks` in order.
void write_vtm(const std::filesystem::path& path, const std::vector<MultiBlockEntry>& blocks);

}  // namespace plyimpact::output
