#include "klueng/core/io/program_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/text_util.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/file_read.h"
#include "klueng/core/io/file_write.h"
#include "klueng/core/io/text_encoding.h"
#include "klueng/core/messages.h"

namespace klueng::core::io {

namespace {

using detail::makeDiagnostic;

constexpr int kHeaderLines = 6;

bool isAsciiDigit(char c) { return c >= '0' && c <= '9'; }

// SPEC 2 (ext): a first line starting with % ( ; or an address letter O N G M T
// followed at once by a number is G-code. "Grammar demo" or "Mild steel" are
// header lines even though they start with G or M.
bool looksLikeGcode(std::string_view firstLine) {
  const std::string_view s = detail::trim(firstLine);
  if (s.empty()) return false;
  const char c = s.front();
  if (c == '%' || c == '(' || c == ';') return true;
  const char upper = (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
  if (upper != 'O' && upper != 'N' && upper != 'G' && upper != 'M' && upper != 'T') return false;
  if (s.size() < 2) return false;
  std::string_view rest = s.substr(1);
  if (rest.front() == '-' || rest.front() == '+') rest.remove_prefix(1);
  return !rest.empty() &&
         (isAsciiDigit(rest.front()) || (rest.front() == '.' && rest.size() > 1 && isAsciiDigit(rest[1])));
}

struct SizeCodes {
  const char* missing;
  const char* badUnit;
  const char* badNumber;
};

// A unit digit (0 = inch, 1 = mm) followed at once by a number; line 4 may add
// `x` and a bore number. The number may be <= 0 (that is E213, not G-code).
bool isUnitDigitSize(std::string_view line, bool allowBore) {
  const std::string_view field = detail::trim(line);
  if (field.size() < 2 || (field.front() != '0' && field.front() != '1')) return false;
  std::string_view number = field.substr(1);
  if (allowBore) {
    const std::size_t x = number.find_first_of("xX");
    if (x != std::string_view::npos) {
      if (!detail::parseNumber(detail::trim(number.substr(x + 1)))) return false;
      number = detail::trim(number.substr(0, x));
    }
  }
  return detail::parseNumber(number).has_value();
}

// Reads "150" (unit digit 1 = mm, then 50) from header line 4 or 5; the caller
// has checked the form with isUnitDigitSize.
void parseStockSize(std::string_view line, int lineNumber, const SizeCodes& codes, const std::string& fileName,
                    double& value, LengthUnit& unit, std::vector<Diagnostic>& diags) {
  const std::string_view field = detail::trim(line);
  if (field.empty()) {
    diags.push_back(makeDiagnostic(Severity::Error, codes.missing, lineNumber, 1, 0, {fileName}));
    return;
  }
  const int fieldColumn = detail::columnOf(line, field);
  const int fieldLength = utf8Length(field);
  if (field.front() != '0' && field.front() != '1') {
    // Quote the whole first character, which may be a Thai letter.
    const auto lead = static_cast<unsigned char>(field.front());
    const std::size_t bytesOfFirst = lead < 0xC0 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
    const std::string_view first = field.substr(0, bytesOfFirst);
    diags.push_back(
        makeDiagnostic(Severity::Error, codes.badUnit, lineNumber, fieldColumn, 1, {fileName, std::string(first)}));
    return;
  }
  const std::string_view number = field.substr(1);
  const std::optional<double> parsed = detail::parseNumber(number);
  if (!parsed) {
    diags.push_back(makeDiagnostic(Severity::Error, codes.badNumber, lineNumber, fieldColumn + 1, utf8Length(number),
                                   {fileName, std::string(number)}));
    return;
  }
  if (*parsed <= 0.0) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kStockSizeNotPositive, lineNumber, fieldColumn, fieldLength,
                                   {fileName, std::string(number), std::string(field)}));
    return;
  }
  // A bar no lathe holds (1e308 took minutes to draw and measured "nan"): as Job details and --stock bound it.
  constexpr double kLargestStock = 9999.999;
  if (*parsed > kLargestStock) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kStockSizeTooLarge, lineNumber, fieldColumn + 1,
                                   utf8Length(number), {fileName, std::string(number), "9999.999"}));
    return;
  }
  unit = field.front() == '0' ? LengthUnit::Inch : LengthUnit::Millimetre;
  value = *parsed;
}

