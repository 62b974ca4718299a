#pragma once
// The number of a word exactly as written ("01", "-.5", "25.", "#101").
// A big program holds millions of words (issue 42 item 3): this is 8 bytes. Up to 7
// characters (nearly every number a CAM program writes: "-12.345") are kept inside;
// a longer text is a length-prefixed run of characters, either the number's own (on the
// heap) or borrowed from a store the parser keeps beside the words (Program::wordStores,
// alive as long as the program's words). A copy always owns its text; a move keeps it.
#include <bit>
#include <cstdint>
#include <cstring>
#include <iosfwd>
#include <string>
#include <string_view>

namespace klueng::core::gcode {

class WordNumber {
 public:
  static constexpr std::size_t npos = std::string_view::npos;
  static constexpr std::size_t kInlineCapacity = 7;

  WordNumber() = default;
  WordNumber(std::string_view text) { init(text); }  // NOLINT(google-explicit-constructor): reads like a string
  WordNumber(const WordNumber& o) { init(o.view()); }
  WordNumber(WordNumber&& o) noexcept : bits_(o.bits_) { o.bits_ = kEmpty; }
  WordNumber& operator=(const WordNumber& o) {
    if (this != &o) assign(o.view());
    return *this;
  }
  WordNumber& operator=(WordNumber&& o) noexcept {
    if (this != &o) {
      release();
      bits_ = o.bits_;
      o.bits_ = kEmpty;
    }
    return *this;
  }
  WordNumber& operator=(std::string_view text) {
    assign(text);
    return *this;
  }
  WordNumber& operator=(const std::string& text) { return *this = std::string_view(text); }
  WordNumber& operator=(const char* text) { return *this = std::string_view(text); }
  ~WordNumber() { release(); }

  // The text at `prefixed` (a 4-byte aligned std::uint32_t length, then the characters), kept by
  // the caller for as long as this number or its moves live (the parser's store).
  static WordNumber borrow(const char* prefixed) {
    WordNumber n;
    n.bits_ = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(prefixed)) | kBorrowedTag;
    return n;
  }

  // The lexer's case: a text of at most kInlineCapacity characters, kept inside (a byte at a time:
  // a call to memcpy for a few bytes cost more).
  void setShort(std::string_view text) {
    release();
    std::uint64_t bits = kInlineTag | (static_cast<std::uint64_t>(text.size()) << 2);
    for (std::size_t k = 0; k < text.size(); ++k)
      bits |= static_cast<std::uint64_t>(static_cast<unsigned char>(text[k])) << (8 * (k + 1));
    bits_ = bits;
  }

  void assign(std::string_view text) {
    // (text may point into this number: build the new value before freeing the old.)
    WordNumber fresh(text);
    *this = std::move(fresh);
  }
  WordNumber& operator+=(char c) {
    std::string s = str();
    s.push_back(c);
    assign(s);
    return *this;
  }

  const char* data() const {
    return isInline() ? reinterpret_cast<const char*>(&bits_) + 1 : pointer() + sizeof(std::uint32_t);
  }
  std::size_t size() const {
    if (isInline()) return static_cast<std::size_t>((bits_ >> 2) & 7u);
    std::uint32_t n = 0;
    std::memcpy(&n, pointer(), sizeof n);
    return n;
  }
  bool empty() const { return size() == 0; }
  std::string_view view() const { return {data(), size()}; }
  operator std::string_view() const { return view(); }  // NOLINT(google-explicit-constructor)
  std::string str() const { return std::string(view()); }

  char operator[](std::size_t i) const { return data()[i]; }
  char front() const { return data()[0]; }
  char back() const { return data()[size() - 1]; }
  const char* begin() const { return data(); }
  const char* end() const { return data() + size(); }
  std::size_t find(char c, std::size_t from = 0) const { return view().find(c, from); }
  std::size_t find(std::string_view s, std::size_t from = 0) const { return view().find(s, from); }
  std::string substr(std::size_t from, std::size_t count = npos) const {
    return std::string(view().substr(from, count));
  }

  friend bool operator==(const WordNumber& a, const WordNumber& b) { return a.view() == b.view(); }
  friend bool operator==(const WordNumber& a, std::string_view b) { return a.view() == b; }
  friend bool operator==(const WordNumber& a, const char* b) { return a.view() == b; }
  friend bool operator==(const WordNumber& a, const std::string& b) { return a.view() == b; }
  friend std::string operator+(char c, const WordNumber& n) { return std::string(1, c).append(n.view()); }
  friend std::string operator+(const char* s, const WordNumber& n) { return std::string(s).append(n.view()); }
  friend std::string operator+(std::string s, const WordNumber& n) { return s.append(n.view()); }
  friend std::string operator+(const WordNumber& n, std::string_view s) { return n.str().append(s); }
  friend std::ostream& operator<<(std::ostream& os, const WordNumber& n);

 private:
  // The low two bits say the form: 01 inside (the length in bits 2-4, the characters in bytes
  // 1-7), 00 owned (a pointer to new'd memory), 10 borrowed. (Little-endian: bytes 1-7 are the
  // high seven; x86, ARM and WebAssembly all are.)
  static_assert(std::endian::native == std::endian::little, "WordNumber keeps its characters in bytes 1-7");
  static constexpr std::uint64_t kInlineTag = 1;
  static constexpr std::uint64_t kBorrowedTag = 2;
  static constexpr std::uint64_t kTagMask = 3;
  static constexpr std::uint64_t kEmpty = kInlineTag;

  bool isInline() const { return (bits_ & kTagMask) == kInlineTag; }
  bool owns() const { return (bits_ & kTagMask) == 0; }
  const char* pointer() const { return reinterpret_cast<const char*>(static_cast<std::uintptr_t>(bits_ & ~kTagMask)); }
  void init(std::string_view text) {
    if (text.size() <= kInlineCapacity) {
      bits_ = kInlineTag | (static_cast<std::uint64_t>(text.size()) << 2);
      if (!text.empty()) std::memcpy(reinterpret_cast<char*>(&bits_) + 1, text.data(), text.size());
      return;
    }
    const auto n = static_cast<std::uint32_t>(text.size());  // a line is at most a few MB
    auto* p = static_cast<char*>(::operator new(sizeof n + text.size()));
    std::memcpy(p, &n, sizeof n);
    std::memcpy(p + sizeof n, text.data(), text.size());
    bits_ = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(p));
  }
  void release() {
    if (owns()) ::operator delete(const_cast<char*>(pointer()));
    bits_ = kEmpty;
  }

  std::uint64_t bits_ = kEmpty;
};

}  // namespace klueng::core::gcode
