#include "solver/energies.hpp"

namespace plyimpact::solver {

Energies::Energies()
    : terms{{"kinetic", "kinetic_energy"},
            {"internal", "internal_energy"},
            {"hourglass", "hourglass_energy"},
            {"bulk_viscous", "bulk_viscous_energy"},
            {"external_work", "external_work", false}} {}

double Energies::value(std::string_view key) const {
  for (const auto& t : terms)
    if (t.key == key) return t.value;
  return 0.0;
}

double Energies::total() const {
  double sum = 0;
  for (const auto& t : terms)
    if (t.in_total) sum += t.value;
  return sum;
}

}  // namespace plyimpact::solver
