#pragma once
// The parsed program: blocks of words, each with its source range. No modal
// knowledge lives here (that is the interpreter's job).
#include <cstdint>
#include <string>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/word_number.h"

namespace klueng::core::gcode {

struct Word {
  // (Members ordered to avoid padding: a big program holds millions of words.)
  // (48 bytes: the flags and the digit count share the first eight with expr.)
  char letter = 0;  // upper-case address letter, 'A'..'Z'
  bool hasDecimalPoint : 1 = false;
  bool colon : 1 = false;     // an ISO ':' program number (":0100"), stored as letter 'O'
  bool comma : 1 = false;     // a Fanuc ',C' ',R' ',A' word (chamfer, corner radius, angle) on G01
  bool blanks : 1 = false;    // written with blanks inside ("X 38"): a Fanuc skips them, classic refuses
  std::int16_t decimals = 0;  // digits after the decimal point (a line is at most 4096 characters)
  int expr = -1;              // macro B: index into Program::expressions when the value is an
                              // expression (X#101, Z-[#1+2.]); value is 0 then and number holds
                              // the expression as written ("#101", "-[#1+2.]")
  double value = 0.0;         // numeric value as written (mm or inch, diameters for X/U)
  WordNumber number;          // the number exactly as written ("01", "-.5", "25.")
                              // (an O word written ':0100' has colon set and number "0100")
  SourceRange range;          // covers letter and number

  // Integer code of a G/M/T/N/O word ("G01" -> 1). Only meaningful when
  // !hasDecimalPoint; G-code numbers like "G1.5" are reported by the checker.
  // (A value outside int's range, reachable through a macro expression, gives -1.)
  int code() const { return value > -2.0e9 && value < 2.0e9 ? static_cast<int>(value) : -1; }
  // The word as written, for messages: "X25.4", ":0100".
  std::string text() const { return (colon ? ':' : letter) + number; }
};
static_assert(sizeof(Word) == 48, "a Word is 48 bytes: big programs hold millions");

// Custom macro B statements (Fanuc 0i-TF manual, custom macro chapter; Haas
// reads the same). A statement block holds only its statement (and an N word).
enum class StatementKind : std::uint8_t {
  None,    // an NC block
  Assign,  // #i = expr              (target: the variable number, value: the value)
  Goto,    // GOTO n                 (value: the sequence number)
  If,      // IF [c] GOTO n          (condition, value)
           // IF [c] THEN #i = expr  (condition, then, target, value)
  While,   // WHILE [c] DO m         (condition, loop)
  Do,      // DO m without WHILE: an endless loop until GOTO leaves it (loop)
  End,     // END m                  (loop)
  Output,  // POPEN, PCLOS, DPRNT[...], BPRNT[...]: external output, nothing to simulate
};

struct Statement {
  StatementKind kind = StatementKind::None;
  bool then = false;   // IF ... THEN assignment (else IF ... GOTO)
  int loop = 0;        // DO m / END m identifier (1-3)
  int condition = -1;  // expression index (Program::expressions)
  int target = -1;     // expression index of the variable number: #[#1+100] = ...
  int value = -1;      // expression index of the value or the GOTO target
  SourceRange range;   // the keyword (or the '#' of an assignment)
};

// Macro expressions, compiled to postfix when the line is read.
enum class ExprOp : std::uint8_t {
  Constant,  // push value
  Variable,  // pop n, push #n
  Negate,
  Plus,
  Add,
  Sub,
  Mul,
  Div,
  Mod,
  And,
  Or,
  Xor,
  Eq,
  Ne,
  Gt,
  Ge,
  Lt,
  Le,
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Atan2,
  Sqrt,
  Abs,
  Round,
  Fix,
  Fup,
  Ln,
  Exp,
  Pow,
  Bin,
  Bcd,
};

struct ExprToken {
  ExprOp op = ExprOp::Constant;
  double value = 0.0;  // Constant only
};

struct Expression {
  std::vector<ExprToken> code;  // postfix
  SourceRange range;            // the expression as written
};

struct Block {
  std::vector<Word> words;      // in source order
  std::string comment;          // text of ( ) and ; comments, joined by a space
  Statement statement;          // a macro statement (kind None for an NC block)
  int line = 0;                 // 1-based line in the file
  int file = 0;                 // Program::files index: 0 = the program itself, else a subprogram file
  bool blockSkip = false;       // started with '/'
  bool hasExpressions = false;  // some word's value is an expression (evaluated when the block runs)
  // The address letters of its words, one bit each ('A' = bit 0): a superset
  // is always right, so a block built by hand keeps all bits set. parse()
  // sets it exactly, and find() then answers "no such word" from the block
  // alone, without touching its words (their own allocation: a cache miss).
  std::uint32_t letters = ~std::uint32_t{0};

