// State copy through a StateVisitor (core/state_visitor.hpp): a writer records every named block in
// visiting order, a reader of a second object replays them into it, checking that the names and
// element sizes match and resizing vectors whose count differs — what a restart writer and reader
// do, without a file.
#pragma once

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/state_visitor.hpp"

namespace plyimpact::test {

struct StateBlock {
  std::string name;  // group path and block name
  std::size_t elem_size = 0, count = 0;
  std::vector<char> bytes;
};

class StateRecorder : public StateVisitor {
 public:
  std::vector<StateBlock> blocks;
  void enter(std::string_view group) override { path_.push_back(std::string(group)); }
  void leave() override { path_.pop_back(); }
  void block(std::string_view name, std::size_t elem_size, std::size_t count, void* data, Resize, void*) override {
    StateBlock b{joined(path_) + std::string(name), elem_size, count, {}};
    b.bytes.resize(elem_size * count);
    if (!b.bytes.empty()) std::memcpy(b.bytes.data(), data, b.bytes.size());
    blocks.push_back(std::move(b));
  }

  static std::string joined(const std::vector<std::string>& path) {
    std::string s;
    for (const auto& p : path) s += p + "/";
    return s;
  }

 private:
  std::vector<std::string> path_;
};

class StateReplayer : public StateVisitor {
 public:
  explicit StateReplayer(const std::vector<StateBlock>& blocks) : blocks_(blocks) {}
  std::size_t replayed() const { return next_; }
  void enter(std::string_view group) override { path_.push_back(std::string(group)); }
  void leave() override { path_.pop_back(); }
  void block(std::string_view name, std::size_t elem_size, std::size_t count, void* data, Resize resize,
             void* owner) override {
    if (next_ >= blocks_.size()) throw std::runtime_error("state has no block for " + std::string(name));
    const StateBlock& b = blocks_[next_++];
    const std::string here = StateRecorder::joined(path_) + std::string(name);
    if (b.name != here || b.elem_size != elem_size)
      throw std::runtime_error("state block " + b.name + " read as " + here);
    if (b.count != count) {
      if (!resize) throw std::runtime_error("fixed-size state block " + here + " has another size");
      data = resize(owner, b.count);
    }
    if (!b.bytes.empty()) std::memcpy(data, b.bytes.data(), b.bytes.size());
  }

 private:
  const std::vector<StateBlock>& blocks_;
  std::vector<std::string> path_;
  std::size_t next_ = 0;
};

}  // namespace plyimpact::test
