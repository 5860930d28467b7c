// unsupported_field: the *MAT_054/055 fields material/composite_damage does not implement.
#include "config/mat054_spec.hpp"

#include "core/error.hpp"

namespace plyimpact::config {

std::optional<std::string> unsupported_field(const MatCompositeDamage& m) {
  auto say = [](const char* name, double value, const char* why) -> std::optional<std::string> {
    return std::string(msg() << name << "=" << value << " (" << why << ")");
  };
  if (m.CRIT != 54 && m.CRIT != 55) return say("CRIT", m.CRIT, "only 54 (Chang-Chang) and 55 (Tsai-Wu matrix) exist");
  if (m.TWOWAY != 0) return say("2WAY", m.TWOWAY, "two-way fabric option, thin shells only");
  if (m.TI != 0)
    return say("TI", m.TI, "transversely isotropic solid behaviour: its failure rules are not documented in our sources");
  if (m.KF != 0) return say("KF", m.KF, "bulk modulus of failed material is not implemented");
  if (m.axes.AOPT != 0 && m.axes.AOPT != 2 && m.axes.AOPT != 3)
    return say("AOPT", m.axes.AOPT, "only AOPT 0, 2 and 3 are implemented");
  if (m.XP != 0 || m.YP != 0 || m.ZP != 0)
    return say(m.XP != 0 ? "XP" : m.YP != 0 ? "YP" : "ZP", m.XP != 0 ? m.XP : m.YP != 0 ? m.YP : m.ZP,
               "point P serves AOPT 1 and 4 only, which are not implemented");
  if (m.PFL != 0) return say("PFL", m.PFL, "percentage of failed layers: shells only, a solid has one layer");
  if (m.SOFT2 != 1) return say("SOFT2", m.SOFT2, "orthogonal crashfront softening: its rule is not documented");
  const struct {
    const char* name;
    int id;
  } curves[] = {{"LCXC", m.LCXC}, {"LCXT", m.LCXT}, {"LCYC", m.LCYC}, {"LCYT", m.LCYT}, {"LCSC", m.LCSC}};
  for (const auto& c : curves)
    if (c.id != 0) return say(c.name, c.id, "strain-rate dependent strengths are not implemented");
  if (m.DT != 0) return say("DT", m.DT, "strain-rate averaging serves the LC* curves, which are not implemented");
  if (m.CRIT == 55) {
    // Card 7 and DFAILM/DFAILS act only for MAT_054 (KW; DC054): LS-DYNA would ignore them.
    const struct {
      const char* name;
      double value;
    } only54[] = {{"DFAILM", m.DFAILM}, {"DFAILS", m.DFAILS}, {"EPSF", m.EPSF}, {"EPSR", m.EPSR}, {"TSMD", m.TSMD}};
    for (const auto& f : only54)
      if (f.value != 0) return say(f.name, f.value, "acts only with CRIT 54 (MAT_054); LS-DYNA ignores it for 55");
  }
  return std::nullopt;
}

}  // namespace plyimpact::config