  static constexpr std::uint32_t letterBit(char letter) {
    return letter >= 'A' && letter <= 'Z' ? std::uint32_t{1} << (letter - 'A') : 0;
  }
  bool mayHave(char letter) const { return (letters & letterBit(letter)) != 0; }

  // The first word of a letter (comma words ',C' excluded: findComma).
  // (Inline: the checker and the scans ask several letters of every block.)
  const Word* find(char letter) const {
    if (!mayHave(letter)) return nullptr;
    for (const Word& w : words)
      if (w.letter == letter && !w.comma) return &w;
    return nullptr;
  }
  const Word* findComma(char letter) const {
    if (!mayHave(letter)) return nullptr;
    for (const Word& w : words)
      if (w.letter == letter && w.comma) return &w;
    return nullptr;
  }
  bool has(char letter) const { return find(letter) != nullptr; }
  // Every G (or M) code word of the block, in source order, as pointers
  // (a view: walking it allocates nothing; scans run it on every block).
  class LetterWords {
   public:
    class iterator {
     public:
      iterator(const Word* at, const Word* end, char letter) : at_(at), end_(end), letter_(letter) { skip(); }
      const Word* operator*() const { return at_; }
      iterator& operator++() {
        ++at_;
        skip();
        return *this;
      }
      bool operator==(const iterator& o) const { return at_ == o.at_; }

     private:
      void skip() {
        while (at_ != end_ && (at_->letter != letter_ || at_->comma)) ++at_;
      }
      const Word* at_;
      const Word* end_;
      char letter_;
    };
    LetterWords(const std::vector<Word>& words, char letter, bool present)
        : words_(words), letter_(letter), present_(present) {}
    iterator begin() const {
      const Word* end = words_.data() + words_.size();
      return {present_ ? words_.data() : end, end, letter_};
    }
    iterator end() const { return {words_.data() + words_.size(), words_.data() + words_.size(), letter_}; }

   private:
    const std::vector<Word>& words_;
    char letter_;
    bool present_;
  };
  LetterWords all(char letter) const { return LetterWords(words, letter, mayHave(letter)); }
};

struct Program {
  std::vector<Block> blocks;                   // only lines with words; blank, comment-only and % lines are dropped
  std::vector<Diagnostic> lexicalDiagnostics;  // errors found while reading the text
  int firstLine = 1;                           // file line of the first G-code line
  int lineCount = 0;                           // number of G-code lines read
  std::vector<Expression> expressions;         // macro expressions of every block (Word::expr, Statement)
  // Subprogram files appended after the program's own blocks (io/subprogram_files.h):
  // files[0] is the program itself (empty name); files[i] the path of file i.
  std::vector<std::string> files{std::string()};
  // Called programs whose only file of that name in the folder is no file (a
  // folder, a pipe, a device), so that the call says so (E416) instead of "not
  // in its folder" (E404).
  struct NotAFile {
    int number = 0;    // the O number called
    std::string name;  // the entry's name in the folder
    bool folder = false;
  };
  std::vector<NotAFile> notProgramFiles;
  // Text that controls read differently (issue 38 item 5): what follows the first ';' of a line
  // (a Fanuc reads it as the next block; here it is a comment), and what follows the first ')' of
  // a comment with nested parentheses (a Fanuc's comment ends there; here at the balancing ')').
  // The checker judges them by the machine's profile; only lines that have such text are listed.
  struct TextTail {
    int line = 0;
    int column = 0;  // of the tail's first character
    int file = 0;
    bool afterEndOfBlock = false;  // after ';' (else after a comment's first ')')
    std::string text;
  };
  std::vector<TextTail> tails;
};

// The O number whose program contains block `index` (the nearest O word at or
// before it within the same file); 0 when none.
int programNumberAt(const Program& program, int index);

}  // namespace klueng::core::gcode
