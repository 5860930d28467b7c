// Channel frequency class (CFC) filtering of a sampled record, as crash and impact test laboratories
// filter force and acceleration channels before reading a peak (SAE J211-1, Appendix C).
//
// The filter is a two-pole low-pass Butterworth, designed by the bilinear transform, run forward and
// then backward over the record: no phase shift, and the magnitude of one pass squared,
//   G(f) = 1 / (1 + (tan(pi f T) / w_a)^4),   w_a = tan(pi T 2.0775 CFC),
// which is 1/sqrt(2) (-3 dB) at f ~ 1.67 CFC for T << 1/CFC. The factor 2.0775 is J211's: it puts
// the corner of the two passes where the class's corridor asks for it. The record starts and ends
// on the filter's steady state for its first and last value (a record that starts and ends flat,
// as an impact's force before contact and after separation, is filtered without an end transient).
#pragma once

#include <span>
#include <vector>

namespace plyimpact::study {

/// The record x, sampled every sample_interval seconds, filtered at channel frequency class cfc
/// (Hz; J211 names 60, 180, 600 and 1000). Needs sample_interval > 0 and cfc > 0; a record of
/// fewer than three samples is returned unchanged.
std::vector<double> cfc_filter(std::span<const double> x, double sample_interval, double cfc);

/// The filter's gain at frequency f (Hz), the closed form above.
double cfc_gain(double f, double sample_interval, double cfc);

}  // namespace plyimpact::study
