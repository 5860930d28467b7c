#include "app/convert_command.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>

#include "core/error.hpp"
#include "keyword/converter.hpp"

namespace plyimpact::app {
namespace {

namespace fs = std::filesystem;

bool is_deck(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".k" || ext == ".key" || ext == ".dyn";
}

constexpr const char* kDeckUsage =
    "usage: plyimpact convert DECK.k --units UNITS [-o SCENE.yaml] [--coverage]\n"
    "       plyimpact run DECK.k --units UNITS [-o DIR]\n"
    "UNITS: the deck's consistent unit system (SI, mm-t-s-MPa, mm-kg-ms-GPa); keyword files carry none\n";

}  // namespace

bool is_keyword_command(const std::vector<std::string>& args) {
  return !args.empty() && (args[0] == "convert" || ((args[0] == "run" || args[0] == "check") && args.size() >= 2 && is_deck(args[1])));
}

int keyword_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, const RunScene& run) {
  if (args.size() < 2) {
    err << "plyimpact: missing keyword deck\n" << kDeckUsage;
    return 64;
  }
  std::string units, output;
  bool coverage = false;
  for (std::size_t i = 2; i < args.size(); ++i) {
    if (args[i] == "--units" && i + 1 < args.size()) units = args[++i];
    else if ((args[i] == "-o" || args[i] == "--output") && i + 1 < args.size()) output = args[++i];
    else if (args[i] == "--coverage" && args[0] == "convert") coverage = true;
    else {
      err << "plyimpact: unexpected argument '" << args[i] << "'\n" << kDeckUsage;
      return 64;
    }
  }
  if (args[0] == "check") {
    err << "plyimpact: check takes a YAML scene; convert the deck first\n" << kDeckUsage;
    return 64;
  }
  if (units.empty()) {
    err << "plyimpact: " << args[1] << ": a keyword deck needs --units (keyword files carry no unit system)\n" << kDeckUsage;
    return 64;
  }
  const std::string& deck = args[1];
  const std::string stem = fs::path(deck).stem().string();
  if (args[0] == "run") {
    const fs::path dir = output.empty() ? fs::path("results") / stem : fs::path(output);
    const fs::path scene = dir / (stem + ".yaml");
    keyword::convert_deck_file(deck, units, scene);
    out << "converted " << deck << " (" << units << ") to " << scene.string() << "\n";
    return run(scene.string(), dir.string(), out);
  }
  const fs::path scene = output.empty() ? fs::path(deck).parent_path() / (stem + ".yaml") : fs::path(output);
  if (coverage) {
    const keyword::Conversion c = keyword::convert_deck(keyword::read_deck(deck), {units, scene.stem().string() + ".msh"});
    out << keyword::coverage_table(c);
    if (c.refused()) return 1;
  }
  keyword::convert_deck_file(deck, units, scene);
  out << "wrote " << scene.string() << " and " << (scene.parent_path() / (scene.stem().string() + ".msh")).string() << "\n";
  return 0;
}

}  // namespace plyimpact::app
