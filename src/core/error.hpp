// Error types. InputError: the user's scene or command line is wrong (file:line:col, key path, what
// was found, what is allowed). RunError: the physics stopped (element, time, cause). Both are caught
// once in app/ and printed as one clear line.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace plyimpact {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Builds a message with stream syntax: throw InputError(msg() << "x = " << x);
class msg {
 public:
  template <class T>
  msg& operator<<(const T& v) {
    s_ << v;
    return *this;
  }
  operator std::string() const { return s_.str(); }
  std::string str() const { return s_.str(); }

 private:
  std::ostringstream s_;
};

}  // namespace plyimpact
