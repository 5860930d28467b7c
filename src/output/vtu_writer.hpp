// Writes one output Frame as a VTK XML unstructured grid (.vtu): hex8 cells, double point
// coordinates, each Field as a double array with named components, IntFields as int32 arrays, and
// a "TimeValue" field-data entry so ParaView shows the time even when the file is opened alone.
// Binary appended raw data with UInt64 block headers: exact doubles, no 4 GB limit (toolchain V6),
// fastest to write. The file is replaced atomically (atomic_file.hpp).
#pragma once

#include <filesystem>

#include "output/frame.hpp"

namespace plyimpact::output {

struct WriteOptions {
  // zlib trades write time for roughly 2-4x smaller files; off by default because frames are
  // written from inside the time loop.
  bool compress = false;
};

/// Validates `frame` (array sizes, connectivity range, unique non-empty field names) and writes it
/// to `path` atomically. Throws plyimpact::RunError naming the field or the path on any problem;
/// on failure no file and no temporary is left behind and an existing `path` is untouched.
void write_vtu(const Frame& frame, const std::filesystem::path& path,
               const WriteOptions& options = {});

}  // namespace plyimpact::output
