// The measurements of a fracture coupon (config::CouponSpec: DCB, ENF, MMB) as history.csv
// columns `load`, `opening` and `crack_length` (SI: N, m, m), the columns `plyimpact dcb-reduce`
// reads by default, so a simulated DCB is reduced as a test machine's record is. It only reads the
// solver: the load is the reaction the solver records at the loading block, the opening comes from
// the blocks' mean displacements, and the crack length from the interface's damage (the separated
// pairs, pre-crack included). docs/coupons.md gives the definitions.
#pragma once

#include <string>
#include <vector>

#include "interface/interface_output.hpp"
#include "run/history_writer.hpp"

namespace plyimpact::run {

class CouponProbe : public HistoryColumns {
 public:
  // model.coupon must be set; its sets and interface are those the scene loader checked.
  explicit CouponProbe(const model::Model& model);

  std::vector<std::string> columns() const override { return {"load", "opening", "crack_length"}; }
  void values(const solver::Solver& solver, std::vector<double>& row) const override;

  double load(const solver::Solver& solver) const;     // N
  double opening(const solver::Solver& solver) const;  // m
  double crack_length(const solver::Solver& solver) const;  // m

 private:
  const model::Model& model_;
  int axis_ = 2;
  int reaction_ = 0;        // index into State::reaction / 3 (the load set among the constrained sets)
  double load_sign_ = 1;    // +1 when the load set is the upper block, -1 when it is the lower one
  std::vector<Index> upper_, lower_;
  int interface_ = 0;       // 1-based interface number
  double origin_ = 0;       // m, x of the load line
  // The interface's outputs, found among the solver's contributors at the first call, and the
  // sorted distinct reference x of its rows of sample points.
  struct Found {
    const interface::InterfaceSampleSource* source = nullptr;
    std::size_t index = 0;
    std::vector<double> rows;
  };
  const Found& find(const solver::Solver& solver) const;
  mutable Found found_;
};

}  // namespace plyimpact::run
