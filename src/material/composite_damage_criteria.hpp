// Failure criteria of *MAT_054 / *MAT_055 (docs/theory.md section 7) as pure functions of the in-plane
// stresses in material axes. Each value is LS-DYNA's e^2: the criterion minus 1, so >= 0 means the
// mode has failed. A mode whose stress sign does not apply (fibre tension with sigma_aa < 0, ...)
// gets -1, the value of an unloaded mode.
#pragma once

namespace plyimpact::material {

// Current strengths, all positive (Pa): after FBRT/YCFAC and crashfront SOFT.
struct CompositeStrengths {
  double XT = 0, XC = 0, YT = 0, YC = 0, SC = 0;
};

struct CompositeCriteria {
  double fibre_tension = -1, fibre_compression = -1, matrix_tension = -1, matrix_compression = -1;
};

// Energy-like shear ratio of MAT_022 (SCR22):
//   tau_bar = (tau^2/(2 GAB) + 3/4 ALPH tau^4) / (SC^2/(2 GAB) + 3/4 ALPH SC^4),
// equal to (tau/SC)^2 when ALPH = 0.
double shear_ratio(double tau, double sc, double gab, double alph);

// crit 54 (Chang-Chang) or 55 (Tsai-Wu matrix). beta: fibre-tension shear weight in [0, 1].
//   fibre tension,      s_aa >= 0: (s_aa/XT)^2 + beta tau_bar - 1
//   fibre compression,  s_aa <  0: (s_aa/XC)^2 - 1
//   crit 54, s_bb >= 0: (s_bb/YT)^2 + tau_bar - 1                                   (matrix tension)
//            s_bb <  0: (s_bb/2SC)^2 + [(YC/2SC)^2 - 1] s_bb/YC + tau_bar - 1        (matrix compression)
//   crit 55, either sign: s_bb^2/(YC YT) + tau_bar + (YC - YT) s_bb/(YC YT) - 1, reported as matrix
//            tension for s_bb >= 0 and matrix compression for s_bb < 0.
CompositeCriteria composite_criteria(int crit, double beta, double alph, double gab, const CompositeStrengths& s,
                                     double s_aa, double s_bb, double s_ab);

}  // namespace plyimpact::material
