#include "material/composite_damage_lanes.hpp"

#include "core/voigt.hpp"

namespace plyimpact::material {

CompositeDamageResult composite_point_update(const CompositeDamageParams& p, const double Qo[9],
                                                    const double Qn[9], const double D[6], double dt,
                                                    const CompositeDamageContext& ctx, double s[6], double* history) {
  double sm[6], de[6], dm[6];
  for (int i = 0; i < 6; ++i) de[i] = D[i] * dt;
  rotate_voigt(Qo, s, sm);  // stress in the old material axes
  rotate_voigt(Qn, de, dm);  // strain increment in the new ones
  for (int i = 3; i < 6; ++i) dm[i] *= 2;  // engineering shear
  const auto res = composite_damage_update(p, dm, sm, history, ctx);
  const double Sm[9] = {sm[0], sm[3], sm[5], sm[3], sm[1], sm[4], sm[5], sm[4], sm[2]};
  constexpr int kV[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      double sum = 0;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) sum += Qn[3 * a + i] * Sm[3 * a + b] * Qn[3 * b + j];
      s[kV[i][j]] = sum;
    }
  return res;
}

}  // namespace plyimpact::material
