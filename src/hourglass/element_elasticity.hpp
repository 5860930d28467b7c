// What the moduli of the stiffness (IHQ 4/5) and assumed-strain (IHQ 6) hourglass control start
// from: the material's undamaged stiffness in its own axes, and the element frame's axes expressed
// in those axes. The hourglass modes live in the element frame (element_frame: the orthonormalised
// centre-Jacobian columns) and a ply's material axes turn with it, so both are taken once, from the
// reference geometry. Undamaged constants, as LS-DYNA takes the elastic constants of the card.
#pragma once

#include <cstddef>

#include "material/elastic.hpp"
#include "model/model.hpp"

namespace plyimpact::hourglass {

// Voigt stiffness (xx yy zz xy yz zx, engineering shear) in material axes; an isotropic one for
// materials without axes. Throws std::logic_error for a material without elastic constants (rigid).
material::Stiffness6 stiffness_in_material_axes(const model::Material& mat);

// Rows of n: the element frame's axes x', y', z' of element e at t = 0 in material axes (global
// axes for a material without axes).
void element_axes_in_material_axes(const model::Model& model, const model::ElementBlock& block, std::size_t e,
                                   double (&n)[3][3]);

}  // namespace plyimpact::hourglass
