// write_file_atomically / write_text_atomically: the target is either the old or the new file,
// failures name the path and the OS reason, and no temporary is ever left behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "output/atomic_file.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using plyimpact::RunError;
using plyimpact::output::write_file_atomically;
using plyimpact::output::write_text_atomically;

using plyimpact::test::ScratchDir;
using plyimpact::test::slurp;

namespace {

}  // namespace

TEST(AtomicFile, WritesTextExactly) {
  ScratchDir dir;
  const fs::path target = dir.path() / "a.txt";
  const std::string content("line 1\nline 2\0binary\n", 21);
  write_text_atomically(target, content);
  EXPECT_EQ(slurp(target), content);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, ReplacesExistingFileAndLeavesNoTemporary) {
  ScratchDir dir;
  const fs::path target = dir.path() / "a.txt";
  write_text_atomically(target, "old contents that are longer than the new ones\n");
  write_text_atomically(target, "new\n");
  EXPECT_EQ(slurp(target), "new\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, TemporaryIsNextToTargetAndHidden) {
  ScratchDir dir;
  const fs::path target = dir.path() / "frame.vtu";
  fs::path seen;
  write_file_atomically(target, [&](const fs::path& tmp) {
    seen = tmp;
    EXPECT_TRUE(fs::exists(tmp));  // created before the writer runs
    std::ofstream(tmp) << "x";
  });
  // Same directory, so rename() stays on one file system and is atomic.
  EXPECT_EQ(seen.parent_path(), target.parent_path());
  EXPECT_EQ(seen.filename().string().front(), '.');
  EXPECT_FALSE(fs::exists(seen));
  EXPECT_EQ(slurp(target), "x");
}

TEST(AtomicFile, MissingDirectoryThrowsNamingPathAndReason) {
  ScratchDir dir;
  const fs::path target = dir.path() / "no_such_dir" / "a.txt";
  try {
    write_text_atomically(target, "x");
    FAIL() << "expected RunError";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(target.string()), std::string::npos) << what;
    EXPECT_NE(what.find("No such file or directory"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(target));
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, WriterFailureKeepsOldFileAndRemovesTemporary) {
  ScratchDir dir;
  const fs::path target = dir.path() / "a.txt";
  write_text_atomically(target, "old\n");
  fs::path seen;
  try {
    write_file_atomically(target, [&](const fs::path& tmp) {
      seen = tmp;
      std::ofstream(tmp) << "half a fi";
      throw std::runtime_error("disk on fire");
    });
    FAIL() << "expected RunError";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(target.string()), std::string::npos) << what;
    EXPECT_NE(what.find("disk on fire"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(seen));
  EXPECT_EQ(slurp(target), "old\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, RenameOntoDirectoryFailsCleanly) {
  ScratchDir dir;
  const fs::path target = dir.path() / "occupied";
  fs::create_directories(target / "child");  // a non-empty directory cannot be replaced
  EXPECT_THROW(write_text_atomically(target, "x"), RunError);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"occupied"});
  EXPECT_TRUE(fs::is_directory(target / "child"));
}