// Line 4: "1118x90" = diameter 118 with a 90 bore; "150" = solid bar.
void parseDiameterLine(std::string_view line, const std::string& fileName, JobHeader& h,
                       std::vector<Diagnostic>& diags) {
  const std::size_t x = line.find_first_of("xX");
  h.bore = 0.0;
  if (x == std::string_view::npos) {
    parseStockSize(line, 4, {codes::kDiameterMissing, codes::kDiameterUnitDigit, codes::kDiameterNotNumber}, fileName,
                   h.diameter, h.diameterUnit, diags);
    return;
  }
  const std::size_t before = diags.size();
  parseStockSize(line.substr(0, x), 4, {codes::kDiameterMissing, codes::kDiameterUnitDigit, codes::kDiameterNotNumber},
                 fileName, h.diameter, h.diameterUnit, diags);
  const std::string_view boreText = detail::trim(line.substr(x + 1));
  const double bore = detail::parseNumber(boreText).value_or(0.0);
  if (diags.size() != before) return;
  if (!(bore > 0.0) || bore >= h.diameter) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kBadBore, 4, detail::columnOf(line, boreText),
                                   utf8Length(boreText),
                                   {fileName, std::string(boreText), detail::formatNumber(h.diameter)}));
    return;
  }
  h.bore = bore;
}

// A no-break space in front of a header text that would read as G-code
// ("M10 bolt", "G1 shaft", "%"), so the file stays a header file; the reader drops it.
constexpr std::string_view kHeaderTextMark = "\xC2\xA0";

std::string oneLine(std::string_view text) {
  std::string s(text);
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

std::string formatStockSize(double value, LengthUnit unit) {
  return (unit == LengthUnit::Inch ? "0" : "1") + detail::formatNumber(value);
}

// SPEC 2 (ext): lines 4 and 5 are sizes and lines 1-3 and 6 are not G-code.
bool isKluengHeader(const std::vector<std::string_view>& lines) {
  if (lines.size() < 5) return false;
  if (!isUnitDigitSize(lines[3], true) || !isUnitDigitSize(lines[4], false)) return false;
  for (const std::size_t i : {0u, 1u, 2u, 5u})
    if (i < lines.size() && looksLikeGcode(lines[i])) return false;
  return true;
}

// A plain file whose first line is text and whose line 4 or 5 starts with a
// digit was probably meant to have a header: say which line is not a size.
void hintBrokenHeader(const std::vector<std::string_view>& lines, const std::string& fileName,
                      std::vector<Diagnostic>& diags) {
  if (lines.size() < 5 || detail::trim(lines[0]).empty() || looksLikeGcode(lines[0])) return;
  for (const int n : {4, 5}) {
    const std::string_view field = detail::trim(lines[static_cast<std::size_t>(n - 1)]);
    if (field.empty() || !isAsciiDigit(field.front()) || isUnitDigitSize(field, n == 4)) continue;
    diags.push_back(makeDiagnostic(Severity::Warning, codes::kPlainGcodeFile, n, detail::columnOf(lines[n - 1], field),
                                   utf8Length(field), {fileName, std::string(field), std::to_string(n)}));
    return;
  }
}

// ---- the machine a program names (issue 27) ----

// One comment of a head line: its byte range in the line and its text.
struct HeadComment {
  std::size_t begin = 0, end = 0;  // [begin, end) in the line, the brackets or ';' included
  std::string_view text;
};

char upperAscii(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

// A line of a program's head: blank, '%', a comment alone, or an O (or ':')
// program number with an optional comment. Its comment, if any.
bool headLine(std::string_view line, std::optional<HeadComment>& comment, bool& programStart) {
  comment.reset();
  const std::string_view s = detail::trim(line);
  programStart = false;
  if (s.empty()) return true;
  const std::size_t at = static_cast<std::size_t>(s.data() - line.data());
  std::size_t rest = 0;  // where a comment may start, in s
  if (s.front() == '%') {
    programStart = true;
    rest = 1;
  } else if ((upperAscii(s.front()) == 'O' || s.front() == ':') && s.size() > 1 && isAsciiDigit(s[1])) {
    programStart = true;
    rest = 1;
    while (rest < s.size() && isAsciiDigit(s[rest])) ++rest;
  }
  while (rest < s.size() && (s[rest] == ' ' || s[rest] == '\t')) ++rest;
  if (rest == s.size()) return true;
  if (s[rest] == ';') {
    comment = HeadComment{at + rest, line.size(), s.substr(rest + 1)};
    return true;
  }
  if (s[rest] != '(') return false;
  const std::size_t close = s.rfind(')');
  if (close == std::string_view::npos || close < rest || close + 1 != s.size()) return false;
  comment = HeadComment{at + rest, at + close + 1, s.substr(rest + 1, close - rest - 1)};
  return true;
}

// "MACHINE: romi-gl240m" -> the id and its offset in `text`; nullopt for any other comment.
// `word` is the key ("MACHINE", "OFFSETS"), any case, then ':', '=' or blanks, then one value.
std::optional<std::pair<std::string_view, std::size_t>> keyComment(std::string_view text, std::string_view kWord) {
  const std::string_view t = detail::trim(text);
  if (t.size() <= kWord.size()) return std::nullopt;
  for (std::size_t i = 0; i < kWord.size(); ++i)
    if (upperAscii(t[i]) != kWord[i]) return std::nullopt;
  std::size_t i = kWord.size();
  if (t[i] != ':' && t[i] != '=' && t[i] != ' ' && t[i] != '\t') return std::nullopt;
  while (i < t.size() && (t[i] == ':' || t[i] == '=' || t[i] == ' ' || t[i] == '\t')) ++i;
  std::size_t end = i;
  while (end < t.size() && t[end] != ' ' && t[end] != '\t') ++end;
  if (end == i) return std::nullopt;
  return std::pair{t.substr(i, end - i), static_cast<std::size_t>(t.data() - text.data()) + i};
}

struct MachineLineAt {
  NamedMachine named;
  std::size_t lineIndex = 0;
  HeadComment comment;
};

std::optional<MachineLineAt> findMachineLine(const std::vector<std::string_view>& lines) {
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::optional<HeadComment> comment;
    bool programStart = false;
    if (!headLine(lines[i], comment, programStart)) break;
    if (!comment) continue;
    const auto id = keyComment(comment->text, "MACHINE");
    if (!id) continue;
    const std::size_t offset = static_cast<std::size_t>(comment->text.data() - lines[i].data()) + id->second;
    MachineLineAt at;
    at.named =
        NamedMachine{std::string(id->first), static_cast<int>(i) + 1, utf8Length(lines[i].substr(0, offset)) + 1};
    at.lineIndex = i;
    at.comment = *comment;
    return at;
  }
  return std::nullopt;
}

// detail::splitLines' lines of `text` up to and including the first that is not a head line:
// all that the head's readers look at (a long program's other lines would cost a split each read).
std::vector<std::string_view> headLines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t i = text.find_first_of("\r\n", start);
    if (i == std::string_view::npos) {
      lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, i - start));
    // CRLF is one line end; so is CR CR LF (as splitLines reads them).
    if (text[i] == '\r' && i + 2 < text.size() && text[i + 1] == '\r' && text[i + 2] == '\n') i += 1;
    if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    start = i + 1;
    std::optional<HeadComment> comment;
    bool programStart = false;
    if (!headLine(lines.back(), comment, programStart)) break;
  }
  return lines;
}

}  // namespace

