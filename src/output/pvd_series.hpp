// A ParaView collection file (.pvd) listing the .vtu frames of a run with their times, so ParaView
// opens the whole run as one time series. VTK 9.1 has no PVD writer (toolchain V5), so this writes
// the ~10 lines of XML itself. The file is rewritten atomically after every frame: a run that stops
// early still leaves a valid series of everything written so far.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace plyimpact::output {

class PvdSeries {
 public:
  /// The series file is `<directory>/<name>.pvd`; `name` must be a plain file stem.
  PvdSeries(std::filesystem::path directory, std::string name);

  /// Records a frame. `vtu_file_name` is relative to the directory (kept relative in the file so
  /// the output folder can be moved); `time` must be finite. Does not touch the disk.
  void add(double time, const std::string& vtu_file_name);

  /// Atomically rewrites `path()` with every frame added so far (times with 17 significant
  /// digits). Throws plyimpact::RunError on I/O failure.
  void write() const;

  std::filesystem::path path() const;
  std::size_t size() const { return frames_.size(); }

 private:
  struct Entry {
    double time;
    std::string file;
  };
  std::filesystem::path directory_;
  std::string name_;
  std::vector<Entry> frames_;
};

}  // namespace plyimpact::output
