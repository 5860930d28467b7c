#include "run/frame_legends.hpp"

#include <string>

namespace plyimpact::run {

namespace {

const char* kUnitSystem = "SI: m, kg, s, N, Pa, J; angles in degrees (whatever units the scene was given in)";

output::StringField part_legend(const model::Model& model) {
  output::StringField legend{"legend_part_id", {}};
  for (const auto& p : model.parts) legend.values.push_back(std::to_string(p.id) + ": " + p.name);
  return legend;
}

void add_common(const model::Model& model, output::Frame& frame) {
  frame.field_strings.push_back({"unit_system", {kUnitSystem}});
  frame.field_strings.push_back(part_legend(model));
}

// Appends to the `notes` entry, creating it if needed (the material fields add their own notes).
void add_notes(output::Frame& frame, std::initializer_list<std::string> notes) {
  for (auto& f : frame.field_strings)
    if (f.name == "notes") {
      f.values.insert(f.values.end(), notes);
      return;
    }
  frame.field_strings.push_back({"notes", notes});
}

}  // namespace

void add_frame_description(const model::Model& model, output::Frame& frame) {
  add_common(model, frame);
  add_notes(frame,
            {"points are the deformed positions at TimeValue: do not Warp By Vector with displacement",
             "node_id: model node number (1-based); nodes used by no element of this file are left out",
             "cell arrays: one value per element; ELFORM 2 elements give the mean of their eight points "
             "(the mat054_* fields: the most critical point)",
             "stress, strain: global axes, components xx yy zz xy yz zx, tensor shear; strain is the "
             "logarithmic (Hencky) strain. *_material: the same in the current material axes (aa bb cc ab bc ca)",
             "ply_index: laminate ply counted from the bottom (1-based), 0 outside a laminate; ply_angle: "
             "fibre (a) axis at t = 0 in the x-y plane from +x, in (-90, 90], NaN for materials without axes"});
}

void add_rigid_description(const model::Model& model, output::Frame& frame) {
  add_common(model, frame);
  output::StringField bodies{"legend_rigid_body", {}};
  for (std::size_t r = 0; r < model.rigid_bodies.size(); ++r)
    bodies.values.push_back(std::to_string(r + 1) + ": " + model.rigid_bodies[r].name);
  frame.field_strings.push_back(std::move(bodies));
  add_notes(frame, {"rigid bodies at their current position: hexahedra of *MAT_020 parts and the meshed rigid "
                    "impactor's surface (quadrilaterals, part_id 0 and element_id 0)",
                    "node_id: model node number (1-based)"});
}

}  // namespace plyimpact::run
