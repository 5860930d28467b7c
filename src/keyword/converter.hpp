// LS-DYNA keyword deck -> plyimpact scene. The deck's cards map onto the scene's YAML sections
// (written with `units:` as the user states them, values unconverted, so the scene loader does the
// one conversion to SI) plus a mesh (nodes and hexahedra, SI) that goes to a gmsh .msh beside the
// YAML (`mesh: {file, length_unit: m}`), with the deck's node sets as physical point groups.
// Strict: a keyword, option or non-default field value this code does not implement is refused
// with file:line and its name; nothing is dropped silently. Every card gets a coverage entry:
// used (converted as it is), mapped (turned into another form of the scene, said how), refused.
// Names in the scene: parts part_<PID>, materials mat_<MID>, sections sec_<SECID>[_hg<HGID>],
// node sets set_<SID>, contacts contact_<n>, rigid walls wall_<n> (n: 1-based order in the deck).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "config/scene.hpp"
#include "keyword/deck.hpp"
#include "mesh/mesh.hpp"

namespace plyimpact::keyword {

struct CoverageEntry {
  std::string file;
  int line = 0;
  std::string keyword;
  std::string status;  // "used", "mapped" or "refused"
  std::string note;    // how it was mapped, or why it was refused (with the field)
};

struct Conversion {
  std::string yaml;                      // the scene; its mesh is mesh_file_name
  mesh::Mesh mesh;                       // coordinates in m
  std::vector<config::PartSpec> parts;   // names and ids of the mesh's parts (element_part indexes them)
  std::vector<CoverageEntry> coverage;   // one entry per card, in deck order
  bool refused() const;
};

struct ConvertOptions {
  std::string unit_system;      // the deck's consistent units, e.g. "mm-t-s-MPa" (keyword files carry none)
  std::string mesh_file_name;   // written into the YAML, relative to the YAML's folder
};

/// Card-level problems become "refused" coverage entries; never throws for them.
/// @throws InputError for an unknown unit system.
Conversion convert_deck(const Deck& deck, const ConvertOptions& options);

/// The coverage as an aligned table (file:line, keyword, status, note).
std::string coverage_table(const Conversion& c);

/// "file:line: *KEYWORD: reason" lines of the refused cards.
std::string refusals(const Conversion& c);

/// Reads, converts and writes <yaml_path> and the .msh beside it (same stem). Refusals throw
/// InputError listing them all. Returns the conversion (for its coverage).
Conversion convert_deck_file(const std::string& deck_path, const std::string& unit_system,
                             const std::filesystem::path& yaml_path);

}  // namespace plyimpact::keyword
