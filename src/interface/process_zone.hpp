// Interface strengths lowered segment by segment so that the cohesive process zone spans a given
// number of segments (InterfaceLawSpec::process_zone_elements): the remedy of Turon, Davila, Camanho
// & Costa (2007, Eng. Fract. Mech. 74:1665) for meshes coarser than the zone, and what LS-DYNA's
// OPTION 9 and *MAT_138 do with NFLS/SFLS (T/S) given as curves of the element length. A segment of
// length l gets min(card strength, sqrt(9 pi E G_c / (32 N l))) in each mode, with G_c = ERATEN or
// ERATES and E the interface's transverse modulus (model::Interface); the energies G_c and the
// stiffness are kept, so a coarse segment dissipates what a fine one does, over a longer zone.
// The length of a segment is sqrt(its reference area); of a tiebreak pair, sqrt(the mean area of
// the segments it is a corner of).
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"

namespace plyimpact::interface {

struct SegmentStrengths {
  std::vector<double> nfls, sfls;  // Pa, per pair or per segment; both empty: the card's everywhere
};

// Per pair of `itf` (its lower_nodes order); empty when the interface has no process_zone_elements.
SegmentStrengths pair_strengths(const model::Model& model, const model::Interface& itf);

// Per interface segment of `itf` (its lower_segments order, one *MAT_138 element each); empty as above.
SegmentStrengths segment_strengths(const model::Model& model, const model::Interface& itf);

// For `check`: "NFLS 27.7-60 MPa, SFLS 35.4-60 MPa over 2880 of 7488 pairs (3 segments in the zone,
// E 8.5 GPa)", or "" when the strengths are the card's.
std::string strengths_text(const SegmentStrengths& s, const model::Interface& itf, const char* items);

}  // namespace plyimpact::interface
