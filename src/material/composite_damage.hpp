// *MAT_054 / *MAT_055 (enhanced composite damage) at one integration point of a solid element.
// Stress and strain are in MATERIAL axes (aa, bb, cc, ab, bc, ca; engineering shear strain), the
// update is incremental (hypoelastic) in the corotated material frame: the element kernel rotates
// the strain increment into the current material axes and the stress back. Units SI.
// Every choice where the manual is ambiguous is listed at the top of composite_damage.cpp.
#pragma once

#include "material/composite_damage_criteria.hpp"
#include "material/elastic.hpp"

namespace plyimpact::material {

// History of one integration point: kCompositeDamageHistory doubles, set by composite_damage_init.
namespace composite_history {
// Mode flags, as LS-DYNA's e_f, e_c, e_m, e_d: 1 intact, 0 failed (permanent).
inline constexpr int kFibreTension = 0;
inline constexpr int kFibreCompression = 1;
inline constexpr int kMatrixTension = 2;
inline constexpr int kMatrixCompression = 3;
// Current fibre strengths (Pa): XT, or FBRT*XT after e_d = 0; XC, or YCFAC*YC after e_d = 0.
inline constexpr int kXT = 4;
inline constexpr int kXC = 5;
// 6 values: total strain in material axes (sum of the increments, engineering shear), for DFAIL*,
// EFS and the transverse shear damage.
inline constexpr int kStrain = 6;
// d in [0, TSMD] on the bc and ca stresses (EPSF/EPSR); never decreases.
inline constexpr int kTransverseShearDamage = 12;
// 1 once the context reported the element on a crashfront.
inline constexpr int kCrashfront = 13;
// CompositeDamageCause of the erosion; 0 while the point is alive.
inline constexpr int kCause = 14;
// 4 values: last e^2 of fibre tension, fibre compression, matrix tension, matrix compression
// (-1 when the stress sign does not load the mode; frozen at the failure value once failed).
inline constexpr int kCriteria = 15;
// 5 values: cycles since the limit on aa tension, aa compression, bb tension, bb compression and
// ab shear started (0 = not started; 1 in the failure cycle), for the NCYRED ramp.
inline constexpr int kRampCycles = 19;
// 5 values: stress magnitude (Pa) at which each of those limits started.
inline constexpr int kRampStart = 24;
inline constexpr int kCount = 29;
}  // namespace composite_history
inline constexpr int kCompositeDamageHistory = composite_history::kCount;

// Why a point eroded (the element is deleted when its only point erodes).
enum class CompositeDamageCause : int {
  None = 0,
  FibreTension = 1,     // DFAILT = 0: fibre-tension criterion met
  DFAILT = 2,           // eps_aa >= DFAILT
  DFAILC = 3,           // eps_aa <= DFAILC
  DFAILM = 4,           // |eps_bb| >= DFAILM
  DFAILS = 5,           // |gamma_ab| / 2 >= DFAILS (tensorial shear)
  EFS = 6,              // effective strain >= EFS
  TFAIL = 7,            // element time step below TFAIL (absolute or ratio)
  TransverseShear = 8,  // EPSR < 0 and transverse shear damage reached TSMD
};
const char* composite_damage_cause_name(CompositeDamageCause c);

// Constants prepared once per material from the card (model/material_builder: composite_damage_params),
// no strings, trivially copyable.
struct CompositeDamageParams {
  Stiffness6 C{};             // undamaged stiffness, material axes (orthotropic_stiffness)
  double RO = 0;
  double wave_modulus = 0;    // max rho c^2 of the undamaged stiffness (max_wave_modulus)
  double GAB = 0, GBC = 0, GCA = 0;
  CompositeStrengths strength;  // as entered
  int CRIT = 54;
  double BETA = 0, ALPH = 0;
  double FBRT = 0, YCFAC = 2, SOFT = 1, SOFTG = 1;
  double SLIMT1 = 0, SLIMC1 = 0, SLIMT2 = 0, SLIMC2 = 0, SLIMS = 0;
  int NCYRED = 1;             // >= 1 (blank/0 -> 1: the stress drops in the failure cycle)
  double DFAILT = 0, DFAILC = 0, DFAILM = 0, DFAILS = 0, EFS = 0;
  double TFAIL = 0;
  double EPSF = 0, EPSR = 0, TSMD = 0.9;  // TSMD blank -> 0.90 (KW text)
  double erosion_reference_length = 0;    // m, 0 = off (config::MatCompositeDamage)
  bool erosion_nonlocal = false;          // config::MatCompositeDamage
};

// Undamaged state: flags 1, strengths as entered, zero strain, criteria -1.
void composite_damage_init(const CompositeDamageParams& p, double* history);

struct CompositeDamageContext {
  double element_dt = 0;  // current stable step of the element (s); <= 0: TFAIL not checked
  double initial_dt = 0;  // its step at t = 0 (s), for TFAIL > 0.1
  bool crashfront = false;  // the element shares a node with a deleted element
  // Factor (>= 1) on DFAILT, DFAILC, DFAILM, DFAILS and EFS for this element: erosion_reference_length
  // over the element's in-plane length when it is shorter (model::erosion_strain_scale), else 1.
  double erosion_scale = 1;
  // erosion_nonlocal: the card's strain limits (bits 1 << CompositeDamageCause, as
  // composite_damage_strain_limits) that the mean strain over the element's neighbourhood reached
  // in the previous pass; they erode the point whatever its own strain.
  int mean_limits = 0;
};

struct CompositeDamageResult {
  bool erode = false;  // the point has failed: its stress is zero from now on
  int cause = 0;       // CompositeDamageCause
};

// One cycle: dstrain = strain increment (material axes, engineering shear), stress = stress in
// material axes at the start of the cycle, overwritten with the new stress. No allocation.
CompositeDamageResult composite_damage_update(const CompositeDamageParams& p, const double dstrain[6],
                                              double stress[6], double* history,
                                              const CompositeDamageContext& ctx);

// The strain limits DFAILT, DFAILC, DFAILM, DFAILS and EFS, each times k, that the strain e
// (material axes, engineering shear) reaches, as bits 1 << CompositeDamageCause.
int composite_damage_strain_limits(const CompositeDamageParams& p, const double e[6], double k);

// In-plane components a point has lost to failure, as a bit mask: their tangent is zero from the
// failure on (removed, or held at the SLIM floor: perfectly plastic). Degradation table of
// composite_damage.cpp, item 2: fibre tension loses aa, bb and ab; fibre compression aa; matrix
// tension or compression bb and ab. The assumed-strain hourglass control (IHQ 6) follows it, so an
// element's hourglass modes are no stiffer than its material.
namespace lost_component {
inline constexpr int kAa = 1, kBb = 2, kAb = 4;
}
int composite_damage_lost_components(const double* history);

// A point that has failed in no mode and is not eroded (its degradation box is unbounded).
inline bool composite_damage_intact(const double* h) {
  namespace H = composite_history;
  return h[H::kCause] == 0 && h[H::kFibreTension] == 1 && h[H::kFibreCompression] == 1 &&
         h[H::kMatrixTension] == 1 && h[H::kMatrixCompression] == 1;
}

// rho c^2 for the stable time step: undamaged stiffness (damage only lowers it).
inline double composite_damage_wave_modulus(const CompositeDamageParams& p) { return p.wave_modulus; }

}  // namespace plyimpact::material
