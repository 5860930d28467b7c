// A ParaView collection file (.pvd) listing the .vtu frames of a run with their times, so ParaView
// opens the whole run as one time series. A time may hold several named parts (files): ParaView's
// PVD reader then makes each part a block of one multiblock data set, named by the part's `name`
// attribute, so the blocks move together through time in one pipeline source. VTK 9.1 has no PVD
// writer (toolchain V5), so this writes the XML itself. The file is rewritten atomically after every frame: a run that stops
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

  /// Records part `part` (0, 1, ...) of the frame at `time`, named `block_name` (the block's name in
  /// ParaView's Multiblock Inspector). Give every time the same parts, in the same order.
  void add(double time, const std::string& vtu_file_name, int part, const std::string& block_name);

  /// Atomically rewrites `path()` with every frame added so far (times with 17 significant
  /// digits). Throws plyimpact::RunError on I/O failure.
  void write() const;

  std::filesystem::path path() const;
  std::size_t size() const { return frames_.size(); }  // entries: every part of every time

 private:
  struct Entry {
    double time;
    std::string file;
    int part = 0;
    std::string name;  // empty: no name attribute
  };
  std::filesystem::path directory_;
  std::string name_;
  std::vector<Entry> frames_;
};

}  // namespace plyimpact::output
