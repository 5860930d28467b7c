// Fields of one data line of a keyword card. Fixed columns (LS-DYNA Keyword User's Manual, Vol. I,
// "General card format"): 8 fields of 10 characters in standard format; in long format every field
// narrower than 20 characters is 20 wide (so a card of 8 fields is one 160-character line; as the
// Oasys PRIMER manual, "Long keyword format and large labels", describes it); the few cards with other widths pass their own layout (*NODE: 8+16+16+16+8+8,
// *ELEMENT_SOLID: 8 each, *DEFINE_CURVE points: 20+20). A line with a comma is free format: the
// fields in order, separated by commas. A blank field takes the card's default. Numbers are read
// strictly: "1.5e3" is 1500, "1.5-3" or "12abc" are refused, and an integer field does not take
// "1.0".
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "keyword/deck.hpp"

namespace plyimpact::keyword {

struct FieldSpec {
  std::string name;
  int width = 10;  // standard format; long format widens it to 20 if narrower
};

class Fields {
 public:
  Fields(const Card& card, const DataLine& line, const std::vector<FieldSpec>& layout);

  bool blank(std::string_view name) const;
  std::string text(std::string_view name) const;  // trimmed
  double real(std::string_view name, double fallback) const;
  long integer(std::string_view name, long fallback) const;
  // Refuses a value other than `fallback` (blank passes): the field is not implemented.
  void require_default(std::string_view name, double fallback, std::string_view why = "") const;
  [[noreturn]] void fail(std::string_view name, const std::string& what) const;
  std::string where() const;  // "file:line: *KEYWORD: "

 private:
  int index(std::string_view name) const;
  const Card& card_;
  const DataLine& line_;
  std::vector<std::string> names_;
  std::vector<std::string> values_;
};

// Standard-format layout of n fields of 10 characters with these names.
std::vector<FieldSpec> tens(std::initializer_list<const char*> names);

}  // namespace plyimpact::keyword
