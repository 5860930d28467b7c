// History rows are at t^n, the balance's time (the kinetic energy needs v^{n+1/2}), but the force
// pass that ends a cycle is at t^{n+1}: a row that printed a contributor's last forces showed them
// one cycle early (a rigid wall's force began two steps before the impact). A contributor whose
// columns are forces keeps them here and prints the pass before its last one, which is at the
// row's time; at the start the single pass and the row are both at t = 0.
#pragma once

#include <span>
#include <vector>

#include "core/state_visitor.hpp"

namespace plyimpact::solver {

class RowLag {
 public:
  // After each pass, with the values just computed; initial: the pass at t = 0, before any step.
  void record(std::span<const double> current, bool initial) {
    if (initial || last_.size() != current.size())
      row_.assign(current.begin(), current.end());
    else
      row_.swap(last_);
    last_.assign(current.begin(), current.end());  // same size after the first pass: no allocation
  }
  // The values at the history row's time t^n.
  std::span<const double> row() const { return row_; }
  void visit_state(StateVisitor& visitor) {
    visitor.array("history_row", row_);
    visitor.array("history_last", last_);
  }

 private:
  std::vector<double> last_, row_;
};

}  // namespace plyimpact::solver
