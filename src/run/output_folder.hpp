// A run owns its output folder. Before a run writes anything, the folder is checked: plyimpact's
// result files there (frames <name>_NNNN.vtu, <name>.pvd, history.csv, summary.json, restart.dump)
// must be this scene's, as recorded in the folder's marker file `.plyimpact-run` (scene name and run
// identity, run/restart_dump.hpp). Another scene's results, or results without a marker, are
// refused unless the user asks to replace them; then exactly the recognised result files are
// removed, never a file plyimpact does not recognise (the user's notes, a converted deck's scene
// and mesh). A fresh run of the same scene replaces its own earlier results, so no frame of an
// older, longer run is left beside the new ones; a continued run (--restart) keeps them.
// Temporaries of atomic writes (`.*.tmp.<pid>`) of dead processes are removed on the way in, and
// the run's own on the way out (OutputFolderGuard), also when it ends with an error.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace plyimpact::run {

inline constexpr const char* kFolderMarker = ".plyimpact-run";

struct FolderUse {
  bool continuing = false;  // a run from a restart dump: keeps this scene's results
  bool replace = false;     // removes every plyimpact result the folder holds, whoever wrote it
};

// Creates the folder if needed, checks and cleans it as above and writes the marker.
// @throws InputError naming the folder, whose results it holds and what to do.
void prepare_output_folder(const std::filesystem::path& dir, const std::string& scene_name, std::uint64_t identity,
                           FolderUse use);

// True for a file name plyimpact writes as a run result (any scene name).
bool is_result_file(const std::string& file_name);

// Removes the temporaries this process left in the folder when it goes out of scope.
class OutputFolderGuard {
 public:
  explicit OutputFolderGuard(std::filesystem::path dir) : dir_(std::move(dir)) {}
  ~OutputFolderGuard();
  OutputFolderGuard(const OutputFolderGuard&) = delete;
  OutputFolderGuard& operator=(const OutputFolderGuard&) = delete;

 private:
  std::filesystem::path dir_;
};

}  // namespace plyimpact::run
