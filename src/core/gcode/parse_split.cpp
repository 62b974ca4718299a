// gcode::parse: a big program is read as two halves on two threads and joined,
// giving exactly what one pass gives (blocks, line numbers, expression indices,
// lexical diagnostics and their E109 cut-off). Lines are independent of each
// other, so the only seams are the line numbers and the indices.
#include <algorithm>
#include <atomic>
#include <cstring>
#include <future>
#include <iterator>
#include <thread>

#include "diagnostic_codes.h"
#include "klueng/core/gcode/parser.h"
#include "parser_detail.h"

namespace klueng::core::gcode {

namespace {

std::atomic<std::size_t> parses{0};

// Below this a thread costs more than it saves (10k blocks are ~180 KB).
constexpr std::size_t kSplitBytes = 256 * 1024;

// Lines in text as parseLines counts them: LF, CRLF, CR, and CR CR LF end one line.
int lineCount(std::string_view text) {
  if (text.empty()) return 0;
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  if (!std::memchr(begin, '\r', text.size()))
    return static_cast<int>(std::count(begin, end, '\n')) + (text.back() == '\n' ? 0 : 1);
  int lines = 0;
  for (const char* pos = begin; pos < end; ++lines) {
    const char* lineEnd = pos;
    while (lineEnd < end && *lineEnd != '\n' && *lineEnd != '\r') ++lineEnd;
    const char* next = lineEnd < end ? lineEnd + 1 : end;
    if (lineEnd < end && *lineEnd == '\r') {
      if (next < end && *next == '\n') ++next;
      else if (next + 1 < end && next[0] == '\r' && next[1] == '\n') next += 2;
    }
    pos = next;
  }
  return lines;
}

// The second half's blocks, expressions and diagnostics after the first's.
void append(Program& into, Program&& tail) {
  const int shift = static_cast<int>(into.expressions.size());
  if (shift > 0 && !tail.expressions.empty()) {
    const auto moved = [shift](int& index) {
      if (index >= 0) index += shift;
    };
    for (Block& b : tail.blocks) {
      if (b.hasExpressions)
        for (Word& w : b.words) moved(w.expr);
      if (b.statement.kind != StatementKind::None) {
        moved(b.statement.condition);
        moved(b.statement.target);
        moved(b.statement.value);
      }
    }
  }
  into.blocks.insert(into.blocks.end(), std::make_move_iterator(tail.blocks.begin()),
                     std::make_move_iterator(tail.blocks.end()));
  into.expressions.insert(into.expressions.end(), std::make_move_iterator(tail.expressions.begin()),
                          std::make_move_iterator(tail.expressions.end()));
  into.lineCount += tail.lineCount;
  // One pass stops at kMaxLexicalDiagnostics, the last one replaced by E109 where it fell.
  auto& diags = into.lexicalDiagnostics;
  for (Diagnostic& d : tail.lexicalDiagnostics) {
    if (diags.size() >= codes::kMaxLexicalDiagnostics) break;
    if (diags.size() + 1 == codes::kMaxLexicalDiagnostics) {
      diags.push_back(Diagnostic{Severity::Error, codes::kTooManyLexicalErrors,
                                 {d.range.line, d.range.column, 0, d.range.file}, {}});
      break;
    }
    diags.push_back(std::move(d));
  }
}

}  // namespace

std::size_t parseCount() { return parses.load(std::memory_order_relaxed); }

Program parse(std::string_view text, int firstLine, int file) {
  parses.fetch_add(1, std::memory_order_relaxed);
  if (text.size() < kSplitBytes || std::thread::hardware_concurrency() < 2) return parseLines(text, firstLine, file);
  // Split just after a line feed near the middle: every LF ends a line (alone, or
  // closing CRLF or CR CR LF), so both halves see whole lines.
  const std::size_t lf = text.find('\n', text.size() / 2);
  if (lf == std::string_view::npos || lf + 1 >= text.size()) return parseLines(text, firstLine, file);
  const std::string_view head = text.substr(0, lf + 1), tail = text.substr(lf + 1);
  const int headLines = lineCount(head), tailFirstLine = firstLine + headLines;
  std::future<Program> second = std::async(std::launch::async, [&] { return parseLines(tail, tailFirstLine, file); });
  // The first half's block array has room for the second's: the join moves them in once.
  Program program = parseLines(head, firstLine, file, static_cast<std::size_t>(headLines + lineCount(tail)));
  append(program, second.get());
  return program;
}

}  // namespace klueng::core::gcode