int offsetsUnknownIn(std::string_view gcode) {
  const std::vector<std::string_view> lines = headLines(gcode);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::optional<HeadComment> comment;
    bool programStart = false;
    if (!headLine(lines[i], comment, programStart)) break;
    if (!comment) continue;
    const auto value = keyComment(comment->text, "OFFSETS");
    if (!value || value->first.size() != 7) continue;
    std::string upper;
    for (char c : value->first) upper.push_back(upperAscii(c));
    // Only what the comment says alone: "(OFFSETS: UNKNOWN T1 T2)" is not the key.
    if (upper == "UNKNOWN" && detail::trim(comment->text.substr(value->second + 7)).empty())
      return static_cast<int>(i) + 1;
  }
  return 0;
}

std::optional<NamedMachine> machineNamedIn(std::string_view gcode) {
  const std::optional<MachineLineAt> at = findMachineLine(headLines(gcode));
  if (!at) return std::nullopt;
  return at->named;
}

std::string withMachineNamed(std::string_view gcode, std::string_view id) {
  const std::vector<std::string_view> lines = detail::splitLines(gcode);
  const std::string comment = id.empty() ? std::string() : "(MACHINE: " + std::string(id) + ")";
  const auto offsetOf = [&](std::size_t i) {
    return i < lines.size() ? static_cast<std::size_t>(lines[i].data() - gcode.data()) : gcode.size();
  };
  if (const std::optional<MachineLineAt> at = findMachineLine(lines)) {
    const std::size_t lineAt = offsetOf(at->lineIndex);
    std::string line(lines[at->lineIndex]);
    line.replace(at->comment.begin, at->comment.end - at->comment.begin, comment);
    std::string out(gcode.substr(0, lineAt));
    if (!detail::trim(line).empty()) {
      // An O line keeps its number; a line of its own becomes the comment alone.
      out += line;
    } else {
      // Taken out: the line and its line end go.
      std::size_t next = lineAt + lines[at->lineIndex].size();
      if (next < gcode.size() && gcode[next] == '\r') ++next;
      if (next < gcode.size() && gcode[next] == '\n') ++next;
      out += gcode.substr(next);
      return out;
    }
    out += gcode.substr(lineAt + lines[at->lineIndex].size());
    return out;
  }
  if (id.empty()) return std::string(gcode);
  // After the head's '%' and O line: the program number stays the first block.
  std::size_t insertAt = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::optional<HeadComment> c;
    bool programStart = false;
    if (!headLine(lines[i], c, programStart)) break;
    if (programStart) insertAt = i + 1;
  }
  const std::size_t at = offsetOf(insertAt);
  std::string out(gcode.substr(0, at));
  if (!out.empty() && out.back() != '\n') out += '\n';
  out += comment;
  out += '\n';
  out += gcode.substr(at);
  return out;
}

