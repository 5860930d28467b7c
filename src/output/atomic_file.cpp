#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <string>
#include <system_error>

#include "core/error.hpp"

namespace plyimpact::output {
namespace fs = std::filesystem;

namespace {

std::string os_reason(int err) { return std::error_code(err, std::generic_category()).message(); }

constexpr std::string_view kTemporaryTag = ".tmp.";

fs::path temporary_path_for(const fs::path& path) {
  // The pid keeps two processes writing into one output directory from clobbering each other's
  // temporary; the leading dot keeps it out of ParaView's file dialog.
  // Appended piecewise: g++ 12 -O3 gives a false -Wrestrict on `"." + std::string` (GCC PR 105329).
  std::string name(1, '.');
  name += path.filename().string();
  name += kTemporaryTag;
  name += std::to_string(static_cast<long>(::getpid()));
  return path.parent_path() / name;
}

// Owns a POSIX descriptor so every early exit closes it.
class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  // close() can report a deferred write error (NFS, quota), so its result matters.
  int close() {
    const int r = ::close(fd_);
    fd_ = -1;
    return r;
  }

 private:
  int fd_;
};

}  // namespace

void write_file_atomically(const fs::path& path,
                           const std::function<void(const fs::path& tmp)>& writer) {
  if (path.filename().empty()) {
    throw RunError(msg() << "cannot write '" << path.string() << "': not a file name");
  }
  const fs::path tmp = temporary_path_for(path);

  // Creating the temporary ourselves first turns "directory missing", "permission denied" or
  // "read-only file system" into a precise errno, whatever library the writer uses afterwards.
  {
    Fd fd(::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666));
    if (fd.get() < 0) {
      const int err = errno;
      throw RunError(msg() << "cannot write '" << path.string() << "': cannot create '"
                           << tmp.string() << "': " << os_reason(err));
    }
  }

  std::error_code ignored;
  try {
    writer(tmp);
  } catch (const std::exception& e) {
    fs::remove(tmp, ignored);
    throw RunError(msg() << "cannot write '" << path.string() << "': " << e.what());
  } catch (...) {
    fs::remove(tmp, ignored);
    throw RunError(msg() << "cannot write '" << path.string() << "': unknown error");
  }

  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ignored);
    throw RunError(msg() << "cannot write '" << path.string() << "': rename from '"
                         << tmp.string() << "' failed: " << ec.message());
  }
}

void write_text_atomically(const fs::path& path, std::string_view content) {
  write_file_atomically(path, [content](const fs::path& tmp) {
    Fd fd(::open(tmp.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC));
    if (fd.get() < 0) {
      throw RunError(msg() << "open '" << tmp.string() << "': " << os_reason(errno));
    }
    const char* data = content.data();
    std::size_t left = content.size();
    while (left > 0) {
      const ssize_t n = ::write(fd.get(), data, left);
      if (n < 0) {
        if (errno == EINTR) continue;
        throw RunError(msg() << "write '" << tmp.string() << "': " << os_reason(errno));
      }
      data += n;
      left -= static_cast<std::size_t>(n);
    }
    if (::fsync(fd.get()) != 0) {
      throw RunError(msg() << "fsync '" << tmp.string() << "': " << os_reason(errno));
    }
    if (fd.close() != 0) {
      throw RunError(msg() << "close '" << tmp.string() << "': " << os_reason(errno));
    }
  });
}

pid_t temporary_owner(const std::string& file_name) {
  const std::size_t tag = file_name.rfind(kTemporaryTag);
  if (file_name.size() < 2 || file_name[0] != '.' || tag == std::string::npos || tag < 2) return -1;
  const std::string digits = file_name.substr(tag + kTemporaryTag.size());
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
  return static_cast<pid_t>(std::stol(digits));
}

std::size_t remove_stale_temporaries(const fs::path& dir) noexcept {
  std::size_t removed = 0;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const pid_t owner = temporary_owner(it->path().filename().string());
    if (owner <= 0) continue;
    // kill(pid, 0) probes a process without signalling it; ESRCH: no such process. EPERM means
    // it exists under another user, whose temporary is not ours to remove.
    const bool dead = owner != ::getpid() && ::kill(owner, 0) != 0 && errno == ESRCH;
    std::error_code ignored;
    if ((owner == ::getpid() || dead) && fs::remove(it->path(), ignored)) ++removed;
  }
  return removed;
}

void AppendingFile::open(const fs::path& path) {
  close();
  path_ = path;
  fd_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) throw RunError(msg() << "cannot append to '" << path.string() << "': " << os_reason(errno));
}

void AppendingFile::append(std::string_view text) {
  struct stat st {};
  if (::fstat(fd_, &st) != 0) throw RunError(msg() << "cannot append to '" << path_.string() << "': " << os_reason(errno));
  const char* data = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      if (::ftruncate(fd_, st.st_size) != 0) {}  // best effort: the file ends at its last whole line
      throw RunError(msg() << "cannot append to '" << path_.string() << "': " << os_reason(err));
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
}

void AppendingFile::close() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

}  // namespace plyimpact::output
