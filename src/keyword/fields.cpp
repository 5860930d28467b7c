#include "keyword/fields.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/units.hpp"

namespace plyimpact::keyword {
namespace {

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return "";
  return std::string(s.substr(b, s.find_last_not_of(" \t\r") - b + 1));
}

}  // namespace

std::vector<FieldSpec> tens(std::initializer_list<const char*> names) {
  std::vector<FieldSpec> out;
  for (const char* n : names) out.push_back({n, 10});
  return out;
}

Fields::Fields(const Card& card, const DataLine& line, const std::vector<FieldSpec>& layout)
    : card_(card), line_(line) {
  for (const auto& f : layout) names_.push_back(f.name);
  const std::string& t = line.text;
  if (t.find(',') != std::string::npos) {
    std::size_t start = 0;
    while (true) {
      const auto comma = t.find(',', start);
      values_.push_back(trim(std::string_view(t).substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    while (values_.size() > layout.size() && values_.back().empty()) values_.pop_back();
    if (values_.size() > layout.size())
      throw InputError(msg() << where() << values_.size() << " comma-separated fields; allowed: at most "
                             << layout.size() << " (" << names_.front() << " ... " << names_.back() << ")");
  } else {
    std::size_t col = 0;
    for (const auto& f : layout) {
      const std::size_t w = card.long_format ? std::max<std::size_t>(20, std::size_t(f.width)) : std::size_t(f.width);
      values_.push_back(col < t.size() ? trim(std::string_view(t).substr(col, w)) : "");
      col += w;
    }
    if (col < t.size() && !trim(std::string_view(t).substr(col)).empty())
      throw InputError(msg() << where() << "text beyond the last field (" << names_.back() << ", column " << col
                             << "): '" << trim(std::string_view(t).substr(col)) << "'; allowed: "
                             << layout.size() << " fields" << (card.long_format ? " of (at least) 20 characters" : ""));
  }
  values_.resize(layout.size());
}

std::string Fields::where() const { return keyword::where(card_, line_); }

int Fields::index(std::string_view name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) throw std::logic_error("keyword field " + std::string(name) + " not in the layout");
  return int(it - names_.begin());
}

void Fields::fail(std::string_view name, const std::string& what) const {
  throw InputError(msg() << where() << "field " << name << " = '" << values_[std::size_t(index(name))] << "': " << what);
}

bool Fields::blank(std::string_view name) const { return values_[std::size_t(index(name))].empty(); }

std::string Fields::text(std::string_view name) const { return values_[std::size_t(index(name))]; }

double Fields::real(std::string_view name, double fallback) const {
  const std::string& v = values_[std::size_t(index(name))];
  if (v.empty()) return fallback;
  try {
    return units::parse_number(v);
  } catch (const units::UnitError& e) {
    fail(name, "not a number; allowed: a number such as 1.5, -2e-3 or 7.85E+03");
  }
}

long Fields::integer(std::string_view name, long fallback) const {
  const std::string& v = values_[std::size_t(index(name))];
  if (v.empty()) return fallback;
  try {
    return units::parse_integer(v);
  } catch (const units::UnitError& e) {
    fail(name, "not an integer; allowed: an integer such as 3");
  }
}

void Fields::require_default(std::string_view name, double fallback, std::string_view why) const {
  if (blank(name)) return;
  const double v = real(name, fallback);
  if (v == fallback) return;
  std::ostringstream d;
  d << fallback;
  fail(name, "not supported" + (why.empty() ? std::string() : " (" + std::string(why) + ")") +
                 "; allowed: blank or " + d.str());
}

}  // namespace plyimpact::keyword
