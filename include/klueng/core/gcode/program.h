#pragma once
// The parsed program: blocks of words, each with its source range. No modal
// knowledge lives here (that is the interpreter's job).
#include <string>
#include <vector>

#include "klueng/core/diagnostic.h"

namespace klueng::core::gcode {

struct Word {
  // (Members ordered to avoid padding: a big program holds millions of words.)
  char letter = 0;          // upper-case address letter, 'A'..'Z'
  bool hasDecimalPoint = false;
  bool colon = false;       // an ISO ':' program number (":0100"), stored as letter 'O'
  int decimals = 0;         // digits after the decimal point
  double value = 0.0;       // numeric value as written (mm or inch, diameters for X/U)
  std::string number;       // the number exactly as written ("01", "-.5", "25.")
                            // (an O word written ':0100' has colon set and number "0100")
  SourceRange range;        // covers letter and number

  // Integer code of a G/M/T/N/O word ("G01" -> 1). Only meaningful when
  // !hasDecimalPoint; G-code numbers like "G1.5" are reported by the checker.
  int code() const { return static_cast<int>(value); }
  // The word as written, for messages: "X25.4", ":0100".
  std::string text() const { return (colon ? ':' : letter) + number; }
};

struct Block {
  int line = 0;                 // 1-based line in the file
  bool blockSkip = false;       // started with '/'
  std::vector<Word> words;      // in source order
  std::string comment;          // text of ( ) and ; comments, joined by a space

  const Word* find(char letter) const;
  bool has(char letter) const { return find(letter) != nullptr; }
  // Every G (or M) code word of the block, in source order.
  std::vector<const Word*> all(char letter) const;
};

struct Program {
  std::vector<Block> blocks;    // only lines with words; blank, comment-only and % lines are dropped
  std::vector<Diagnostic> lexicalDiagnostics;  // errors found while reading the text
  int firstLine = 1;            // file line of the first G-code line
  int lineCount = 0;            // number of G-code lines read
};

}  // namespace klueng::core::gcode
