// Run state as named blocks of plain values. Everything a run needs to continue (nodal kinematics,
// element stresses and history, contact springs, rigid bodies, energy accumulators) lives in
// objects that offer `void visit_state(StateVisitor&)` and name each of their arrays and scalars
// there, in a fixed order. A restart writer, its reader and a state digest are visitors; a domain
// partitioner can be one later. Keeping the list next to the members it names is what makes a
// forgotten member visible in review, and a restart that differs from the uninterrupted run
// visible in a test.
//
// A reader may change the size of a vector (an eroding contact's surface has another size after a
// rebuild): `block` hands it a resize callback that returns the new data pointer.
#pragma once

#include <cstddef>
#include <string_view>
#include <type_traits>
#include <vector>

namespace plyimpact {

class StateVisitor {
 public:
  using Resize = void* (*)(void* owner, std::size_t count);

  virtual ~StateVisitor() = default;

  // Groups nest (e.g. "solver" > "block 3"); names are unique within their group.
  virtual void enter(std::string_view group) = 0;
  virtual void leave() = 0;

  // A named block of `count` trivially copyable values of `elem_size` bytes at `data`. `resize`
  // (null for fixed-size blocks) lets a reader change the count; it returns the new data pointer.
  virtual void block(std::string_view name, std::size_t elem_size, std::size_t count, void* data, Resize resize,
                     void* owner) = 0;

  template <class T>
  void scalar(std::string_view name, T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "state values must be plain data");
    block(name, sizeof(T), 1, &value, nullptr, nullptr);
  }

  template <class T, class A>
  void array(std::string_view name, std::vector<T, A>& values) {
    static_assert(std::is_trivially_copyable_v<T>, "state values must be plain data");
    block(name, sizeof(T), values.size(), values.data(), &resize_vector<T, A>, &values);
  }

  // A vector whose size the model fixes (nodal and element arrays): a reader refuses another size
  // instead of adopting it.
  template <class T, class A>
  void fixed_array(std::string_view name, std::vector<T, A>& values) {
    static_assert(std::is_trivially_copyable_v<T>, "state values must be plain data");
    block(name, sizeof(T), values.size(), values.data(), nullptr, nullptr);
  }

 private:
  template <class T, class A>
  static void* resize_vector(void* owner, std::size_t count) {
    auto& v = *static_cast<std::vector<T, A>*>(owner);
    v.resize(count);
    return v.data();
  }
};

// Opens a group for the lifetime of the guard.
class StateGroup {
 public:
  StateGroup(StateVisitor& visitor, std::string_view group) : visitor_(visitor) { visitor_.enter(group); }
  ~StateGroup() { visitor_.leave(); }
  StateGroup(const StateGroup&) = delete;
  StateGroup& operator=(const StateGroup&) = delete;

 private:
  StateVisitor& visitor_;
};

}  // namespace plyimpact
