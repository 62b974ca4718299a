#pragma once
// The number of a word exactly as written ("01", "-.5", "25.", "#101").
// A big program holds millions of words, and std::string's 32 bytes were half
// of each: this keeps up to 15 characters in 16 bytes, and a longer text
// (a line may hold a 4,000-digit number) on the heap.
#include <cstdint>
#include <cstring>
#include <iosfwd>
#include <string>
#include <string_view>

namespace klueng::core::gcode {

class WordNumber {
 public:
  static constexpr std::size_t npos = std::string_view::npos;

  WordNumber() { clearInline(); }
  WordNumber(std::string_view text) { init(text); }  // NOLINT(google-explicit-constructor): reads like a string
  WordNumber(const WordNumber& o) { init(o.view()); }
  WordNumber(WordNumber&& o) noexcept {
    std::memcpy(buf_, o.buf_, sizeof buf_);
    o.clearInline();
  }
  WordNumber& operator=(const WordNumber& o) {
    if (this != &o) assign(o.view());
    return *this;
  }
  WordNumber& operator=(WordNumber&& o) noexcept {
    if (this != &o) {
      release();
      std::memcpy(buf_, o.buf_, sizeof buf_);
      o.clearInline();
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

  void assign(std::string_view text) {
    if (!onHeap() && text.size() <= kInlineCapacity) {
      // The lexer's case: stays inside (memmove: text may be this number's own).
      if (!text.empty()) std::memmove(buf_, text.data(), text.size());
      buf_[kTag] = static_cast<char>(text.size());
      return;
    }
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

  const char* data() const { return onHeap() ? heapPointer() : buf_; }
  std::size_t size() const { return onHeap() ? heapSize() : static_cast<unsigned char>(buf_[kTag]); }
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
  static constexpr std::size_t kTag = 15;  // inline: the length; 0xFF: on the heap
  static constexpr unsigned char kHeapTag = 0xFF;
  static constexpr std::size_t kInlineCapacity = 15;

  bool onHeap() const { return static_cast<unsigned char>(buf_[kTag]) == kHeapTag; }
  char* heapPointer() const {
    char* p = nullptr;
    std::memcpy(&p, buf_, sizeof p);
    return p;
  }
  std::size_t heapSize() const {
    std::uint32_t n = 0;
    std::memcpy(&n, buf_ + sizeof(char*), sizeof n);
    return n;
  }
  void clearInline() { std::memset(buf_, 0, sizeof buf_); }
  void init(std::string_view text) {
    clearInline();
    if (text.size() <= kInlineCapacity) {
      if (!text.empty()) std::memcpy(buf_, text.data(), text.size());
      buf_[kTag] = static_cast<char>(text.size());
      return;
    }
    char* p = new char[text.size()];
    std::memcpy(p, text.data(), text.size());
    const auto n = static_cast<std::uint32_t>(text.size());  // a line is at most a few MB
    std::memcpy(buf_, &p, sizeof p);
    std::memcpy(buf_ + sizeof p, &n, sizeof n);
    buf_[kTag] = static_cast<char>(kHeapTag);
  }
  void release() {
    if (onHeap()) delete[] heapPointer();
    clearInline();
  }

  alignas(8) char buf_[16];
};

}  // namespace klueng::core::gcode
