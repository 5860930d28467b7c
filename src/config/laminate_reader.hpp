// Internal to config/: readers for the `laminate:` and `impactor:` scene sections (issue 3). They
// fill Scene::laminate / Scene::impactor and expand them into ordinary scene entries the model
// builder already understands: one part per ply (or sub-laminate block), Generated node sets for
// supports and symmetry planes with their fixed conditions, the impactor's part and velocity.
#pragma once

#include "config/scene.hpp"
#include "config/yaml_reader.hpp"

namespace plyimpact::config::detail {

// Needs scene.materials, scene.sections and any user parts already read.
void read_laminate(const Reader& r, Scene& scene);
// Needs scene.laminate (if any) already read: the impact point comes from it.
void read_impactor(const Reader& r, Scene& scene);
// The tiebreak card keys (OPTION, NFLS, SFLS, PARAM, ERATEN, ERATES, CN, CT2CN, FS) of `r` on top of
// `law`, as the laminate's interfaces read them; a tiebreak contact reads the same card.
void read_tiebreak_law_keys(const Reader& r, cohesive::TractionLawParams& law);

}  // namespace plyimpact::config::detail
