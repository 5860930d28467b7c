// *MAT_054 / *MAT_055 (*MAT_ENHANCED_COMPOSITE_DAMAGE): every field of the LS-DYNA card (docs/theory.md section 7;
// section 6.1; seed Figure 7.3), under its card name, in SI. Defaults are the card defaults
// (the card field texts): SOFT 1, YCFAC 2, CRIT 54, SOFT2 1, SOFTG 1; every other field blank = 0.
// TSMD has no card default; its 0.90 is applied inside the material (material/composite_damage),
// so 0 here means "internal default". Nothing here depends on yaml-cpp.
#pragma once

#include <optional>
#include <string>

#include "config/material_axes.hpp"

namespace plyimpact::config {

struct MatCompositeDamage {
  // Card 1. PRBA, PRCA, PRCB are LS-DYNA's minor ratios nu_ba, nu_ca, nu_cb (as on *MAT_002).
  double RO = 0, EA = 0, EB = 0, EC = 0, PRBA = 0, PRCA = 0, PRCB = 0;
  // Card 2. KF: bulk modulus of failed material (unused by LS-DYNA). TWOWAY is the card's 2WAY
  // (1 = two-way fabric, thin shells only). TI: 1 = transversely isotropic solid behaviour.
  double GAB = 0, GBC = 0, GCA = 0, KF = 0;
  int TWOWAY = 0, TI = 0;
  // Cards 3-4. AOPT, A1-A3, V1-V3, D1-D3 and MANGLE live in `axes` (MANGLE = axes.BETA, rad);
  // XP, YP, ZP (m) only serve AOPT 1 and 4.
  MaterialAxes axes;
  double XP = 0, YP = 0, ZP = 0;
  double DFAILM = 0, DFAILS = 0;  // matrix strain (|eps_bb|), tensorial shear strain (|gamma_ab|/2)
  // Card 5. TFAIL: <= 0 off; (0, 0.1] absolute element step limit (s); > 0.1 ratio dt/dt0
  // (the card field texts). ALPH: nonlinear shear term (Pa^-3). DFAILC is negative.
  double TFAIL = 0, ALPH = 0, SOFT = 1, FBRT = 0, YCFAC = 2, DFAILT = 0, DFAILC = 0, EFS = 0;
  // Card 6. Strengths entered positive (Pa). BETA: weight of shear in the fibre-tension criterion
  // (NOT the material angle, which is MANGLE).
  double XC = 0, XT = 0, YC = 0, YT = 0, SC = 0;
  int CRIT = 54;
  double BETA = 0;
  // Card 7 (MAT_054 only). PFL: % of layers failed before crashfront (shells). EPSF/EPSR: transverse
  // shear damage start / end strain; TSMD: its cap (0 = internal 0.90); SOFT2: orthogonal softening.
  double PFL = 0, EPSF = 0, EPSR = 0, TSMD = 0, SOFT2 = 1;
  // Card 8. Residual stress limits as fractions of the strengths; NCYRED: cycles of stress ramp-down;
  // SOFTG: transverse shear moduli factor in crashfront elements.
  double SLIMT1 = 0, SLIMC1 = 0, SLIMT2 = 0, SLIMC2 = 0, SLIMS = 0;
  int NCYRED = 0;
  double SOFTG = 1;
  // Card 9. Strength vs strain-rate curve ids and the rate averaging window (s).
  int LCXC = 0, LCXT = 0, LCYC = 0, LCYT = 0, LCSC = 0;
  double DT = 0;
  // Not on the LS-DYNA card (a plyimpact extension): the element length (m) at which DFAILT, DFAILC,
  // DFAILM, DFAILS and EFS hold. An element shorter than it in the ply plane erodes at those strains
  // times erosion_reference_length / its length, so its elongation at erosion is the reference
  // element's (docs/theory.md, "Erosion strains and the element length"). 0 = the card's strains in
  // every element.
  double erosion_reference_length = 0;
  // An element shorter than erosion_reference_length also erodes at the card's limits where the mean
  // strain within that length of it (its own included) reaches them, as *MAT_NONLOCAL: a uniform
  // field then erodes at the card's strain, a one-element band near the factor's.
  bool erosion_nonlocal = false;
};

// The first field set to a value this code does not implement, as "NAME=value (reason)", or
// nullopt when every field is supported. The loader refuses the card with this text: a field the
// code does not implement is never silently ignored.
std::optional<std::string> unsupported_field(const MatCompositeDamage& m);

}  // namespace plyimpact::config
