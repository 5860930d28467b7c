// Contact surfaces from solid elements: the faces of a set of hexahedral blocks that are not shared
// by two active elements of the set (the exterior, and after erosion also the newly exposed
// faces; docs/theory.md section 10, EROSOP = 1). Face adjacency is found once by sorting the faces'
// node quadruples; a rebuild after element deletion is then one pass over the faces.
// Faces are quads in LS-DYNA/VTK order with the outward normal t_xi x t_eta.
#pragma once

#include <vector>

#include "model/model.hpp"

namespace plyimpact::contact {

// Outward faces of a hexahedron (LS-DYNA node order 1-4 bottom, 5-8 top), local node numbers.
inline constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                        {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// alive[b][e] != 0: element e of block b is active; an empty vector for a block means all active.
using AliveMask = std::vector<std::vector<char>>;

class SurfaceBuilder {
 public:
  SurfaceBuilder() = default;
  SurfaceBuilder(const model::Model& model, const std::vector<int>& blocks);

  struct Face {
    int block = 0;
    Index element = 0;  // index within the block
    int face = 0;       // 0..5, kHexFaces
  };

  // Exterior faces of the active elements (faces whose neighbour across is absent or inactive).
  std::vector<Face> exterior(const AliveMask* alive) const;

 private:
  bool active(const AliveMask* alive, int block, Index e) const;
  std::vector<Face> faces_;          // every face of every element of the set
  std::vector<long> neighbour_;      // (num faces) index of the face across, -1 none
};

}  // namespace plyimpact::contact
