// Writes one output Frame as a VTK XML unstructured grid (.vtu): hexahedra then quadrilaterals,
// double point coordinates, each Field as a double array with named components, IntFields as int32
// arrays, and field data: "TimeValue" (so ParaView shows the time even when the file is opened
// alone), "Cycle", every StringField, and "units" ("<array>: <unit>" for each array that names its
// unit). Binary appended raw data with UInt64 block headers: exact doubles, no 4 GB limit
// (toolchain V6). The file is replaced atomically (atomic_file.hpp).
#pragma once

#include <filesystem>

#include "output/frame.hpp"

namespace plyimpact::output {

// Block compression of the appended data (lossless; VTK's readers and ParaView read all three).
enum class Compression { none, zlib, lz4 };

// Uncompressed unless asked: the run's frames take the scene's output.compression (zlib by default,
// docs/outputs.md has the measured sizes and times); mesh exports stay plain.
struct WriteOptions {
  Compression compression = Compression::none;
  bool compress = false;  // shorthand for compression = zlib
};

/// Validates `frame` (array sizes, connectivity range, unique non-empty field names) and writes it
/// to `path` atomically. Throws plyimpact::RunError naming the field or the path on any problem;
/// on failure no file and no temporary is left behind and an existing `path` is untouched.
void write_vtu(const Frame& frame, const std::filesystem::path& path,
               const WriteOptions& options = {});

}  // namespace plyimpact::output
