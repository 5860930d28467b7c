// The penalty contact's acceptance rules (docs/theory.md section 10): which segment of the search's
// candidates a contact node is in contact with in this pass, given its spring of the last pass.
// A node penetrates a segment when it projects onto it (MAXPAR) with its own surface facing the
// segment and its gap g = n . (x_s - x_c) - offset lies in (-depth, 0), where depth is
//   - the full release depth on the segment of the last pass,
//   - its depth at the last pass plus the one-step catch depth on that segment's neighbours,
//   - the one-step catch depth (what relative motion can have crossed in one step) elsewhere,
//   - the full release depth in the pass after an eroding rebuild for a new node or segment
//     (an exposure, kept as an offset by penalty_contact).
// The least penetrated accepted segment wins (ties: the segment of the last pass, then the one
// met first).
#pragma once

#include "contact/geometry.hpp"
#include "contact/segment_search.hpp"
#include "contact/segment_set.hpp"
#include "contact/spring_history.hpp"

namespace plyimpact::contact {

// Segment contact node i penetrates at x, or -1; fills the projection.
// new_contact_depth: deepest penetration accepted for a node that was not in contact at the last
// pass (it can only have crossed the surface by its relative motion in one step; a deeper
// "penetration" is a node beside an edge projecting onto a side face, not a real one).
// v, dt (optional): velocities and step, for the per-segment bound of what a new contact can
// have crossed in the step.
long catch_segment(const SegmentSet& set, SegmentSearch& search, const SpringHistory& springs, std::size_t i,
                   const double* x, Projection& best, double new_contact_depth, const double* v = nullptr,
                   double dt = 0);

}  // namespace plyimpact::contact
