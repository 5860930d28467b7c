// LS-DYNA keyword deck reader: splits a deck (and the files it *INCLUDEs) into cards, each with its
// data lines and where they came from. It knows the file structure only (LS-DYNA Keyword User's
// Manual, Vol. I, "General card format" and *KEYWORD, *INCLUDE, *TITLE, *END):
//  - a line starting with '*' opens a keyword, one starting with '$' is a comment; every other line,
//    blank ones included, is a data line of the open keyword;
//  - "*KEYWORD LONG=Y" switches the whole deck to long format (20-character fields); a keyword
//    written with a trailing '+' ("*NODE +") is in long format, with '-' in standard format;
//  - "*INCLUDE" names one file per data line, relative to the folder of the including file;
//  - "*END" ends the file it is in.
// What each card's fields mean is keyword/fields.hpp and keyword/converter.cpp.
#pragma once

#include <string>
#include <vector>

namespace plyimpact::keyword {

struct DataLine {
  std::string text;  // without the line end
  std::string file;
  int line = 0;      // 1-based
};

struct Card {
  std::string keyword;      // upper case, without '*' and the +/- format suffix, e.g. "MAT_ELASTIC_TITLE"
  bool long_format = false;
  std::string file;
  int line = 0;             // line of the keyword
  std::vector<DataLine> lines;
};

struct Deck {
  std::string file;                  // the main file
  std::vector<Card> cards;           // in input order, includes expanded; *INCLUDE/*KEYWORD/*END kept
};

/// @throws InputError (file:line) for an unreadable file, an include cycle, data before the first
/// keyword or an unsupported *KEYWORD/*INCLUDE form.
Deck read_deck(const std::string& path);

/// "file:line: *KEYWORD: " for messages.
std::string where(const Card& c);
std::string where(const Card& c, const DataLine& l);

}  // namespace plyimpact::keyword
