// The gmsh scripts of geo/ (impactor shapes), compiled in; see src/mesh/CMakeLists.txt.
#pragma once

#include <string_view>

namespace plyimpact::mesh {

/// Text of geo/<name>.geo, or an empty view if there is no such script.
std::string_view geo_script(std::string_view name);

}  // namespace plyimpact::mesh
