#include "hourglass/element_elasticity.hpp"

#include <stdexcept>

#include "element/hex8.hpp"
#include "hourglass/assumed_strain.hpp"

namespace plyimpact::hourglass {

namespace {

material::Stiffness6 isotropic_stiffness(double lambda, double mu) {
  material::Stiffness6 C{};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) C[6 * a + b] = a == b ? lambda + 2 * mu : lambda;
  for (int s = 3; s < 6; ++s) C[7 * s] = mu;
  return C;
}

}  // namespace

material::Stiffness6 stiffness_in_material_axes(const model::Material& mat) {
  switch (mat.kind) {
    case model::MaterialKind::IsotropicElastic: return isotropic_stiffness(mat.iso.lambda, mat.iso.mu);
    case model::MaterialKind::Plastic: return isotropic_stiffness(mat.plastic.lambda, mat.plastic.shear);
    case model::MaterialKind::OrthotropicElastic: return mat.c_material;
    case model::MaterialKind::CompositeDamage: return mat.composite.C;
    case model::MaterialKind::JohnsonCook:
      return isotropic_stiffness(mat.bulk_modulus - 2 * mat.johnson_cook.shear / 3, mat.johnson_cook.shear);
    default: throw std::logic_error("hourglass moduli: material '" + mat.name + "' has no elastic constants");
  }
}

void element_axes_in_material_axes(const model::Model& model, const model::ElementBlock& block, std::size_t e,
                                   double (&n)[3][3]) {
  double J[9][1] = {};
  for (int k = 0; k < 8; ++k) {
    const double* X = &model.X[3 * std::size_t(block.conn[8 * e + k])];
    for (int i = 0; i < 3; ++i) {
      J[3 * i][0] += 0.125 * X[i] * element::kXi[k];
      J[3 * i + 1][0] += 0.125 * X[i] * element::kEta[k];
      J[3 * i + 2][0] += 0.125 * X[i] * element::kZeta[k];
    }
  }
  double Ef[9][1], ha[1], hb[1], hc[1];
  element_frame(J, 0, Ef, ha, hb, hc);
  const model::Material& mat = model.materials[block.material];
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 3; ++a) {
      if (mat.has_axes()) {
        const auto& Q = model.orientations[block.orientation[e]].axes;  // rows: material axes
        n[i][a] = Q[3 * a] * Ef[3 * i][0] + Q[3 * a + 1] * Ef[3 * i + 1][0] + Q[3 * a + 2] * Ef[3 * i + 2][0];
      } else {
        n[i][a] = Ef[3 * i + a][0];
      }
    }
}

}  // namespace plyimpact::hourglass
