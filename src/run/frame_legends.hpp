// Field data that lets a frame file explain itself when opened alone: the unit system, the part
// names behind part_id, the rigid bodies behind rigid_body, and notes on how to read the arrays.
// Conventions (docs/outputs.md): a legend is a string array `legend_<array>` with one entry
// "<value>: <meaning>" per value; `notes` holds sentences; each array's unit is in `units`
// (written by output/vtu_writer from Field::unit).
#pragma once

#include "model/model.hpp"
#include "output/frame.hpp"

namespace plyimpact::run {

// True for the blocks written in the bodies frame (deformable parts); the others are rigid bodies,
// written in the rigid frame.
inline bool in_bodies_frame(const model::ElementBlock& block) { return !block.rigid; }

// The unit system, legend_part_id and notes of the bodies frame (appended to frame.field_strings).
void add_frame_description(const model::Model& model, output::Frame& frame);

// The unit system, legend_part_id, legend_rigid_body and notes of the rigid frame.
void add_rigid_description(const model::Model& model, output::Frame& frame);

}  // namespace plyimpact::run
