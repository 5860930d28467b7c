#include "keyword/deck.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace plyimpact::keyword {
namespace {

namespace fs = std::filesystem;

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

struct Reader {
  Deck& deck;
  bool long_deck = false;
  std::vector<std::string> open_files;  // include chain, for cycles

  [[noreturn]] void fail(const std::string& file, int line, const std::string& what) {
    throw InputError(msg() << file << ":" << line << ": " << what);
  }

  // "*KEYWORD LONG=Y" / "*KEYWORD 100000000" (memory size: no meaning here).
  void keyword_options(const std::string& rest, const std::string& file, int line) {
    std::string token;
    std::istringstream in(rest);
    while (in >> token) {
      const std::string t = upper(token);
      if (t == "LONG=Y") long_deck = true;
      else if (t == "LONG=S") long_deck = false;
      else if (!t.empty() && std::all_of(t.begin(), t.end(), ::isdigit)) continue;
      else fail(file, line, "*KEYWORD: option '" + token + "' is not supported; allowed: LONG=Y, LONG=S or a memory size");
    }
  }

  void read_file(const std::string& path, const std::string& from_file, int from_line) {
    const std::string canonical = fs::weakly_canonical(path).string();
    if (std::find(open_files.begin(), open_files.end(), canonical) != open_files.end())
      fail(from_file, from_line, "*INCLUDE: " + path + " includes itself (directly or through other files)");
    std::ifstream in(path, std::ios::binary);
    if (!in.is_open() || fs::is_directory(path)) {
      if (from_file.empty()) throw InputError(msg() << path << ": cannot open the keyword deck");
      fail(from_file, from_line, "*INCLUDE: cannot open " + path);
    }
    open_files.push_back(canonical);
    std::string text;
    int line_no = 0;
    Card* open = nullptr;
    std::vector<std::pair<std::string, int>> includes;  // read after their card is complete
    auto flush_includes = [&] {
      for (const auto& [file, line] : includes) read_file(file, path, line);
      includes.clear();
    };
    while (std::getline(in, text)) {
      ++line_no;
      if (!text.empty() && text.back() == '\r') text.pop_back();
      if (!text.empty() && text[0] == '$') continue;
      if (!text.empty() && text[0] == '*') {
        flush_includes();
        std::string head = trim(text.substr(1));
        const auto space = head.find_first_of(" \t");
        std::string name = upper(space == std::string::npos ? head : head.substr(0, space));
        const std::string rest = space == std::string::npos ? "" : head.substr(space + 1);
        bool long_card = long_deck;
        std::string suffix = trim(rest);
        if (!name.empty() && (name.back() == '+' || name.back() == '-')) {
          long_card = name.back() == '+';
          name.pop_back();
        } else if (suffix == "+" || suffix == "-") {
          long_card = suffix == "+";
          suffix.clear();
        }
        if (name == "KEYWORD") {
          keyword_options(rest, path, line_no);
          suffix.clear();
        }
        if (!suffix.empty())
          fail(path, line_no, "*" + name + ": unexpected text '" + suffix + "' after the keyword; allowed: '+' or '-' only");
        deck.cards.push_back(Card{name, long_card, path, line_no, {}});
        open = &deck.cards.back();
        if (name == "END") break;
        continue;
      }
      if (!open) {
        if (trim(text).empty()) continue;
        fail(path, line_no, "data before the first keyword; allowed: a '*' keyword line first ($ for comments)");
      }
      open->lines.push_back(DataLine{text, path, line_no});
      if (open->keyword == "INCLUDE" && !trim(text).empty()) {
        const std::string name = trim(text);
        if (name.size() >= 78 && name.back() == '+')
          fail(path, line_no, "*INCLUDE: continued file names ('+' at column 80) are not supported; allowed: one line");
        const fs::path p = fs::path(name).is_absolute() ? fs::path(name) : fs::path(path).parent_path() / name;
        includes.emplace_back(p.string(), line_no);
      }
    }
    flush_includes();
    open_files.pop_back();
  }
};

}  // namespace

Deck read_deck(const std::string& path) {
  Deck deck;
  deck.file = path;
  Reader r{deck, false, {}};
  r.read_file(path, "", 0);
  return deck;
}

std::string where(const Card& c) { return msg() << c.file << ":" << c.line << ": *" << c.keyword << ": "; }

std::string where(const Card& c, const DataLine& l) { return msg() << l.file << ":" << l.line << ": *" << c.keyword << ": "; }

}  // namespace plyimpact::keyword
