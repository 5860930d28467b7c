// Materials of the model from the scene's cards: the one place where a card (config/) becomes the
// constants of a material routine (material/). The reader has checked every field on its own
// (ranges, combinations, unsupported options); what needs the constants together is checked here,
// once, with the card's file:line:col (the positive definiteness of an orthotropic compliance).
#pragma once

#include "config/scene.hpp"
#include "material/composite_damage.hpp"
#include "material/elastic.hpp"
#include "material/johnson_cook.hpp"
#include "model/model.hpp"

namespace plyimpact::model {

Material make_material(const config::MaterialSpec& spec);

material::MaterialAxes material_axes_of(const config::MaterialAxes& axes);

// *MAT_015 (with its EOS) and *MAT_098 constants from cards the reader accepted.
material::JohnsonCookParams johnson_cook_params(const config::MatJohnsonCook& card);
material::JohnsonCookParams simplified_johnson_cook_params(const config::MatSimplifiedJohnsonCook& card);

// Stiffness of a *MAT_002 card in its material axes. Throws InputError (naming `where`) when the
// compliance is not positive definite, with the offending combination and a hint about the PRBA
// convention.
material::Stiffness6 orthotropic_stiffness(const config::MatOrthotropicElastic& card,
                                           const config::SourceLocation& where);

// *MAT_054/055 constants from a card the reader accepted. Throws InputError like
// orthotropic_stiffness for its elastic constants.
material::CompositeDamageParams composite_damage_params(const config::MatCompositeDamage& card,
                                                        const config::SourceLocation& where);

}  // namespace plyimpact::model
