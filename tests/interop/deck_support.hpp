// Test support for the keyword-deck tests: converting a deck text or a deck under tests/data/decks,
// running the converted scene and a YAML scene to their histories, and reading a refusal's note.
#pragma once

#include <filesystem>
#include <string>

#include "config/scene_loader.hpp"
#include "interop_support.hpp"
#include "keyword/converter.hpp"

namespace plyimpact::test {

inline const std::filesystem::path kDecks = std::filesystem::path(PLYIMPACT_SOURCE_DIR) / "tests" / "data" / "decks";

inline keyword::Conversion convert_text(const std::filesystem::path& dir, const std::string& deck,
                                        const std::string& units = "SI") {
  write_file(dir / "d.k", deck);
  return keyword::convert_deck(keyword::read_deck((dir / "d.k").string()), {units, "d.msh"});
}

// The history of the deck tests/data/decks/<deck>, converted into dir.
inline std::string deck_history(const std::string& deck, const std::filesystem::path& dir) {
  keyword::convert_deck_file((kDecks / deck).string(), "SI", dir / "deck.yaml");
  return run_history(config::load_scene((dir / "deck.yaml").string()), dir / "deck_run");
}

inline std::string yaml_history(const std::string& yaml, const std::filesystem::path& dir) {
  return run_history(config::load_scene_from_string(yaml, (dir / "yaml.yaml").string()), dir / "yaml_run");
}

// The note of the refusal of `keyword`, or "" when it was not refused.
inline std::string refusal(const keyword::Conversion& c, const std::string& keyword) {
  for (const auto& e : c.coverage)
    if (e.keyword == keyword && e.status == "refused") return e.note;
  return "";
}

}  // namespace plyimpact::test
