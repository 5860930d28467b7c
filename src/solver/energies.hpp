// Global energy balance at one time, as a named list: the integrator's own terms (kinetic, internal,
// hourglass, bulk viscous, external work) followed by those of the force contributors (contact,
// friction, rigid wall, interfaces ...). The balance check, history.csv and summary.json all read
// this list, so a new energy appears in all three by being named once (docs/theory.md section 11:
// sliding energy with SLNTEN = 2, rigid-wall energy with RWEN = 2; the eroded kinetic energy).
//   total = sum of the terms counted in the total (in list order)
//   ratio = total / (initial total + external work), 1 for a perfect balance
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace plyimpact::solver {

struct EnergyTerm {
  std::string key;     // summary.json final_energies key
  std::string column;  // history.csv column
  bool in_total = true;
  double value = 0;    // J
  int owner = -1;      // index of the force contributor that reports it, or Energies::kIntegrator / kErosion
};

class Energies {
 public:
  enum Own : std::size_t { kKinetic, kInternal, kHourglass, kBulkViscous, kExternalWork, kNumOwn };
  // Owners of the terms that no contributor reports: the integrator's own (above), and the kinetic
  // energy of the nodes erosion removed (appended after the contributors' terms; history.csv lists
  // it with the erosion columns).
  static constexpr int kIntegrator = -1, kErosion = -2;

  Energies();

  double time = 0;  // s
  std::vector<EnergyTerm> terms;

  double kinetic() const { return terms[kKinetic].value; }
  double internal() const { return terms[kInternal].value; }
  double hourglass() const { return terms[kHourglass].value; }
  double bulk_viscous() const { return terms[kBulkViscous].value; }
  double external_work() const { return terms[kExternalWork].value; }
  // Value of the term with this key; 0 when the run has no such term.
  double value(std::string_view key) const;
  double total() const;
};

}  // namespace plyimpact::solver
