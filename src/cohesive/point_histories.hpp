// What every interface kernel (tiebreak pairs, segment ties, cohesive elements) keeps per point of
// the law and sums over its points:
//   PointHistories : the five PointHistory fields (traction_law.hpp) as five arrays of num_points
//                    doubles, loaded into and stored from a PointHistory around each traction_update,
//                    and named in the run state as max_opening, damage, slip_1, slip_2, stick_energy
//                    (in that order: a restart dump is these arrays in sequence);
//   ChunkSums      : per fixed chunk of points the elastic energy, dissipation and separated area of
//                    the last pass, added in chunk order, so the totals are bit-identical for any
//                    thread count.
#pragma once

#include <cstddef>
#include <vector>

#include "cohesive/traction_law.hpp"
#include "core/state_visitor.hpp"

namespace plyimpact::cohesive {

class PointHistories {
 public:
  // n points, all intact and unloaded.
  void assign(std::size_t n) {
    for (auto* a : {&max_opening_, &damage_, &slip1_, &slip2_, &stick_energy_}) a->assign(n, 0.0);
  }
  std::size_t size() const { return damage_.size(); }

  [[gnu::always_inline]] PointHistory load(std::size_t p) const {
    return {max_opening_[p], damage_[p], slip1_[p], slip2_[p], stick_energy_[p]};
  }
  [[gnu::always_inline]] void store(std::size_t p, const PointHistory& h) {
    max_opening_[p] = h.max_opening;
    damage_[p] = h.damage;
    slip1_[p] = h.slip1;
    slip2_[p] = h.slip2;
    stick_energy_[p] = h.stick_energy;
  }

  const std::vector<double>& damage() const { return damage_; }  // (num_points)
  // For the SIMD path of intact points, which reads damage and updates max_opening in place.
  double* max_opening_data() { return max_opening_.data(); }
  // Initial history of a pre-crack: point p starts separated.
  void separate(std::size_t p) { damage_[p] = 1.0; }
  // A point that lets go for good (its master gone): separated, its stick spring unloaded.
  void release(std::size_t p) {
    damage_[p] = 1.0;
    stick_energy_[p] = 0.0;
  }

  void visit_state(StateVisitor& visitor) {
    visitor.array("max_opening", max_opening_);
    visitor.array("damage", damage_);
    visitor.array("slip_1", slip1_);
    visitor.array("slip_2", slip2_);
    visitor.array("stick_energy", stick_energy_);
  }

 private:
  std::vector<double> max_opening_, damage_, slip1_, slip2_, stick_energy_;
};

// Three arrays, not one array of triples: adjacent stores of the three sums would let the compiler
// pack the running sums into one vector register and round them differently from a scalar build.
class ChunkSums {
 public:
  struct Totals {
    double elastic = 0, dissipated = 0, separated = 0;
  };
  void assign(std::size_t num_chunks) {
    for (auto* a : {&elastic_, &dissipated_, &separated_}) a->assign(num_chunks, 0.0);
  }
  std::size_t size() const { return elastic_.size(); }
  void set(std::size_t chunk, double elastic, double dissipated, double separated) {
    elastic_[chunk] = elastic;
    dissipated_[chunk] = dissipated;
    separated_[chunk] = separated;
  }
  Totals total() const {  // in chunk order
    Totals t;
    for (std::size_t c = 0; c < elastic_.size(); ++c) {
      t.elastic += elastic_[c];
      t.dissipated += dissipated_[c];
      t.separated += separated_[c];
    }
    return t;
  }

 private:
  std::vector<double> elastic_, dissipated_, separated_;  // (num_chunks) of the last pass
};

}  // namespace plyimpact::cohesive
