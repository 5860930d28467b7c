// Visitors over the run state (core/state_visitor.hpp):
//   StateWriter  writes every block as a record: its path ("solver/block 0/stress"), element size,
//                count and raw bytes, after a header; the same program reads it back.
//   StateReader  reads the records in the order the visitor meets the blocks and checks each path
//                and element size (a state from another scene or version is refused with both
//                names); a block with a resize callback takes the stored count.
//   StateDigest  a 64-bit FNV-1a hash of paths, sizes and bytes: two runs in the same state have
//                the same digest (restart and thread-determinism tests, regression checks).
//   StateSize    the bytes of all blocks (the memory the run state holds; `check`'s estimate).
// Raw bytes, native byte order: a restart is read on the machine type that wrote it.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "core/state_visitor.hpp"

namespace plyimpact {

// Group stack shared by the visitors: the path of the current group.
class StatePath : public StateVisitor {
 public:
  void enter(std::string_view group) override { groups_.emplace_back(group); }
  void leave() override { groups_.pop_back(); }

 protected:
  std::string path(std::string_view name) const;

 private:
  std::vector<std::string> groups_;
};

class StateWriter : public StatePath {
 public:
  explicit StateWriter(std::ostream& out);
  void block(std::string_view name, std::size_t elem_size, std::size_t count, void* data, Resize resize,
             void* owner) override;

 private:
  std::ostream& out_;
};

class StateReader : public StatePath {
 public:
  // source: named in error messages (the file).
  StateReader(std::istream& in, std::string source);
  void block(std::string_view name, std::size_t elem_size, std::size_t count, void* data, Resize resize,
             void* owner) override;

 private:
  std::istream& in_;
  std::string source_;
};

class StateDigest : public StatePath {
 public:
  void block(std::string_view name, std::size_t elem_size, std::size_t count, void* data, Resize resize,
             void* owner) override;
  std::uint64_t value() const { return hash_; }

 private:
  void add(const void* data, std::size_t bytes);
  std::uint64_t hash_ = 14695981039346656037ull;  // FNV-1a offset basis
};

class StateSize : public StatePath {
 public:
  void block(std::string_view, std::size_t elem_size, std::size_t count, void*, Resize, void*) override {
    bytes_ += elem_size * count;
  }
  std::size_t bytes() const { return bytes_; }

 private:
  std::size_t bytes_ = 0;
};

}  // namespace plyimpact
