// Lexer and parser in one pass (SPEC 3). Each line is scanned once, byte by
// byte, with the column counted in Unicode code points so that a Thai comment
// before a word still gives the word's true column.
#include "klueng/core/gcode/parser.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <memory>
#include <new>
#include <string>

#include "diagnostic_codes.h"
#include "klueng/core/gcode/comment.h"
#include "klueng/core/gcode/macro.h"
#include "klueng/core/number_read.h"

namespace klueng::core::gcode {

namespace {

bool isLetter(unsigned char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isDigit(unsigned char c) { return c >= '0' && c <= '9'; }
bool isNumberChar(unsigned char c) { return isDigit(c) || c == '.' || c == '+' || c == '-'; }
bool isBlank(unsigned char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }

// Byte length of the UTF-8 sequence starting at s[i]; 1 for an invalid byte
// (counted as one code point, like io::utf8Length).
std::size_t utf8SequenceLength(std::string_view s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  std::size_t n = 1;
  if (c >= 0xC2 && c <= 0xDF)
    n = 2;
  else if (c >= 0xE0 && c <= 0xEF)
    n = 3;
  else if (c >= 0xF0 && c <= 0xF4)
    n = 4;
  else
    return 1;
  if (i + n > s.size()) return 1;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 1;
  return n;
}

// Short numbers (at most 15 digits) take the exact fast path in lexWord: an
// integer mantissa below 2^53 divided by an exact power of ten is correctly
// rounded, i.e. the same double strtod gives.
constexpr double kPow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

// Value of a longer "digits[.digits]" (no sign).
double parseLongUnsigned(std::string_view digits) {
  double v = 0.0;
  const auto result = readDouble(digits.data(), digits.data() + digits.size(), v);
  if (result.ec == std::errc::result_out_of_range) v = 1e308;  // reported as out of range by the checker
  return v;
}

// [+-]? digits [. digits] from s[k]: where it ends, its digits as one integer and how many lie
// before and after the point. One pass: the lexer's hottest loop, every word of the file.
struct DecimalScan {
  std::size_t start = 0, end = 0;  // the digits (after the sign) to the end
  std::uint64_t mantissa = 0;      // exact while at most 15 digits
  std::size_t intDigits = 0, fracDigits = 0;
  bool point = false;
};

inline DecimalScan scanDecimal(std::string_view s, std::size_t k) {
  const std::size_t n = s.size();
  DecimalScan r;
  if (k < n && (s[k] == '+' || s[k] == '-')) ++k;
  r.start = k;
  while (k < n && isDigit(static_cast<unsigned char>(s[k])))
    r.mantissa = r.mantissa * 10 + static_cast<std::uint64_t>(s[k++] - '0');
  r.intDigits = k - r.start;
  if (k < n && s[k] == '.') {
    r.point = true;
    const std::size_t fracStart = ++k;
    while (k < n && isDigit(static_cast<unsigned char>(s[k])))
      r.mantissa = r.mantissa * 10 + static_cast<std::uint64_t>(s[k++] - '0');
    r.fracDigits = k - fracStart;
  }
  r.end = k;
  return r;
}

class LineParser {
 public:
  LineParser(Program& program, std::size_t& diagnosticBudget, int file)
      : program_(program), budget_(diagnosticBudget), file_(file) {}

  void addTail(bool afterEndOfBlock, int column, std::string_view text) {
    if (program_.tails.size() >= codes::kMaxLexicalDiagnostics) return;  // a hostile file: bounded
    program_.tails.push_back({lineNumber_, column, file_, afterEndOfBlock, std::string(text)});
  }

  // One line of text: its items in turn (blanks, comments, a macro statement, words, and what is
  // none of them: each reported), then the block they make.
  void parseLine(std::string_view line, int lineNumber) {
    line_ = line;
    lineNumber_ = lineNumber;
    // (Made in place, and taken back when the line makes no block.)
    Block& block = program_.blocks.emplace_back();
    block.line = lineNumber;
    block.file = file_;
    words_.clear();
    LineState state;
    std::size_t i = 0;
    int col = 1;
    while (i < line.size())
      if (!readItem(block, state, i, col)) break;
    if (!finishBlock(block, state.tapeLine)) program_.blocks.pop_back();
  }

 private:
  struct LineState {
    bool sawWordOrSkip = false;  // '/' is block skip only before the first word
    bool tapeLine = false;       // a '%' line: only blanks and comments may follow
  };

  // The item that starts at line_[i]: read, or reported; i and col move past it. False when the
  // block can hold no more words (E120): the rest of the line is not read.
  bool readItem(Block& block, LineState& state, std::size_t& i, int& col) {
    const std::string_view line = line_;
    const auto c = static_cast<unsigned char>(line[i]);
    if (isBlank(c)) {
      ++i;
      ++col;
    } else if (isLetter(c) && lexPlainWord(i, col)) {
      // (The common word, "X49.816": read in one pass; anything else goes the long way below.)
      state.sawWordOrSkip = true;
    } else if (c == '(') {
      col = readComment(block, i, col);
    } else if (c == ';') {
      readEndOfBlockComment(block, i, col);
    } else if (block.statement().kind == StatementKind::None && isLetter(c) && i + 1 < line.size() &&
               isLetter(static_cast<unsigned char>(line[i + 1])) && startsStatement(line.substr(i))) {
      // IF / WHILE / GOTO / DO / END: a macro statement to the end of the line.
      col = lexStatement(block, i, col);
      state.sawWordOrSkip = true;
    } else if (block.statement().kind == StatementKind::None && c == '#') {
      col = lexAssignment(block.editStatement(), i, col, false);
      state.sawWordOrSkip = true;
    } else if (c == ',' && i + 1 < line.size() && isLetter(static_cast<unsigned char>(line[i + 1]))) {
      if (blockIsFull(col)) return false;
      col = readCommaWord(i, col);
      state.sawWordOrSkip = true;
    } else if (isLetter(c) && oForZeroEnd(i) > i) {
      col = reportLetterOForZero(i, col);
      state.sawWordOrSkip = true;
    } else if ((isLetter(c) && looksLikeText(i)) || utf8SequenceLength(line, i) > 1) {
      col = reportTextLine(i, col);
      state.sawWordOrSkip = true;
    } else if (isLetter(c)) {
      if (blockIsFull(col)) return false;
      col = lexWord(i, col);
      state.sawWordOrSkip = true;
    } else if (c == ':' && i + 1 < line.size() && isDigit(static_cast<unsigned char>(line[i + 1]))) {
      // ISO program number ":0100": read as an O word; the checker decides
      // whether the profile allows it.
      if (blockIsFull(col)) return false;
      col = lexWord(i, col);
      state.sawWordOrSkip = true;
    } else if (isNumberChar(c)) {
      col = reportLoneNumber(i, col);
      state.sawWordOrSkip = true;
    } else if (c == '/' && !state.sawWordOrSkip && !state.tapeLine) {
      block.blockSkip = true;
      state.sawWordOrSkip = true;
      ++i;
      ++col;
    } else if (c == '%' && !state.sawWordOrSkip && !state.tapeLine && block.comment().empty()) {
      // Tape start/end mark: only blanks and comments may follow it.
      state.tapeLine = true;
      state.sawWordOrSkip = true;
      ++i;
      ++col;
      return !reportTextAfterTapeMark(i, col);
    } else {
      col = reportUnknownRun(i, col, state.sawWordOrSkip);
    }
    return true;
  }

  // A control skips what follows the first '%' up to the line end (B-63524EN §8), so text there
  // (`%PART 7`) is one E108 for the whole rest, never read as words or as a line of text. True when
  // there was some: the rest of the line is not read.
  bool reportTextAfterTapeMark(std::size_t i, int col) {
    const std::string_view line = line_;
    std::size_t rest = i;
    while (rest < line.size() && isBlank(static_cast<unsigned char>(line[rest]))) ++rest;
    if (rest >= line.size() || line[rest] == '(' || line[rest] == ';') return false;
    std::string_view tail = line.substr(rest);
    while (!tail.empty() && isBlank(static_cast<unsigned char>(tail.back()))) tail.remove_suffix(1);
    report(codes::kTextAfterTapeMark, col + static_cast<int>(rest - i), static_cast<int>(tail.size()),
           {std::string(tail.substr(0, std::min<std::size_t>(tail.size(), 40)))});
    return true;
  }

  // "( ... )": a comment ends where its parentheses balance ("(n = Vc*1000/(pi*D))" is one
  // comment) or at the end of the line (issue 26; docs/program-file.md). Returns the column after it.
  int readComment(Block& block, std::size_t& i, int col) {
    const std::string_view line = line_;
    const int startCol = col;
    const std::size_t close = commentClose(line, i);
    const std::size_t j = close == std::string_view::npos ? line.size() : close;
    const std::size_t firstClose = line.find(')', i + 1);
    int endCol = col + 1;
    for (std::size_t k = i + 1; k < j; k += utf8SequenceLength(line, k)) {
      if (k == firstClose + 1) addTail(false, endCol, line.substr(k, j + 1 - k));
      ++endCol;
    }
    appendComment(block, line.substr(i + 1, j - i - 1));
    if (j >= line.size()) {
      report(codes::kCommentToLineEnd, startCol, endCol - startCol, {}, Severity::Warning);
      i = j;
      return endCol;
    }
    i = j + 1;
    return endCol + 1;
  }

  // ";": the rest of the line is a comment (and a tail that a Fanuc reads as the next block).
  void readEndOfBlockComment(Block& block, std::size_t& i, int col) {
    const std::string_view line = line_;
    if (line.find_first_not_of(" \t\f\v;", i + 1) != std::string_view::npos) addTail(true, col + 1, line.substr(i + 1));
    appendComment(block, line.substr(i + 1));
    i = line.size();
  }

  // A block keeps at most kMaxWordsPerBlock words: one more is E120, and the line ends there.
  bool blockIsFull(int col) {
    if (words_.size() != codes::kMaxWordsPerBlock) return false;
    report(codes::kBlockTooLong, col, 0, {std::to_string(codes::kMaxWordsPerBlock)});
    return true;
  }

  // ',C' ',R' ',A': chamfer, corner radius and angle words of G01.
  int readCommaWord(std::size_t& i, int col) {
    ++i;
    const std::size_t before = words_.size();
    col = lexWord(i, col + 1);
    if (words_.size() > before) {
      Word& w = words_.back();
      w.comma = true;
      w.range.column -= 1;
      w.range.length += 1;
    }
    return col;
  }

  // "GO1": the letter O typed for the digit 0. One error that names the word meant.
  int reportLetterOForZero(std::size_t& i, int col) {
    const std::size_t e = oForZeroEnd(i);
    std::string written(line_.substr(i, e - i)), meant = written;
    for (std::size_t k = 1; k < meant.size(); ++k)
      if (meant[k] == 'O' || meant[k] == 'o') meant[k] = '0';
    for (std::string* t : {&written, &meant})
      t->front() = static_cast<char>(std::toupper(static_cast<unsigned char>(t->front())));
    report(codes::kLetterOForZero, col, static_cast<int>(e - i), {written, meant});
    col += static_cast<int>(e - i);
    i = e;
    return col;
  }

  // "roughing pass", "กลึงหยาบ": words the author meant as a comment. One error for the line.
  int reportTextLine(std::size_t& i, int col) {
    const std::string_view line = line_;
    std::size_t e = i;
    while (e < line.size() && line[e] != '(' && line[e] != ';') ++e;
    std::size_t last = e;
    while (last > i && isBlank(static_cast<unsigned char>(line[last - 1]))) --last;
    int length = 0;
    std::size_t shown = i;  // the first 20 code points, for the message
    for (std::size_t k = i; k < last; k += utf8SequenceLength(line, k))
      if (++length <= 20) shown = k + utf8SequenceLength(line, k);
    report(codes::kTextLine, col, length, {std::string(line.substr(i, shown - i))});
    for (std::size_t k = last; k < e; ++k) ++length;
    col += length;
    i = e;
    return col;
  }

  // A number with no address letter before it.
  int reportLoneNumber(std::size_t& i, int col) {
    const std::string_view line = line_;
    const std::size_t start = i;
    while (i < line.size() && isNumberChar(static_cast<unsigned char>(line[i]))) ++i;
    const int length = static_cast<int>(i - start);
    report(codes::kLoneNumber, col, length, {std::string(line.substr(start, i - start))});
    return col + length;
  }

  // Unknown characters: one diagnostic for a run of them, so binary junk gives few messages.
  int reportUnknownRun(std::size_t& i, int col, bool sawWordOrSkip) {
    const std::string_view line = line_;
    const std::size_t start = i;
    const int startCol = col;
    while (i < line.size()) {
      const auto d = static_cast<unsigned char>(line[i]);
      if (isBlank(d) || isLetter(d) || isNumberChar(d) || d == '(' || d == ';') break;
      if (d == '/' && !sawWordOrSkip) break;
      i += utf8SequenceLength(line, i);
      ++col;
    }
    const std::string_view run = line.substr(start, i - start);
    const std::size_t first = utf8SequenceLength(run, 0);
    const bool slash = run.size() == 1 && run[0] == '/';
    const bool percent = run.size() == 1 && run[0] == '%';
    const char* code = slash     ? codes::kMisplacedBlockSkip
                       : percent ? codes::kMisplacedTapeMark
                                 : codes::kUnknownCharacter;
    report(code, startCol, col - startCol, {std::string(run.substr(0, first))});
    return col;
  }

  // The block the line's words make: a statement keeps only an N word beside it; a '%' line's
  // words are reported, not run; a line without words makes no block.
  // True when the line makes a block.
  bool finishBlock(Block& block, bool tapeLine) {
    if (block.statement().kind != StatementKind::None) {
      // Only an N word may share the block with a statement.
      for (std::size_t k = 0; k < words_.size(); ++k)
        if (words_[k].letter != 'N' || k != 0)
          report(codes::kStatementNotAlone, words_[k].range.column, words_[k].range.length, {words_[k].text()});
      if (!words_.empty() && words_[0].letter == 'N') block.words.push_back(std::move(words_[0]));
      noteWords(block);
      return true;
    }
    if (words_.empty()) return false;
    if (tapeLine) {
      // Words after '%' are reported, not run: the line is a tape mark.
      const Word& w = words_.front();
      report(codes::kTextAfterTapeMark, w.range.column, w.range.length, {w.letter + w.number});
      return false;
    }
    block.words = words_.keep();
    noteWords(block);
    return true;
  }

  // The line's words, made in place in the program's word store, one chunk after another (a
  // block's words side by side): the block borrows them, no allocation a block and no copy.
  // Words of a line that makes no block are left behind and made again by the next line.
  class LineWords {
   public:
    explicit LineWords(Program& program) : program_(program) {}
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    Word& operator[](std::size_t k) { return chunk_->words[used_ + k]; }
    Word& front() { return chunk_->words[used_]; }
    Word& back() { return chunk_->words[used_ + size_ - 1]; }
    void clear() { size_ = 0; }
    // A fresh word after the line's others (a new chunk takes them when this one is full).
    Word& emplace_back() {
      if (!chunk_ || used_ + size_ == chunk_->capacity) grow();
      const std::size_t at = used_ + size_++;
      if (at < chunk_->made) return chunk_->words[at] = Word();  // a word of a line that made no block
      ++chunk_->made;
      return *new (chunk_->words + at) Word();
    }
    // The line's words, kept: the block borrows them.
    WordList keep() {
      WordList list = WordList::borrow(chunk_->words + used_, size_);
      used_ += size_;
      size_ = 0;
      return list;
    }

   private:
    static constexpr std::size_t kChunkWords = 4096;  // words a store chunk holds (160 KB)
    // Room for words, made one by one as the lines need them (not all at once, then again).
    struct Chunk {
      explicit Chunk(std::size_t n) : words(static_cast<Word*>(::operator new(n * sizeof(Word)))), capacity(n) {}
      Chunk(const Chunk&) = delete;
      Chunk& operator=(const Chunk&) = delete;
      ~Chunk() {
        std::destroy_n(words, made);
        ::operator delete(words);
      }
      Word* words;
      std::size_t capacity;
      std::size_t made = 0;  // words [0, made) are made
    };
    void grow() {
      auto chunk = std::make_shared<Chunk>(std::max(kChunkWords, 2 * size_));
      for (std::size_t k = 0; k < size_; ++k) new (chunk->words + k) Word(std::move(chunk_->words[used_ + k]));
      chunk->made = size_;
      chunk_ = chunk.get();
      used_ = 0;
      program_.wordStores.push_back(std::move(chunk));
    }
    Program& program_;
    Chunk* chunk_ = nullptr;  // the chunk being filled: kept words [0, used_), the line's after them
    std::size_t used_ = 0;
    std::size_t size_ = 0;
  };

  Program& program_;
  std::size_t& budget_;
  int file_ = 0;
  std::string_view line_;
  int lineNumber_ = 0;
  LineWords words_{program_};  // words of the current line
  std::string scratch_;        // a number written with blanks inside, gathered without them
  char* chars_ = nullptr;      // the number store chunk being filled, its size and how far
  std::size_t charsSize_ = 0;
  std::size_t charsUsed_ = 0;

  // A word's number: kept inside the word when short (nearly always), else in the program's
  // number store (a length, then the characters), which the word borrows.
  void setNumber(Word& w, std::string_view text) {
    if (text.size() <= WordNumber::kInlineCapacity) {
      w.number.setShort(text);
      return;
    }
    const std::size_t need = (sizeof(std::uint32_t) + text.size() + 3) & ~std::size_t{3};  // 4-byte aligned
    if (!chars_ || charsUsed_ + need > charsSize_) {
      // 1 KB first (a line the editor explains), doubling to 64 KB (a long program's).
      charsSize_ = std::max(std::min<std::size_t>(std::max<std::size_t>(charsSize_ * 2, 1024), 64 * 1024), need);
      auto chunk = std::shared_ptr<char[]>(new char[charsSize_]);
      chars_ = chunk.get();
      charsUsed_ = 0;
      program_.wordStores.push_back(std::move(chunk));
    }
    char* at = chars_ + charsUsed_;
    const auto n = static_cast<std::uint32_t>(text.size());
    std::memcpy(at, &n, sizeof n);
    std::memcpy(at + sizeof n, text.data(), text.size());
    charsUsed_ += need;
    w.number = WordNumber::borrow(at);
  }

  // What the scans ask of a block without reading its words.
  static void noteWords(Block& block) {
    block.letters = 0;
    for (const Word& w : block.words) {
      block.letters |= Block::letterBit(w.letter);
      block.hasExpressions |= w.expr >= 0;
    }
  }

  static void appendComment(Block& block, std::string_view text) {
    while (!text.empty() && isBlank(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
    while (!text.empty() && isBlank(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
    if (text.empty()) return;
    std::string& comment = block.editComment();
    if (!comment.empty()) comment += ' ';
    comment.append(text);
  }

  void report(const char* code, int column, int length, std::vector<std::string> args,
              Severity severity = Severity::Error) {
    if (budget_ == 0) return;
    if (--budget_ == 0) {
      program_.lexicalDiagnostics.push_back(
          Diagnostic{Severity::Error, codes::kTooManyLexicalErrors, {lineNumber_, column, 0, file_}, {}});
      return;
    }
    program_.lexicalDiagnostics.push_back(
        Diagnostic{severity, code, {lineNumber_, column, length, file_}, std::move(args)});
  }

  // "GO1", "MO3", "G0O": a letter, then digits and at least one letter O, and
  // at least one digit. Returns the end of such a token, else i.
  std::size_t oForZeroEnd(std::size_t i) const {
    std::size_t e = i + 1;
    bool o = false, digit = false;
    while (e < line_.size()) {
      const auto d = static_cast<unsigned char>(line_[e]);
      if (d == 'O' || d == 'o')
        o = true;
      else if (isDigit(d))
        digit = true;
      else if (d != '.')
        break;
      ++e;
    }
    if (!o || !digit) return i;
    if (e < line_.size() && isLetter(static_cast<unsigned char>(line_[e]))) return i;
    return e;
  }

  // A run of letters that no address reads: three or more ("roughing"), or two
  // not followed by a value ("to", "OD"). Macro statements are read before this.
  bool looksLikeText(std::size_t i) const {
    std::size_t e = i;
    while (e < line_.size() && isLetter(static_cast<unsigned char>(line_[e]))) ++e;
    if (e - i >= 3) return true;
    if (e - i < 2) return false;
    if (e >= line_.size()) return true;
    const auto d = static_cast<unsigned char>(line_[e]);
    return !(isNumberChar(d) || d == '#' || d == '[' || d == ',');
  }

  // The number after an address letter. A Fanuc skips blanks inside a word
  // ("X 38" = X38, "X- 5." = X-5.), so the number is gathered here without
  // them: number is a view of line_ when it has no blanks, else of scratch_.
  struct NumberText {
    std::string_view number;
    std::size_t end = 0;       // in line_, after the number
    bool blanks = false;       // blanks between the letter and the number, or after a sign
    bool splitDigits = false;  // blanks between two groups of digits ("X20 30")
  };
  NumberText gatherNumber(std::size_t i) {
    NumberText t;
    const std::size_t n = line_.size();
    std::size_t k = i;
    while (k < n && isBlank(static_cast<unsigned char>(line_[k]))) ++k;
    if (k > i && k < n && isNumberChar(static_cast<unsigned char>(line_[k])))
      t.blanks = true;
    else
      k = i;  // a lone letter: the blanks are not part of it
    const std::size_t start = k;
    std::size_t e = k;
    while (e < n && isNumberChar(static_cast<unsigned char>(line_[e]))) ++e;
    // Fast path: the number stands in one piece.
    auto continues = [&](std::size_t at, bool afterSignOnly) {
      std::size_t b = at;
      while (b < n && isBlank(static_cast<unsigned char>(line_[b]))) ++b;
      if (b == at || b >= n) return std::size_t{0};
      const auto d = static_cast<unsigned char>(line_[b]);
      if (afterSignOnly ? isNumberChar(d) && d != '+' && d != '-' : isDigit(d) || d == '.') return b;
      return std::size_t{0};
    };
    const bool signOnly = e == start + 1 && (line_[start] == '+' || line_[start] == '-');
    if (!t.blanks && !continues(e, signOnly)) {
      t.number = line_.substr(start, e - start);
      t.end = e;
      return t;
    }
    scratch_.assign(line_.substr(start, e - start));
    std::size_t b;
    while ((b = continues(e, scratch_.size() == 1 && (scratch_[0] == '+' || scratch_[0] == '-'))) != 0) {
      if (scratch_.size() == 1 && (scratch_[0] == '+' || scratch_[0] == '-'))
        t.blanks = true;
      else
        t.splitDigits = true;
      e = b;
      while (e < n && isNumberChar(static_cast<unsigned char>(line_[e]))) scratch_ += line_[e++];
    }
    t.number = scratch_;
    t.end = e;
    return t;
  }

  // A plain word at line_[i] (a letter, an optional sign, digits with at most one point, at most
  // 15 digits, then the end of the line, a blank not followed by more digits, or a character
  // that starts the next item): made in one pass, exactly as the long way (readItem's checks,
  // then lexWord) makes it; i and col move past it. False, with nothing read, for any other text.
  bool lexPlainWord(std::size_t& i, int& col) {
    const std::string_view line = line_;
    const std::size_t n = line.size();
    const DecimalScan scan = scanDecimal(line, i + 1);
    const std::size_t k = scan.end;
    const std::size_t fracDigits = scan.fracDigits;
    const std::size_t digits = scan.intDigits + fracDigits;
    if (digits == 0 || digits > 15) return false;
    if (k < n) {
      const auto d = static_cast<unsigned char>(line[k]);
      // More of a number ("1.2.3", "5-"), a letter O for a zero ("G0O1"), a comma for a point ("Z2,5"):
      if (isNumberChar(d) || d == 'O' || d == 'o' || d == ',') return false;
      if (isBlank(d)) {  // "X20 30": digits split by blanks
        std::size_t b = k;
        while (b < n && isBlank(static_cast<unsigned char>(line[b]))) ++b;
        if (b < n && (isDigit(static_cast<unsigned char>(line[b])) || line[b] == '.')) return false;
      }
    }
    if (words_.size() == codes::kMaxWordsPerBlock) return false;  // E120, the long way
    const std::string_view number = line.substr(i + 1, k - i - 1);
    const int length = static_cast<int>(k - i);
    Word& w = words_.emplace_back();
    w.letter = static_cast<char>(line[i] & ~0x20);  // upper case
    if (number.size() <= WordNumber::kInlineCapacity)
      w.number.setShort(number);  // (nearly always: no call)
    else
      setNumber(w, number);
    w.hasDecimalPoint = scan.point;
    w.decimals = static_cast<std::int16_t>(fracDigits);
    w.range = SourceRange{lineNumber_, col, length, file_};
    const double v = static_cast<double>(scan.mantissa) / kPow10[fracDigits];
    w.value = number[0] == '-' ? -v : v;
    i = k;
    col += length;
    return true;
  }

  // Reads letter + number at line_[i]; returns the column after the word.
  int lexWord(std::size_t& i, int col) {
    const bool colon = line_[i] == ':';
    const char letter = colon ? 'O' : static_cast<char>(line_[i] & ~0x20);  // upper case
    const std::size_t start = i;
    ++i;
    if (startsAddressExpression(i)) return lexAddressExpression(letter, i, col);
    // number := [+-]? ( digits [. digits?] | . digits ), read in one pass with its value.
    const NumberText text = gatherNumber(i);
    const std::string_view number = text.number;
    const std::size_t n = number.size();
    const DecimalScan scan = scanDecimal(number, 0);
    const std::size_t k = scan.end;
    const std::uint64_t mantissa = scan.mantissa;  // exact while at most 15 digits (parseLongUnsigned beyond)
    const std::size_t intDigits = scan.intDigits, fracDigits = scan.fracDigits;
    const bool point = scan.point;
    i = text.end;
    // "Z,15" / "X2,5": a comma typed for the decimal point.
    if (i + 1 < line_.size() && line_[i] == ',' && isDigit(static_cast<unsigned char>(line_[i + 1])) && k == n) {
      std::size_t e = i + 1;
      while (e < line_.size() && isDigit(static_cast<unsigned char>(line_[e]))) ++e;
      std::string written(line_.substr(start, e - start));
      written.front() = letter;
      const std::string meant =
          std::string(1, letter) + std::string(number) + "." + std::string(line_.substr(i + 1, e - i - 1));
      report(codes::kCommaForPoint, col, static_cast<int>(e - start), {written, meant});
      i = e;
      return col + static_cast<int>(e - start);
    }
    // The number as written runs on over every sign, digit and point ("1.2.3", "5-").
    const int length = static_cast<int>(i - start);
    if (n == 0) {
      report(codes::kLoneLetter, col, 1, {std::string(1, letter)});
      i = start + 1;
      return col + 1;
    }
    if (k != n || intDigits + fracDigits == 0) {
      report(codes::kMalformedNumber, col, length, {std::string(line_.substr(start, i - start))});
      return col + length;
    }
    if (text.splitDigits)
      report(codes::kBlanksInNumber, col, length,
             {std::string(line_.substr(start, i - start)), std::string(1, letter) + std::string(number)},
             Severity::Warning);

    Word& w = words_.emplace_back();
    w.letter = letter;
    w.colon = colon;
    setNumber(w, number);
    w.hasDecimalPoint = point;
    w.blanks = text.blanks || text.splitDigits;
    w.decimals = static_cast<std::int16_t>(fracDigits);
    w.range = SourceRange{lineNumber_, col, length, file_};
    const std::size_t digits = intDigits + fracDigits;
    const double v = digits <= 15 ? static_cast<double>(mantissa) / kPow10[fracDigits]
                                  : parseLongUnsigned(number.substr(scan.start, k - scan.start));
    w.value = number[0] == '-' ? -v : v;
    return col + length;
  }

  // ---- custom macro B ------------------------------------------------------

  static bool startsWithKeyword(std::string_view s, std::string_view keyword) {
    if (s.size() < keyword.size()) return false;
    for (std::size_t k = 0; k < keyword.size(); ++k)
      if (std::toupper(static_cast<unsigned char>(s[k])) != keyword[k]) return false;
    return s.size() == keyword.size() || !isLetter(static_cast<unsigned char>(s[keyword.size()]));
  }

  static bool startsStatement(std::string_view s) {
    return startsWithKeyword(s, "IF") || startsWithKeyword(s, "WHILE") || startsWithKeyword(s, "GOTO") ||
           startsWithKeyword(s, "DO") || startsWithKeyword(s, "END") || startsWithKeyword(s, "POPEN") ||
           startsWithKeyword(s, "PCLOS") || startsWithKeyword(s, "DPRNT") || startsWithKeyword(s, "BPRNT");
  }

  // X#1, X-[#1+2.], and with blanks between as a control reads them: "X [#1 + 2.]".
  bool startsAddressExpression(std::size_t i) const {
    while (i < line_.size() && isBlank(static_cast<unsigned char>(line_[i]))) ++i;
    if (i >= line_.size()) return false;
    char c = line_[i];
    if ((c == '-' || c == '+') && i + 1 < line_.size()) c = line_[i + 1];
    return c == '#' || c == '[';
  }

  // Stores an expression; returns its index, or -1 (reported) when it does not read.
  int readInto(std::size_t& i, int& col, ExprForm form) {
    Expression e;
    const ExprReadResult r = readExpression(line_.substr(i), col, form, e);
    if (!r.ok) {
      report(r.code, r.errorColumn, 1, r.args);
      // Skip to a comment or the end of the line so one mistake gives one message.
      while (i < line_.size() && line_[i] != '(' && line_[i] != ';') {
        ++i;
        ++col;
      }
      return -1;
    }
    e.range.line = lineNumber_;
    e.range.file = file_;
    i += r.end;
    col += static_cast<int>(r.end);
    program_.expressions.push_back(std::move(e));
    return static_cast<int>(program_.expressions.size() - 1);
  }

  void skipBlanks(std::size_t& i, int& col) const {
    while (i < line_.size() && isBlank(static_cast<unsigned char>(line_[i]))) {
      ++i;
      ++col;
    }
  }

  // X#101, Z-[#1+2.]: an address whose value is an expression.
  int lexAddressExpression(char letter, std::size_t& i, int col) {
    int c = col + 1;
    const std::size_t exprStart = i;
    const int index = readInto(i, c, ExprForm::Address);
    if (index < 0) return c;
    Word& w = words_.emplace_back();
    w.letter = letter;
    std::size_t from = exprStart;
    while (from < i && isBlank(static_cast<unsigned char>(line_[from]))) ++from;
    setNumber(w, line_.substr(from, i - from));
    w.expr = index;
    w.hasDecimalPoint = true;
    w.range = SourceRange{lineNumber_, col, c - col, file_};
    return c;
  }

  // #i = expr (at '#'). In an IF ... THEN, `then` is set.
  int lexAssignment(Statement& st, std::size_t& i, int col, bool then) {
    const std::size_t start = i;
    const int startCol = col;
    ++i;
    ++col;
    const int target = readInto(i, col, ExprForm::Variable);
    if (target < 0) return col;
    skipBlanks(i, col);
    if (i >= line_.size() || line_[i] != '=') {
      report(codes::kExpectedAssignment, startCol, col - startCol, {std::string(line_.substr(start, i - start))});
      i = line_.size();
      return col;
    }
    ++i;
    ++col;
    const int value = readInto(i, col, ExprForm::Full);
    if (value < 0) return col;
    skipBlanks(i, col);
    std::size_t e = i;
    while (e < line_.size() && isLetter(static_cast<unsigned char>(line_[e]))) ++e;
    if (e - i >= 2) {
      // #1 = 1 PLUS 2: a word the expression does not know (X10. after it is E127).
      std::string word(line_.substr(i, e - i));
      for (char& ch : word) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
      report(codes::kMacroUnknownWord, col, static_cast<int>(e - i), {word});
      while (i < line_.size() && line_[i] != '(' && line_[i] != ';') {
        ++i;
        ++col;
      }
      return col;
    }
    if (!then) st.kind = StatementKind::Assign;
    st.target = target;
    st.value = value;
    if (!then) st.range = SourceRange{lineNumber_, startCol, 1, file_};
    return col;
  }

  // The loop number after DO / END: 1, 2 or 3 (a missing number reads as 1, as on the 0i).
  int loopNumber(std::size_t& i, int& col) {
    skipBlanks(i, col);
    const std::size_t start = i;
    while (i < line_.size() && isDigit(static_cast<unsigned char>(line_[i]))) ++i;
    col += static_cast<int>(i - start);
    if (i == start) return 1;
    const std::string digits(line_.substr(start, i - start));
    const int n = digits.size() > 3 ? 999 : std::stoi(digits);
    if (n < 1 || n > 3) {
      report(codes::kBadLoopNumber, col - static_cast<int>(i - start), static_cast<int>(i - start), {digits});
      return 0;
    }
    return n;
  }

  int lexStatement(Block& block, std::size_t& i, int col) {
    Statement& st = block.editStatement();
    const std::size_t start = i;
    const int startCol = col;
    auto keyword = [&](std::string_view k) {
      skipBlanks(i, col);
      if (!startsWithKeyword(line_.substr(i), k)) return false;
      i += k.size();
      col += static_cast<int>(k.size());
      return true;
    };
    auto gotoTarget = [&]() {
      skipBlanks(i, col);
      // GOTO n, GOTO #1, GOTO [#1+10]
      if (i < line_.size() && (line_[i] == '#' || line_[i] == '[')) return readInto(i, col, ExprForm::Full);
      const std::size_t s0 = i;
      while (i < line_.size() && isDigit(static_cast<unsigned char>(line_[i]))) ++i;
      if (i == s0) {
        report(codes::kMacroExpectedValue, col, 1, {i < line_.size() ? std::string(1, line_[i]) : "end of line"});
        i = line_.size();
        return -1;
      }
      Expression e;
      e.code.push_back(
          ExprToken{ExprOp::Constant,
                    static_cast<double>(std::stoll(std::string(line_.substr(s0, std::min<std::size_t>(i - s0, 9)))))});
      e.range = SourceRange{lineNumber_, col, static_cast<int>(i - s0), file_};
      col += static_cast<int>(i - s0);
      program_.expressions.push_back(std::move(e));
      return static_cast<int>(program_.expressions.size() - 1);
    };
    auto condition = [&](const char* name) {
      skipBlanks(i, col);
      if (i >= line_.size() || line_[i] != '[') {
        report(codes::kMacroExpectedBracket, col, 1, {name});
        i = line_.size();
        return -1;
      }
      return readInto(i, col, ExprForm::Full);
    };
    if (keyword("IF")) {
      st.kind = StatementKind::If;
      st.range = SourceRange{lineNumber_, startCol, 2, file_};
      st.condition = condition("IF");
      if (st.condition < 0) return col;
      if (keyword("GOTO")) {
        st.value = gotoTarget();
      } else if (keyword("THEN")) {
        st.then = true;
        skipBlanks(i, col);
        if (i < line_.size() && line_[i] == '#') {
          lexAssignment(st, i, col, true);
          col = startCol + static_cast<int>(i - start);
        } else {
          report(codes::kIfWithoutGotoThen, startCol, 2, {});
          i = line_.size();
        }
      } else {
        report(codes::kIfWithoutGotoThen, startCol, 2, {});
        i = line_.size();
      }
    } else if (keyword("WHILE")) {
      st.kind = StatementKind::While;
      st.range = SourceRange{lineNumber_, startCol, 5, file_};
      st.condition = condition("WHILE");
      if (st.condition < 0) return col;
      if (keyword("DO")) {
        st.loop = loopNumber(i, col);
      } else {
        report(codes::kWhileWithoutDo, startCol, 5, {});
        i = line_.size();
      }
    } else if (keyword("GOTO")) {
      st.kind = StatementKind::Goto;
      st.range = SourceRange{lineNumber_, startCol, 4, file_};
      st.value = gotoTarget();
    } else if (keyword("DO")) {
      st.kind = StatementKind::Do;
      st.range = SourceRange{lineNumber_, startCol, 2, file_};
      st.loop = loopNumber(i, col);
    } else if (keyword("POPEN") || keyword("PCLOS") || keyword("DPRNT") || keyword("BPRNT")) {
      // External output (a printer or a file on the real control): read past, not simulated.
      st.kind = StatementKind::Output;
      st.range = SourceRange{lineNumber_, startCol, static_cast<int>(i - start), file_};
      skipBlanks(i, col);
      if (i < line_.size() && line_[i] == '[') {
        int depth = 0;
        while (i < line_.size()) {
          const char ch = line_[i];
          ++i;
          ++col;
          if (ch == '[')
            ++depth;
          else if (ch == ']' && --depth == 0)
            break;
        }
      }
    } else if (keyword("END")) {
      st.kind = StatementKind::End;
      st.range = SourceRange{lineNumber_, startCol, 3, file_};
      st.loop = loopNumber(i, col);
    }
    // Whatever follows the statement (but a comment) is reported once.
    skipBlanks(i, col);
    if (i < line_.size() && line_[i] != '(' && line_[i] != ';') {
      std::size_t e = i;
      while (e < line_.size() && line_[e] != '(' && line_[e] != ';') ++e;
      report(codes::kStatementNotAlone, col, static_cast<int>(e - i),
             {std::string(line_.substr(i, std::min<std::size_t>(e - i, 20)))});
      col += static_cast<int>(e - i);
      i = e;
    }
    return col;
  }
};

}  // namespace

namespace {
std::atomic<std::size_t> parses{0};
}  // namespace

std::size_t parseCount() { return parses.load(std::memory_order_relaxed); }

namespace {
// A line whose first character after blanks is '%'.
bool startsWithTapeMark(std::string_view line) {
  for (const char c : line) {
    if (c == '%') return true;
    if (!isBlank(static_cast<unsigned char>(c))) return false;
  }
  return false;
}
// Any character that is not a blank or a line end.
bool holdsText(std::string_view text) {
  return std::any_of(text.begin(), text.end(),
                     [](char c) { return !isBlank(static_cast<unsigned char>(c)) && c != '\n' && c != '\r'; });
}
// A line in `text` that is a tape mark.
bool holdsTapeMark(std::string_view text) {
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t lineEnd = std::min(text.find_first_of("\r\n", at), text.size());
    if (startsWithTapeMark(text.substr(at, lineEnd - at))) return true;
    at = lineEnd + 1;
  }
  return false;
}
}  // namespace

// The start of the first line that is a tape mark ('%' after blanks), when lines stand
// before it and the program goes on after it; nullptr otherwise (no leader).
const char* firstTapeMark(const char* begin, const char* end) {
  // No '%' anywhere (most programs): no leader either, found without a look at each byte.
  if (begin == end || !std::memchr(begin, '%', static_cast<std::size_t>(end - begin))) return nullptr;
  const char* line = begin;
  bool first = true;
  for (const char* c = begin; c < end; ++c) {
    if (*c == '\n' || *c == '\r') {
      line = c + 1;
      first = false;
      continue;
    }
    if (isBlank(static_cast<unsigned char>(*c))) continue;
    if (*c == '%') {
      if (first) return nullptr;
      // The program must go on after it: a '%' that only ends the file closes the program, no leader.
      while (c < end && *c != '\n' && *c != '\r') ++c;
      for (; c < end; ++c)
        if (!isBlank(static_cast<unsigned char>(*c)) && *c != '\n' && *c != '\r' && *c != '%') return line;
      return nullptr;
    }
    // Some text on this line: skip to its end and look at the next.
    while (c < end && *c != '\n' && *c != '\r') ++c;
    if (c == end) break;
    line = c + 1;
    first = false;
  }
  return nullptr;
}

Program parse(std::string_view text, int firstLine, int file) {
  parses.fetch_add(1, std::memory_order_relaxed);
  return parseFragment(text, firstLine, file);
}

Program parseFragment(std::string_view text, int firstLine, int file) {
  Program program;
  program.firstLine = firstLine;
  std::size_t budget = codes::kMaxLexicalDiagnostics;
  LineParser parser(program, budget, file);

  // One reservation instead of repeated regrowth; a block needs at least a
  // few bytes, which bounds the guess for files of blank lines.
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  if (text.empty()) return program;
  // (std::count runs over the text in wide strides; a memchr per line cost a call each.)
  const std::size_t lines = 1 + static_cast<std::size_t>(std::count(begin, end, '\n'));
  program.blocks.reserve(std::min(lines, text.size() / 4 + 1));

  int lineNumber = firstLine;
  const char* pos = begin;
  // A control reading a file skips the leader before the first '%' line (a title, a part
  // name in any script): those lines are counted, not read.
  const char* leaderEnd = firstTapeMark(begin, end);
  bool leaderHasText = false;
  while (leaderEnd && pos < leaderEnd) {
    const char* lineEnd = pos;
    while (lineEnd < end && *lineEnd != '\n' && *lineEnd != '\r') ++lineEnd;
    for (const char* c = pos; c < lineEnd; ++c)
      if (!isBlank(static_cast<unsigned char>(*c))) leaderHasText = true;
    pos = lineEnd < end && *lineEnd == '\r' && lineEnd + 1 < end && lineEnd[1] == '\n' ? lineEnd + 2 : lineEnd + 1;
    ++program.lineCount;
    ++lineNumber;
  }
  if (leaderHasText)
    program.lexicalDiagnostics.push_back(
        Diagnostic{Severity::Note, codes::kLeaderSkipped, {firstLine, 1, 0, file}, {std::to_string(lineNumber - 1)}});
  int tapeMarks = 0;  // '%' lines read so far
  while (pos < end) {
    // Line ends: LF, CRLF or CR. Lines are short: one pass over a line's bytes
    // finds its end (a memchr call or two per line cost more than the bytes).
    const char* lineEnd = pos;
    while (lineEnd < end && *lineEnd != '\n' && *lineEnd != '\r') ++lineEnd;
    const char* next = lineEnd < end ? lineEnd + 1 : end;
    // CRLF, and CR CR LF (a CRLF file converted once more), end one line.
    if (lineEnd < end && *lineEnd == '\r') {
      if (next < end && *next == '\n')
        ++next;
      else if (next + 1 < end && next[0] == '\r' && next[1] == '\n')
        next += 2;
    }
    const std::string_view line(pos, static_cast<std::size_t>(lineEnd - pos));
    parser.parseLine(line, lineNumber);
    ++program.lineCount;
    ++lineNumber;
    pos = next;
    // The closing '%' ends the tape: a control stops reading there, so what follows it (a note,
    // a DOS end-of-file byte) is counted, not read. Another '%' after it: more tapes, read on.
    if (startsWithTapeMark(line) && ++tapeMarks >= 2 && pos < end) {
      const std::string_view rest(pos, static_cast<std::size_t>(end - pos));
      if (holdsText(rest) && !holdsTapeMark(rest)) {
        const int lines = static_cast<int>(std::count(rest.begin(), rest.end(), '\n')) + (rest.back() != '\n' ? 1 : 0);
        program.lineCount += lines;
        program.lexicalDiagnostics.push_back(
            Diagnostic{Severity::Note,
                       codes::kTrailerSkipped,
                       {lineNumber, 1, 0, file},
                       {std::to_string(lineNumber), std::to_string(lineNumber + lines - 1)}});
        break;
      }
    }
  }
  return program;
}

void readAnglesWithoutComma(Program& program) {
  for (Block& block : program.blocks) {
    if (!block.mayHave('A') || block.findComma('A')) continue;
    for (Word& w : block.words)
      if (w.letter == 'A') w.comma = true;
  }
}

}  // namespace klueng::core::gcode
