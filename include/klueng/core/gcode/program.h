#pragma once
// The parsed program: blocks of words, each with its source range. No modal
// knowledge lives here (that is the interpreter's job).
#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <iosfwd>
#include <iterator>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/word_number.h"

namespace klueng::core::gcode {

struct Word {
  // (Members ordered to avoid padding: a big program holds millions of words.)
  // (40 bytes: the flags and the digit count share the first eight with expr; the number is 8.)
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
static_assert(sizeof(void*) != 8 || sizeof(Word) == 40, "a Word is 40 bytes: big programs hold millions");

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
  bool then = false;      // IF ... THEN assignment (else IF ... GOTO)
  std::int16_t loop = 0;  // DO m / END m identifier (1-3) (16 bits: a Statement is 32 bytes, not 40)
  int condition = -1;     // expression index (Program::expressions)
  int target = -1;        // expression index of the variable number: #[#1+100] = ...
  int value = -1;         // expression index of the value or the GOTO target
  SourceRange range;      // the keyword (or the '#' of an assignment)
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

// The words of a block (a big program holds millions of blocks): a pointer and two 32-bit
// counts, 16 bytes, not std::vector's 24. The parser's blocks borrow their words from the
// program's word store (Program::wordStores: no allocation a block); a block copied, built by
// hand or changed in length owns its own. Reads like the std::vector<Word> it replaced
// (range-for, size, [], front, back, push_back).
class WordList {
 public:
  using value_type = Word;
  using iterator = Word*;
  using const_iterator = const Word*;

  WordList() = default;
  // Words kept elsewhere (a word store that outlives the list): read and changed in place, never freed here.
  static WordList borrow(Word* words, std::size_t n) {
    WordList list;
    list.data_ = n > 0 ? words : nullptr;
    list.size_ = static_cast<std::uint32_t>(n);
    return list;
  }
  WordList(std::initializer_list<Word> words) { assign(words.begin(), words.end()); }
  WordList(const std::vector<Word>& words) { assign(words.begin(), words.end()); }  // NOLINT: reads like one
  WordList(const WordList& o) { assign(o.begin(), o.end()); }
  WordList(WordList&& o) noexcept : data_(o.data_), size_(o.size_), capacity_(o.capacity_) {
    o.data_ = nullptr;
    o.size_ = o.capacity_ = 0;
  }
  WordList& operator=(const WordList& o) {
    if (this != &o) assign(o.begin(), o.end());
    return *this;
  }
  WordList& operator=(WordList&& o) noexcept {
    if (this != &o) {
      release();
      data_ = o.data_;
      size_ = o.size_;
      capacity_ = o.capacity_;
      o.data_ = nullptr;
      o.size_ = o.capacity_ = 0;
    }
    return *this;
  }
  WordList& operator=(std::initializer_list<Word> words) {
    assign(words.begin(), words.end());
    return *this;
  }
  ~WordList() { release(); }

