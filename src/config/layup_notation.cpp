// Recursive-descent parser for laminate notation; see layup_notation.hpp for the grammar.
#include "config/layup_notation.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace plyimpact::config {
namespace {

constexpr const char* kAllowed =
    "laminate notation such as [0/45/-45/90]2s, [0_2/90]s, [±45/0]s or [0/90~]s (middle ply ~)";
constexpr int kMaxPlies = 100000;  // guards against [0]999999999s

class Parser {
 public:
  explicit Parser(const std::string& text) : s_(text) {}

  std::vector<double> run() {
    skip();
    if (pos_ >= s_.size()) fail("empty stacking sequence");
    if (s_[pos_] != '[') fail("a laminate starts with '['");
    std::vector<double> out = group();
    skip();
    if (pos_ < s_.size()) fail(std::string("unexpected '") + s_[pos_] + "' after the closing ']'");
    return out;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw LayupNotationError(pos_, what, kAllowed); }

  void skip() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool eat(const std::string& token) {
    skip();
    if (s_.compare(pos_, token.size(), token) != 0) return false;
    pos_ += token.size();
    return true;
  }
  bool digit_next() {
    skip();
    return pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]));
  }

  int count() {
    skip();
    const std::size_t start = pos_;
    long n = 0;
    while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) {
      n = n * 10 + (s_[pos_++] - '0');
      if (n > kMaxPlies) break;
    }
    if (pos_ == start) fail("expected a repeat count (an integer >= 1)");
    if (n < 1 || n > kMaxPlies) {
      pos_ = start;
      fail("repeat count must be between 1 and 100000");
    }
    return int(n);
  }

  static void repeat(std::vector<double>& v, int n) {
    const std::vector<double> once = v;
    for (int i = 1; i < n; ++i) v.insert(v.end(), once.begin(), once.end());
  }

  void check_size(const std::vector<double>& v) const {
    if (v.size() > std::size_t(kMaxPlies)) fail("more than 100000 plies");
  }

  std::vector<double> group() {
    eat("[");
    std::vector<double> out;
    std::size_t middle_ply = 0;  // 1 + index of a '~' (barred) ply, 0 = none
    for (;;) {
      std::vector<double> it = item(middle_ply, out.size());
      out.insert(out.end(), it.begin(), it.end());
      check_size(out);
      if (eat("/")) continue;
      if (eat("]")) break;
      skip();
      fail(pos_ >= s_.size() ? "missing closing ']'" : std::string("unexpected '") + s_[pos_] + "' (expected '/' or ']')");
    }
    const std::size_t count_at = pos_;
    if (eat("_") || digit_next()) {
      if (middle_ply) {
        pos_ = count_at;
        fail("a group with a middle ply (~) cannot be repeated");
      }
      repeat(out, count());
    }
    check_size(out);
    skip();
    const std::size_t s_at = pos_;
    if (eat("s") || eat("S")) {
      // The barred middle ply (the last one) appears once.
      const std::size_t n = out.size() - (middle_ply ? 1 : 0);
      out.reserve(out.size() + n);
      for (std::size_t i = n; i-- > 0;) out.push_back(out[i]);
    } else if (middle_ply) {
      pos_ = s_at;
      fail("a middle ply (~) needs a symmetric group ']s'");
    }
    check_size(out);
    return out;
  }

  std::vector<double> item(std::size_t& middle_ply, std::size_t plies_before) {
    skip();
    std::vector<double> out;
    if (pos_ < s_.size() && s_[pos_] == '[') {
      out = group();
    } else {
      out = angle();
    }
    if (eat("_")) repeat(out, count());
    if (eat("~")) {
      if (out.size() != 1) fail("only a single ply can be the middle ply (~)");
      skip();
      if (pos_ >= s_.size() || s_[pos_] != ']') fail("the middle ply (~) must be the last ply of its group");
      middle_ply = plies_before + 1;
    }
    return out;
  }

  std::vector<double> angle() {
    skip();
    const std::size_t start = pos_;
    int sign = 0;  // 0 plain, 1 ±, -1 ∓
    if (eat("±") || eat("+-") || eat("+/-")) sign = 1;
    else if (eat("∓") || eat("-+")) sign = -1;
    skip();
    const char* begin = s_.c_str() + pos_;
    char* end = nullptr;
    if (pos_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '+' ||
                             s_[pos_] == '-' || s_[pos_] == '.'))
      ;
    else {
      pos_ = start;
      fail(pos_ >= s_.size() ? "unexpected end (expected a ply angle)" : "expected a ply angle in degrees");
    }
    const double a = std::strtod(begin, &end);
    if (end == begin) fail("expected a ply angle in degrees");
    // strtod would read "2e1" and "inf"; only plain decimals are angles here.
    for (const char* c = begin; c < end; ++c)
      if (!(std::isdigit(static_cast<unsigned char>(*c)) || *c == '.' || *c == '+' || *c == '-'))
        fail("a ply angle is a plain decimal number of degrees");
    if (sign != 0 && (*begin == '+' || *begin == '-')) fail("a sign after ± is not allowed");
    if (!(std::abs(a) <= 180.0)) fail("ply angle must be within [-180, 180] degrees");
    pos_ += std::size_t(end - begin);
    if (sign == 1) return {a, -a};
    if (sign == -1) return {-a, a};
    return {a};
  }

  const std::string& s_;
  std::size_t pos_ = 0;
};

}  // namespace

std::vector<double> expand_layup(const std::string& notation) { return Parser(notation).run(); }

}  // namespace plyimpact::config
