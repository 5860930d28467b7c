// Atomic file replacement: write to a temporary file in the target's directory, then rename() it
// onto the target. A reader (ParaView polling a running job, a post-processing script) therefore
// sees either the previous complete file or the new complete one, never a half-written file, and a
// crash mid-write leaves the old output intact. rename() is only atomic within one file system,
// which is why the temporary lives next to the target and not in /tmp.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace plyimpact::output {

/// Calls `writer(tmp)` to produce the file at the temporary path `tmp` (".<name>.tmp.<pid>" in the
/// same directory as `path`; it already exists, empty, when `writer` is called), then renames it
/// onto `path`. If `writer` throws or any step fails, the temporary is removed, `path` is left
/// untouched, and plyimpact::RunError is thrown naming `path` and the OS reason.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path& tmp)>& writer);

/// Atomically replaces `path` with `content` (byte for byte), fsync()ed before the rename so the
/// new content is on disk before the old file disappears. Throws plyimpact::RunError on failure.
void write_text_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace plyimpact::output