namespace {}  // namespace

std::string stockSizeText(const JobHeader& h) {
  const bool sameUnit = h.diameterUnit == h.lengthUnit;
  const bool inch = sameUnit && h.diameterUnit == LengthUnit::Inch;
  const double d = inch ? h.diameter : h.diameterMm();
  const double bore = inch ? h.bore : h.boreMm();
  const double len = inch ? h.length : h.lengthMm();
  std::string s = "\xC3\x98" + detail::formatNumber(d);
  if (bore > 0.0) s += "/\xC3\x98" + detail::formatNumber(bore);
  s += " x " + detail::formatNumber(len) + (inch ? " in" : " mm");
  return s;
}

namespace {

// The lines parseProgramFile reads: with LF line ends and no line over the limit (nearly every
// program), only the first few, which hold the header, since the G-code part is then the text
// itself (a table of every line of a 100,000-line program cost a pass and 1.6 MB); else all.
// (Every question asked of the lines' count, up to the header's six, has the same answer.)
std::vector<std::string_view> headOrAllLines(std::string_view text) {
  constexpr std::size_t kHead = 8;
  if (text.find('\r') != std::string_view::npos) return detail::splitLines(text);
  std::vector<std::string_view> head;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    if (end - start > static_cast<std::size_t>(detail::kMaxLineChars)) return detail::splitLines(text);
    if (head.size() < kHead) head.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return head;
}

}  // namespace

