#include "solver/element_update.hpp"

#include "solver/element_families.hpp"

namespace plyimpact::solver {

void update_elements(const model::Model& model, const model::ElementBlock& block, BlockState& state, Index begin,
                     Index end, const double* x, const double* v, double* f, double dt, ChunkResult& result) {
  // Accumulate in a local copy and write once: results of neighbouring chunks share cache lines and
  // are written by different threads.
  ChunkResult local;
  switch (element_family(block)) {
    case ElementFamily::Hex8OnePoint: update_hex8_one_point(model, block, state, begin, end, x, v, f, dt, local); break;
    case ElementFamily::Hex8SelectiveReduced:
      update_hex8_selective(model, block, state, begin, end, x, v, f, dt, local);
      break;
  }
  result = local;
}

}  // namespace plyimpact::solver
