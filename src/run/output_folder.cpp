#include "run/output_folder.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.hpp"
#include "output/atomic_file.hpp"
#include "run/restart_dump.hpp"

namespace plyimpact::run {

namespace fs = std::filesystem;

namespace {

struct Marker {
  bool present = false;
  std::string scene;
  std::string identity;  // hex
};

Marker read_marker(const fs::path& dir) {
  Marker m;
  std::ifstream in(dir / kFolderMarker);
  if (!in) return m;
  m.present = true;
  for (std::string line; std::getline(in, line);) {
    const std::size_t space = line.find(' ');
    if (space == std::string::npos) continue;
    const std::string key = line.substr(0, space), value = line.substr(space + 1);
    if (key == "scene") m.scene = value;
    if (key == "run_identity") m.identity = value;
  }
  return m;
}

// "<name>_NNNN.vtu" with at least four digits.
bool is_frame_of(const std::string& file, std::string_view name) {
  const std::string_view f(file);
  if (!f.ends_with(".vtu") || f.size() < name.size() + 9 || !f.starts_with(name)) return false;
  const std::string_view rest = f.substr(name.size(), f.size() - name.size() - 4);
  return rest.size() >= 5 && rest[0] == '_' && rest.substr(1).find_first_not_of("0123456789") == std::string_view::npos;
}

bool is_any_frame(const std::string& file) {
  const std::size_t underscore = file.rfind('_');
  return underscore != std::string::npos && underscore > 0 && is_frame_of(file, std::string_view(file).substr(0, underscore));
}

// Results in the folder: this scene's (when the marker names it) and the others'.
struct Results {
  std::vector<fs::path> own, foreign;
};

// The delamination outputs (run/interface_frame_writer.hpp) carry fixed names, not the scene's.
bool is_interface_output(const std::string& file) {
  return file == "interfaces.pvd" || file == "cscan.vtu" || file == "cscan.png";
}

// interfaces/interfaces_NNNN.vtm and interfaces_NNNN_III.vtu, the interface series' blocks.
bool is_interface_block(const std::string& file) {
  return file.starts_with("interfaces_") && (file.ends_with(".vtm") || file.ends_with(".vtu"));
}

Results list_results(const fs::path& dir, const std::string& scene_name, bool marker_is_ours) {
  Results r;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string file = it->path().filename().string();
    if (file == "interfaces" && it->is_directory()) {
      std::error_code ec2;
      for (fs::directory_iterator b(it->path(), ec2), bend; !ec2 && b != bend; b.increment(ec2))
        if (b->is_regular_file() && is_interface_block(b->path().filename().string()))
          (marker_is_ours ? r.own : r.foreign).push_back(b->path());
      continue;
    }
    if (file == kFolderMarker || !it->is_regular_file() || !is_result_file(file)) continue;
    const bool series = (file.ends_with(".vtu") || file.ends_with(".pvd")) && !is_interface_output(file);  // named after their scene
    const bool named_ours = !series || is_frame_of(file, scene_name) || is_frame_of(file, scene_name + "_rigid") ||
                            file == scene_name + ".pvd";
    (marker_is_ours && named_ours ? r.own : r.foreign).push_back(it->path());
  }
  return r;
}

void remove_files(const std::vector<fs::path>& files) {
  for (const auto& f : files) {
    std::error_code ec;
    fs::remove(f, ec);
    if (ec) throw RunError(msg() << "cannot remove the earlier result '" << f.string() << "': " << ec.message());
  }
}

std::string some_names(const std::vector<fs::path>& files) {
  std::ostringstream s;
  for (std::size_t i = 0; i < files.size() && i < 4; ++i) s << (i ? ", " : "") << files[i].filename().string();
  if (files.size() > 4) s << " and " << files.size() - 4 << " more";
  return s.str();
}

}  // namespace

bool is_result_file(const std::string& file) {
  return file == "history.csv" || file == "summary.json" || file == kDumpFileName || file == kFolderMarker ||
         (file.ends_with(".pvd") && file.size() > 4) || is_any_frame(file) || is_interface_output(file);
}

void prepare_output_folder(const fs::path& dir, const std::string& scene_name, std::uint64_t identity,
                           FolderUse use) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw RunError(msg() << "cannot create the output folder '" << dir.string() << "': " << ec.message());
  output::remove_stale_temporaries(dir);
  const Marker marker = read_marker(dir);
  const bool ours = marker.present && marker.scene == scene_name && marker.identity == identity_text(identity);
  Results results = list_results(dir, scene_name, ours);
  if (use.replace) {
    remove_files(results.own);
    remove_files(results.foreign);
  } else if (!results.foreign.empty()) {
    std::ostringstream whose;
    if (marker.present && marker.scene != scene_name) whose << "of scene '" << marker.scene << "'";
    else if (marker.present && !ours) whose << "of scene '" << marker.scene << "' with other settings or mesh";
    else if (marker.present) whose << "of other scenes";
    else whose << "that this run did not write";
    throw InputError(msg() << dir.string() << ": the output folder holds results " << whose.str() << " ("
                           << some_names(results.foreign) << "); allowed an empty folder or one holding this "
                           << "scene's results: choose another folder with -o, or add --replace to remove those "
                           << "results (only files plyimpact writes are removed)");
  } else if (!use.continuing) {
    remove_files(results.own);  // a new run of this scene: no frame of an earlier run stays
  }
  output::write_text_atomically(dir / kFolderMarker,
                                "program plyimpact\nscene " + scene_name + "\nrun_identity " + identity_text(identity) + "\n");
}

OutputFolderGuard::~OutputFolderGuard() { output::remove_stale_temporaries(dir_); }

}  // namespace plyimpact::run
