// The projected delamination map an inspector's ultrasonic C-scan gives: every delaminating
// interface projected onto the plate plane, the union of their delaminated areas, and per point the
// depth of the shallowest delaminated interface below the impacted face, which is what a
// pulse-echo scan from the impacted side shows (the first reflector hides those below it). Extra
// layers: the depth of the deepest one (what a scan from the back face would reach first, measured
// from the impacted face), the number of delaminated interfaces and the shallowest one's number.
//
// The map is a raster of square cells of side `pitch` over the layers' bounding box, each cell
// taking the state at its centre. On an interface, a point belongs to the sample point (node pair)
// whose tributary area holds it: in a quad's parametric square, the quarter at that corner, which is
// how the interface's delaminated area (history.csv) is counted. With a uniform mesh of spacing h,
// a pitch of h/2 and the raster aligned with the mesh (the default), the cell edges fall on those
// quarter boundaries and the areas are exact; otherwise the error is below half a cell along the
// delamination's outline.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace plyimpact::output {

struct CscanLayer {
  int id = 0;                          // interface number
  double depth = 0;                    // m below the impacted face
  std::vector<double> xy;              // (num_points, 2) m, in-plane reference coordinates
  std::vector<std::int64_t> quads;     // (num_quads, 4) point indices
  std::vector<char> delaminated;       // (num_points) 1 where separated
};

struct CscanMap {
  double x0 = 0, y0 = 0, pitch = 0;    // m, lower-left corner and cell side
  int nx = 0, ny = 0;                  // cells; cell (i, j) is value index j * nx + i
  std::vector<double> shallowest;      // (ny * nx) m below the impacted face, NaN where no delamination
  std::vector<double> deepest;         // (ny * nx) m, NaN where none
  std::vector<int> count;              // (ny * nx) delaminated interfaces
  std::vector<int> shallowest_id;      // (ny * nx) interface number, 0 where none
  double projected_area() const;       // m^2, the union: cells with count > 0 times pitch^2
};

/// Half the shortest quad edge of any layer, raised if needed so the raster has at most
/// `max_cells` cells. Throws RunError when the layers have no quad.
double cscan_pitch(const std::vector<CscanLayer>& layers, std::size_t max_cells = 4'000'000);

/// Rasterises the layers at `pitch` (m) from the lower-left corner of their bounding box.
CscanMap make_cscan(const std::vector<CscanLayer>& layers, double pitch);

/// cscan.vtu: the raster as quads in the plane z = `z` (m, coordinates in m like the ply frames so
/// the two overlay in ParaView), cell data depth_shallowest and depth_deepest in mm (NaN where no
/// delamination), interfaces_delaminated, shallowest_interface, and a field-data "units" entry.
void write_cscan_vtu(const CscanMap& map, double z, double time, const std::filesystem::path& path);

/// cscan.png (width x height pixels) by gnuplot: axes in mm, equal aspect, the depth of the shallowest
/// delamination as colour with its legend over [0, max_depth] (m), undelaminated points white.
void write_cscan_png(const CscanMap& map, double max_depth, const std::string& title,
                     const std::filesystem::path& path, int width = 1000, int height = 750);

}  // namespace plyimpact::output
