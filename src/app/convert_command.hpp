// Keyword decks on the command line:
//   plyimpact convert DECK.k --units U [-o SCENE.yaml] [--coverage]
//       writes SCENE.yaml (default: beside the deck, same stem) and SCENE.msh beside it;
//       --coverage prints every card as used, mapped or refused (exit 1 if any is refused).
//   plyimpact run DECK.k --units U [-o DIR]
//       converts into DIR (default results/<deck>) as <deck>.yaml + <deck>.msh and runs that scene.
// The deck's unit system must be stated (keyword files carry none).
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace plyimpact::app {

using RunScene = std::function<int(const std::string& scene, const std::string& out_dir, std::ostream& out)>;

// True for "convert ..." and for "run"/"check" of a file ending .k, .key or .dyn.
bool is_keyword_command(const std::vector<std::string>& args);

/// @throws InputError (as the other commands: the caller prints it).
int keyword_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, const RunScene& run);

}  // namespace plyimpact::app