ReadResult<ProgramFile> parseProgramFile(std::string_view bytes, const JobHeader& defaultsForPlain,
                                         const std::string& fileName) {
  ReadResult<ProgramFile> result;
  auto& diags = result.diagnostics;
  if (bytes.size() > detail::kMaxFileBytes) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kFileTooLarge, 0, 0, 0,
                                   {fileName, std::to_string(bytes.size()), sizeLimitText(detail::kMaxFileBytes)}));
    return result;
  }
  // UTF-16 text (Notepad's "Unicode") is text, not binary: read it as UTF-8.
  std::string fromUtf16;
  std::optional<detail::BytePosition> nul = detail::findNulByte(bytes);
  if (bytes.size() >= 2 &&
      (nul || static_cast<unsigned char>(bytes[0]) == 0xFF || static_cast<unsigned char>(bytes[0]) == 0xFE)) {
    if (std::optional<std::string> utf8 = utf16ToUtf8(bytes)) {
      fromUtf16 = std::move(*utf8);
      bytes = fromUtf16;
      nul = detail::findNulByte(bytes);
    }
  }
  if (nul) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kBinaryFile, nul->line, nul->column, 1, {fileName}));
    return result;
  }

  ProgramFile file;
  file.header = defaultsForPlain;
  std::string fromTis620;
  const std::string_view text = detail::decodeTextView(bytes, fromTis620, &file.encoding);
  std::vector<std::string_view> lines = headOrAllLines(text);

  if (lines.empty()) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kEmptyFile, 1, 1, 0, {fileName}));
    file.plainGcode = true;
    file.gcodeFirstLine = 1;
    result.value = std::move(file);
    return result;
  }

  // A 10 MB line is not a program line: report it once and read it as empty,
  // instead of handing the parser millions of words.
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].size() <= static_cast<std::size_t>(detail::kMaxLineChars)) continue;
    const int chars = utf8Length(lines[i]);
    if (chars <= detail::kMaxLineChars) continue;
    diags.push_back(makeDiagnostic(Severity::Error, codes::kLineTooLong, static_cast<int>(i) + 1, 1, 0,
                                   {fileName, std::to_string(chars), std::to_string(detail::kMaxLineChars)}));
    lines[i] = std::string_view();
  }

  std::size_t firstCodeLine = 0;
  if (!isKluengHeader(lines)) {
    file.plainGcode = true;
    file.gcodeFirstLine = 1;
    hintBrokenHeader(lines, fileName, diags);
  } else {
    file.header.stockSource = StockSource::Header;
    file.plainGcode = false;
    file.gcodeFirstLine = kHeaderLines + 1;
    firstCodeLine = kHeaderLines;
    const auto headerLine = [&](int n) -> std::string_view {
      return static_cast<std::size_t>(n) <= lines.size() ? lines[n - 1] : std::string_view();
    };
    const auto text = [&](int n) {
      std::string_view field = detail::trim(headerLine(n));
      if (field.starts_with(kHeaderTextMark)) field.remove_prefix(kHeaderTextMark.size());
      return std::string(field);
    };
    file.header.project = text(1);
    file.header.part = text(2);
    file.header.material = text(3);
    file.header.programmer = text(6);
    if (lines.size() < static_cast<std::size_t>(kHeaderLines)) {
      const int last = static_cast<int>(lines.size());
      diags.push_back(makeDiagnostic(Severity::Error, codes::kHeaderTooShort, last, utf8Length(lines.back()) + 1, 0,
                                     {fileName, std::to_string(last)}));
    }
    parseDiameterLine(lines[3], fileName, file.header, diags);
    parseStockSize(lines[4], 5, {codes::kLengthMissing, codes::kLengthUnitDigit, codes::kLengthNotNumber}, fileName,
                   file.header.length, file.header.lengthUnit, diags);
  }

  // The G-code part, with every line end normalised to '\n'. With LF line
  // ends and no blanked line the text after the header is already that.
  std::string& code = file.gcode;
  const bool plainLf =
      text.find('\r') == std::string::npos &&
      std::none_of(diags.begin(), diags.end(), [](const Diagnostic& d) { return d.code == codes::kLineTooLong; });
  const auto nameMachine = [&file] {
    // The machine is the program's own: never a default's.
    file.header.machine.clear();
    file.header.machineLine = 0;
    const int unknownAt = offsetsUnknownIn(file.gcode);
    file.header.offsetsUnknownLine = unknownAt > 0 ? file.gcodeFirstLine + unknownAt - 1 : 0;
    if (const std::optional<NamedMachine> named = machineNamedIn(file.gcode)) {
      file.header.machine = named->id;
      file.header.machineLine = file.gcodeFirstLine + named->line - 1;
    }
  };
  if (plainLf) {
    if (firstCodeLine < lines.size())
      code.assign(text.substr(static_cast<std::size_t>(lines[firstCodeLine].data() - text.data())));
    nameMachine();
    result.value = std::move(file);
    return result;
  }
  for (std::size_t i = firstCodeLine; i < lines.size(); ++i) {
    code.append(lines[i]);
    if (i + 1 < lines.size() || detail::endsWithLineBreak(text)) code.push_back('\n');
  }
  nameMachine();
  result.value = std::move(file);
  return result;
}

ReadResult<ProgramFile> readProgramFile(const std::string& path, const JobHeader& defaultsForPlain) {
  ReadResult<ProgramFile> result;
  std::optional<std::string> bytes = detail::readFileBytes(path, result.diagnostics);
  if (!bytes) return result;
  return parseProgramFile(*bytes, defaultsForPlain, path);
}

std::string headerText(std::string_view text) {
  const std::string line = oneLine(text);
  return looksLikeGcode(line) ? std::string(kHeaderTextMark) + line : line;
}

std::string formatProgramFile(const ProgramFile& file) {
  if (file.plainGcode) return file.gcode;
  const JobHeader& h = file.header;
  std::string out;
  out.reserve(file.gcode.size() + 256);
  for (const std::string& line :
       {headerText(h.project), headerText(h.part), headerText(h.material),
        formatStockSize(h.diameter, h.diameterUnit) + (h.bore > 0.0 ? "x" + detail::formatNumber(h.bore) : ""),
        formatStockSize(h.length, h.lengthUnit), headerText(h.programmer)}) {
    out += line;
    out += '\n';
  }
  out += file.gcode;
  return out;
}

bool writeTextFileAtomic(const std::string& path, std::string_view text, std::string* error) {
  const std::optional<Diagnostic> failed = writeFileAtomic(path, text);
  if (failed && error) *error = formatMessage(*failed, Lang::En);
  return !failed;
}

bool isProgramFileName(std::string_view path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".txt" || ext == ".nc" || ext == ".cnc" || ext == ".tap" || ext == ".ngc" || ext == ".gcode";
}

}  // namespace klueng::core::io