  template <typename It>
  void assign(It first, It last) {
    WordList fresh;  // (first may point into this list)
    fresh.reserve(static_cast<std::size_t>(std::distance(first, last)));
    for (; first != last; ++first) fresh.push_back(*first);
    *this = std::move(fresh);
  }
  void reserve(std::size_t n) {
    if (n <= capacity_ && !borrowed()) return;
    n = std::max<std::size_t>(n, size_);
    Word* grown = std::allocator<Word>().allocate(n);
    if (borrowed()) {
      for (std::uint32_t k = 0; k < size_; ++k) new (grown + k) Word(data_[k]);  // the store keeps its own
    } else {
      for (std::uint32_t k = 0; k < size_; ++k) {
        new (grown + k) Word(std::move(data_[k]));
        data_[k].~Word();
      }
      if (data_) std::allocator<Word>().deallocate(data_, capacity_);
    }
    data_ = grown;
    capacity_ = static_cast<std::uint32_t>(n);
  }
  void push_back(const Word& w) { emplace_back(w); }
  void push_back(Word&& w) { emplace_back(std::move(w)); }
  template <typename... Args>
  Word& emplace_back(Args&&... args) {
    if (size_ == capacity_ || borrowed()) {
      Word made(std::forward<Args>(args)...);  // (args may name a word of this list)
      reserve(capacity_ == 0 ? 1 : std::size_t{capacity_} * 2);
      return *new (data_ + size_++) Word(std::move(made));
    }
    return *new (data_ + size_++) Word(std::forward<Args>(args)...);
  }
  void pop_back() {
    --size_;
    if (!borrowed()) data_[size_].~Word();
    if (size_ == 0 && borrowed()) data_ = nullptr;
  }
  void clear() {
    while (size_ > 0) pop_back();
  }
  iterator erase(const_iterator at) {
    const auto k = static_cast<std::size_t>(at - data_);
    if (borrowed()) reserve(size_);
    for (std::size_t i = k; i + 1 < size_; ++i) data_[i] = std::move(data_[i + 1]);
    pop_back();
    return data_ + k;
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  Word* data() { return data_; }
  const Word* data() const { return data_; }
  Word* begin() { return data_; }
  Word* end() { return data_ + size_; }
  const Word* begin() const { return data_; }
  const Word* end() const { return data_ + size_; }
  Word& operator[](std::size_t i) { return data_[i]; }
  const Word& operator[](std::size_t i) const { return data_[i]; }
  Word& at(std::size_t i) {
    if (i >= size_) throw std::out_of_range("WordList::at");
    return data_[i];
  }
  const Word& at(std::size_t i) const {
    if (i >= size_) throw std::out_of_range("WordList::at");
    return data_[i];
  }
  Word& front() { return data_[0]; }
  const Word& front() const { return data_[0]; }
  Word& back() { return data_[size_ - 1]; }
  const Word& back() const { return data_[size_ - 1]; }

 private:
  bool borrowed() const { return capacity_ == 0 && data_ != nullptr; }
  void release() {
    clear();
    if (data_ && capacity_ > 0) std::allocator<Word>().deallocate(data_, capacity_);
    data_ = nullptr;
    size_ = 0;
    capacity_ = 0;
  }
  Word* data_ = nullptr;
  std::uint32_t size_ = 0;
  std::uint32_t capacity_ = 0;
};

// What few blocks have: their comments (joined by a space) and a macro statement. A block keeps
// one pointer to them (8 bytes, not a std::string's 32 and a Statement's 32), null for most.
class BlockNotes {
 public:
  BlockNotes() = default;
  BlockNotes(const BlockNotes& o) : data_(o.data_ ? std::make_unique<Data>(*o.data_) : nullptr) {}
  BlockNotes(BlockNotes&&) noexcept = default;
  BlockNotes& operator=(const BlockNotes& o) {
    if (this == &o) return *this;
    if (!o.data_)
      data_.reset();
    else if (data_)
      *data_ = *o.data_;
    else
      data_ = std::make_unique<Data>(*o.data_);
    return *this;
  }
  BlockNotes& operator=(BlockNotes&&) noexcept = default;
  ~BlockNotes() = default;

  std::string_view comment() const { return data_ ? std::string_view(data_->comment) : std::string_view(); }
  std::string& editComment() { return data().comment; }
  const Statement& statement() const { return data_ ? data_->statement : kNone; }
  Statement& editStatement() { return data().statement; }

 private:
  struct Data {
    std::string comment;
    Statement statement;
  };
  Data& data() {
    if (!data_) data_ = std::make_unique<Data>();
    return *data_;
  }
  static constexpr Statement kNone{};
  std::unique_ptr<Data> data_;
};

// (A block is 40 bytes, not 112: a big program holds millions, issue 42 item 3.)
struct Block {
  WordList words;               // in source order
  BlockNotes notes;             // its comments and macro statement (comment(), statement())
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

  // Text of its ( ) and ; comments, joined by a space ("" when none).
  std::string_view comment() const { return notes.comment(); }
  // Its macro statement (kind None for an NC block).
  const Statement& statement() const { return notes.statement(); }
  // For the parser and the loaders that change them (the first call makes room for the notes).
  Statement& editStatement() { return notes.editStatement(); }
  std::string& editComment() { return notes.editComment(); }

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
    LetterWords(const WordList& words, char letter, bool present) : words_(words), letter_(letter), present_(present) {}
    iterator begin() const {
      const Word* end = words_.data() + words_.size();
      return {present_ ? words_.data() : end, end, letter_};
    }
    iterator end() const { return {words_.data() + words_.size(), words_.data() + words_.size(), letter_}; }

   private:
    const WordList& words_;
    char letter_;
    bool present_;
  };
  LetterWords all(char letter) const { return LetterWords(words, letter, mayHave(letter)); }
};
// (On a 64-bit build: the WebAssembly build's 32-bit pointers make it smaller.)
static_assert(sizeof(void*) != 8 || sizeof(Block) == 40, "a Block is 40 bytes: big programs hold millions");

struct Program {
  std::vector<Block> blocks;  // only lines with words; blank, comment-only and % lines are dropped
  // Where the parsed blocks' words live (WordList::borrow): kept while any block of the program
  // may read them, also by a program the blocks were moved into (attachSubprogramFiles).
  std::vector<std::shared_ptr<void>> wordStores;
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
