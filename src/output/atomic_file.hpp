// Atomic file replacement: write to a temporary file in the target's directory, then rename() it
// onto the target. A reader (ParaView polling a running job, a post-processing script) therefore
// sees either the previous complete file or the new complete one, never a half-written file, and a
// crash mid-write leaves the old output intact. rename() is only atomic within one file system,
// which is why the temporary lives next to the target and not in /tmp.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>
#include <sys/types.h>

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

/// The process id in a temporary's name (".<name>.tmp.<pid>"), or -1 when `file_name` is not one.
pid_t temporary_owner(const std::string& file_name);

/// Removes, in `dir`, the temporaries of this process (left by a writer that did not finish, e.g.
/// an exception out of a library writer) and those of processes that no longer exist (a run
/// killed mid-write). Another live process's temporaries are its own and are left alone. Returns
/// the number removed; never throws (a cleanup must not hide the error it follows).
std::size_t remove_stale_temporaries(const std::filesystem::path& dir) noexcept;

/// A file that grows by whole records (history rows) between atomic rewrites: each append() is
/// one write() of complete lines at the end of the file, and a write that fails part-way is cut
/// back, so a reader never sees a torn line except for the instant of one write(). Throws
/// plyimpact::RunError naming the file on failure. Reopen after the file was atomically replaced
/// (rename() leaves an open descriptor on the old file).
class AppendingFile {
 public:
  AppendingFile() = default;
  ~AppendingFile() { close(); }
  AppendingFile(const AppendingFile&) = delete;
  AppendingFile& operator=(const AppendingFile&) = delete;

  void open(const std::filesystem::path& path);
  void append(std::string_view text);
  void close() noexcept;
  bool is_open() const { return fd_ >= 0; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace plyimpact::output
