// Reading a machine file's profile keys (machine_file.h, docs/dialects.md).
#include "klueng/core/gcode/machine_file.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <map>

#include "code_index.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::gcode {

namespace {

enum class Type : std::uint8_t { Whole, Real, Flag, Choice, Text, Numbers, Letters };

struct Value {
  double number = 0.0;
  int choice = 0;
  std::string_view text;
  std::vector<int> numbers;
};

using Setter = void (*)(MachineDefinition&, const Value&);

struct Key {
  std::string_view name;
  Type type;
  double min = 0.0, max = 0.0;    // Whole, Real; Numbers: each number
  std::string_view choices = {};  // Choice: "a|b|c", the enum's order
  Setter set = nullptr;
};

#define KLUENG_SET(expr) [](MachineDefinition& m, const Value& v) { expr; }
#define KLUENG_P m.profile
using VI = int;

// Every profile key. Names and meanings: docs/dialects.md, "Machine files".
const Key kKeys[] = {
    {"id", Type::Text, 0, 0, {}, KLUENG_SET(m.id = std::string(v.text))},
    {"name_en", Type::Text, 0, 0, {}, KLUENG_SET(m.nameEn = std::string(v.text))},
    {"name_th", Type::Text, 0, 0, {}, KLUENG_SET(m.nameTh = std::string(v.text))},
    {"family", Type::Choice, 0, 0, "fanuc|haas|classic", KLUENG_SET(KLUENG_P.family = static_cast<Dialect>(v.choice))},
    {"gcode_system", Type::Choice, 0, 0, "A|B|C", KLUENG_SET(KLUENG_P.system = static_cast<GcodeSystem>(v.choice))},
    {"letters", Type::Letters, 0, 0, {}, KLUENG_SET(m.letters = std::string(v.text))},
    {"program_number_max",
     Type::Whole,
     1,
     99999999,
     {},
     KLUENG_SET(KLUENG_P.programNumberMax = static_cast<VI>(v.number))},
    {"colon_program_number", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.colonProgramNumber = v.number != 0.0)},
    {"sequence_number_max",
     Type::Whole,
     1,
     99999,
     {},
     KLUENG_SET(KLUENG_P.sequenceNumberMax = static_cast<VI>(v.number))},
    {"decimals_mm", Type::Whole, 0, 4, {}, KLUENG_SET(KLUENG_P.decimalsMm = static_cast<VI>(v.number))},
    {"decimals_inch", Type::Whole, 0, 5, {}, KLUENG_SET(KLUENG_P.decimalsInch = static_cast<VI>(v.number))},
    {"max_abs_mm", Type::Real, 1, 99999999, {}, KLUENG_SET(KLUENG_P.maxAbsMm = v.number)},
    {"max_abs_inch", Type::Real, 1, 99999999, {}, KLUENG_SET(KLUENG_P.maxAbsInch = v.number)},
    {"min_positive_mm", Type::Real, 0.00001, 1, {}, KLUENG_SET(KLUENG_P.minPositiveMm = v.number)},
    {"min_positive_inch", Type::Real, 0.000001, 1, {}, KLUENG_SET(KLUENG_P.minPositiveInch = v.number)},
    {"extra_decimals", Type::Choice, 0, 0, "error|round_with_warning",
     KLUENG_SET(KLUENG_P.extraDecimals = static_cast<ExtraDecimals>(v.choice))},
    {"power_on_units", Type::Choice, 0, 0, "mm|inch",
     KLUENG_SET(KLUENG_P.powerOnUnits = static_cast<InputUnits>(v.choice))},
    {"min_tool_digits", Type::Whole, 1, 4, {}, KLUENG_SET(KLUENG_P.minToolDigits = static_cast<VI>(v.number))},
    {"max_tool_station", Type::Whole, 0, 24, {}, KLUENG_SET(KLUENG_P.maxToolStation = static_cast<VI>(v.number))},
    {"max_offset", Type::Whole, 1, 99, {}, KLUENG_SET(KLUENG_P.maxOffset = static_cast<VI>(v.number))},
    {"tool_zero_keeps_turret", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.toolZeroKeepsTurret = v.number != 0.0)},
    {"dwell_p", Type::Choice, 0, 0, "ms|seconds_with_point",
     KLUENG_SET(KLUENG_P.dwellP = static_cast<DwellPUnit>(v.choice))},
    {"bare_g28", Type::Choice, 0, 0, "error|no_motion|home_all_axes",
     KLUENG_SET(KLUENG_P.bareG28 = static_cast<BareG28>(v.choice))},
    {"thread_under_css_is_alarm", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.threadUnderCssIsAlarm = v.number != 0.0)},
    {"one_shots_with_motion", Type::Numbers, 0, 99, {}, KLUENG_SET(m.oneShots = v.numbers)},
    {"cycle_form", Type::Choice, 0, 0, "two_block|one_block",
     KLUENG_SET(KLUENG_P.cycleForm = static_cast<CycleForm>(v.choice))},
    {"unknown_m", Type::Choice, 0, 0, "error|warning", KLUENG_SET(KLUENG_P.unknownMIsWarning = v.choice == 1)},
    {"high_m", Type::Choice, 0, 0, "error|warning", KLUENG_SET(KLUENG_P.highMIsWarning = v.choice == 1)},
    {"blanks_in_words", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.blanksInWords = v.number != 0.0)},
    {"comment_to_line_end", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.commentToLineEnd = v.number != 0.0)},
    {"semicolon_ends_block", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.semicolonEndsBlock = v.number != 0.0)},
    {"comment_ends_at_first_paren",
     Type::Flag,
     0,
     0,
     {},
     KLUENG_SET(KLUENG_P.commentEndsAtFirstParen = v.number != 0.0)},
    {"angle_without_comma", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.angleWithoutComma = v.number != 0.0)},
    {"same_group_last_wins", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.sameGroupLastWins = v.number != 0.0)},
    {"stop_codes_alone_is_error", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.stopCodesAloneIsError = v.number != 0.0)},
    {"program_number_zero_is_error",
     Type::Flag,
     0,
     0,
     {},
     KLUENG_SET(KLUENG_P.programNumberZeroIsError = v.number != 0.0)},
    {"spindle_above_maximum_is_alarm",
     Type::Flag,
     0,
     0,
     {},
     KLUENG_SET(KLUENG_P.spindleAboveMaximumIsAlarm = v.number != 0.0)},
    {"spindle_reversal_is_alarm", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.spindleReversalIsAlarm = v.number != 0.0)},
    {"cycle_under_compensation_is_alarm",
     Type::Flag,
     0,
     0,
     {},
     KLUENG_SET(KLUENG_P.cycleUnderCompensationIsAlarm = v.number != 0.0)},
    {"m_codes", Type::Numbers, 0, 99, {}, KLUENG_SET(m.mCodes = v.numbers)},
    {"error_codes_as_warnings", Type::Numbers, 101, 499, {}, KLUENG_SET(m.errorsAsWarnings = v.numbers)},
    // Cycle defaults.
    {"rough_depth_inch", Type::Real, 0, 100, {}, KLUENG_SET(KLUENG_P.cycles.roughDepthInch = v.number)},
    {"rough_depth_mm", Type::Real, 0, 100, {}, KLUENG_SET(KLUENG_P.cycles.roughDepthMm = v.number)},
    {"rough_retract_inch", Type::Real, 0, 100, {}, KLUENG_SET(KLUENG_P.cycles.roughRetractInch = v.number)},
    {"rough_retract_mm", Type::Real, 0, 100, {}, KLUENG_SET(KLUENG_P.cycles.roughRetractMm = v.number)},
    {"peck_clear_inch", Type::Real, 0, 100, {}, KLUENG_SET(KLUENG_P.cycles.peckClearInch = v.number)},
    {"peck_clear_mm", Type::Real, 0, 100, {}, KLUENG_SET(KLUENG_P.cycles.peckClearMm = v.number)},
    {"thread_min_cut_inch", Type::Real, 0, 100, {}, KLUENG_SET(KLUENG_P.cycles.threadMinCutInch = v.number)},
    {"thread_min_cut_mm", Type::Real, 0, 100, {}, KLUENG_SET(KLUENG_P.cycles.threadMinCutMm = v.number)},
    {"thread_finish_inch", Type::Real, 0, 100, {}, KLUENG_SET(KLUENG_P.cycles.threadFinishInch = v.number)},
    {"thread_finish_mm", Type::Real, 0, 100, {}, KLUENG_SET(KLUENG_P.cycles.threadFinishMm = v.number)},
    {"thread_chamfer_leads", Type::Real, 0, 100, {}, KLUENG_SET(KLUENG_P.cycles.threadChamferLeads = v.number)},
    {"drill_r", Type::Choice, 0, 0, "from_initial_level|plane",
     KLUENG_SET(KLUENG_P.cycles.drillR = static_cast<DrillR>(v.choice))},
    {"profile_tail_beyond_start",
     Type::Flag,
     0,
     0,
     {},
     KLUENG_SET(KLUENG_P.cycles.profileTailBeyondStart = v.number != 0.0)},
    {"profile_first_block_needs_g00_g01",
     Type::Flag,
     0,
     0,
     {},
     KLUENG_SET(KLUENG_P.cycles.profileFirstBlockNeedsG00G01 = v.number != 0.0)},
    // Program flow.
    {"macro_b", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.flow.macroB = v.number != 0.0)},
    {"packed_repeats", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.flow.packedRepeats = v.number != 0.0)},
    {"max_subprogram_nesting",
     Type::Whole,
     0,
     99,
     {},
     KLUENG_SET(KLUENG_P.flow.maxSubprogramNesting = static_cast<VI>(v.number))},
    {"max_macro_nesting",
     Type::Whole,
     0,
     99,
     {},
     KLUENG_SET(KLUENG_P.flow.maxMacroNesting = static_cast<VI>(v.number))},
    {"programs_in_one_file", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.flow.programsInOneFile = v.number != 0.0)},
    {"dwell_before_corner_move",
     Type::Flag,
     0,
     0,
     {},
     KLUENG_SET(KLUENG_P.flow.dwellBeforeCornerMove = v.number != 0.0)},
    {"chamfer_with_i_or_k", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.flow.chamferWithIOrK = v.number != 0.0)},
    {"corner_r_without_comma", Type::Flag, 0, 0, {}, KLUENG_SET(KLUENG_P.flow.cornerRWithoutComma = v.number != 0.0)},
};
#undef KLUENG_SET
#undef KLUENG_P

// Keys a file must hold unless it names a `base` (m_codes may be left out: all).
// Keys added after machine files were in teachers' hands: left out, they keep the old reading.
bool optionalKey(std::string_view name) {
  return name == "m_codes" || name == "semicolon_ends_block" || name == "comment_ends_at_first_paren" ||
         name == "angle_without_comma" || name == "same_group_last_wins" || name == "spindle_above_maximum_is_alarm" ||
         name == "spindle_reversal_is_alarm" || name == "program_number_zero_is_error" ||
         name == "stop_codes_alone_is_error" || name == "error_codes_as_warnings" || name == "corner_r_without_comma" ||
         name == "cycle_under_compensation_is_alarm";
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Columns count characters, not bytes (a Thai name before a mistake).
int columnOf(std::string_view line, std::string_view part) {
  int column = 1;
  for (const char* c = line.data(); c < part.data(); ++c)
    if ((static_cast<unsigned char>(*c) & 0xC0) != 0x80) ++column;
  return column;
}
int lengthOf(std::string_view s) {
  return static_cast<int>(
      std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

std::optional<double> number(std::string_view s) {
  if (s.empty() || s.size() > 32) return std::nullopt;
  const std::string text(s);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno != 0 || !std::isfinite(v)) return std::nullopt;
  return v;
}

// "must be" of a key, English and Thai, for F201.
std::pair<std::string, std::string> expected(const Key& k) {
  const auto num = [](double v) {
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  };
  switch (k.type) {
    case Type::Whole:
      return {"a whole number from " + num(k.min) + " to " + num(k.max),
              "จำนวนเต็มตั้งแต่ " + num(k.min) + " ถึง " + num(k.max)};
    case Type::Real:
      return {"a number from " + num(k.min) + " to " + num(k.max), "ตัวเลขตั้งแต่ " + num(k.min) + " ถึง " + num(k.max)};
    case Type::Flag: return {"0 or 1", "0 หรือ 1"};
    case Type::Choice: {
      std::string list(k.choices);
      std::replace(list.begin(), list.end(), '|', ' ');
      return {"one of: " + list, "ค่าใดค่าหนึ่งต่อไปนี้: " + list};
    }
    case Type::Text: return {"a text", "ข้อความ"};
    case Type::Numbers:
      return {"whole numbers from " + num(k.min) + " to " + num(k.max) + " separated by blanks, or none",
              "จำนวนเต็ม " + num(k.min) + " ถึง " + num(k.max) + " คั่นด้วยช่องว่าง หรือ none"};
    case Type::Letters: return {"capital letters A to Z, each once", "ตัวอักษรพิมพ์ใหญ่ A ถึง Z ตัวละครั้ง"};
  }
  return {};
}

std::optional<Value> readValue(const Key& k, std::string_view text) {
  Value v;
  v.text = text;
  switch (k.type) {
    case Type::Whole:
    case Type::Real: {
      const auto n = number(text);
      if (!n || *n < k.min || *n > k.max || (k.type == Type::Whole && *n != std::floor(*n))) return std::nullopt;
      v.number = *n;
      return v;
    }
    case Type::Flag:
      if (text != "0" && text != "1") return std::nullopt;
      v.number = text == "1" ? 1.0 : 0.0;
      return v;
    case Type::Choice: {
      std::string_view rest = k.choices;
      for (int i = 0; !rest.empty(); ++i) {
        const std::size_t bar = std::min(rest.find('|'), rest.size());
        if (rest.substr(0, bar) == text) {
          v.choice = i;
          return v;
        }
        rest.remove_prefix(std::min(bar + 1, rest.size()));
      }
      return std::nullopt;
    }
    case Type::Text:
      if (text.empty()) return std::nullopt;
      return v;
    case Type::Numbers: {
      if (text == "none") return v;
      std::string_view rest = text;
      while (!(rest = trim(rest)).empty()) {
        const std::size_t blank = std::min(rest.find_first_of(" \t"), rest.size());
        int n = 0;
        const auto [end, ec] = std::from_chars(rest.data(), rest.data() + blank, n);
        if (ec != std::errc() || end != rest.data() + blank || n < k.min || n > k.max) return std::nullopt;
        if (std::find(v.numbers.begin(), v.numbers.end(), n) == v.numbers.end()) v.numbers.push_back(n);
        rest.remove_prefix(blank);
      }
      if (v.numbers.empty()) return std::nullopt;
      return v;
    }
    case Type::Letters: {
      if (text.empty()) return std::nullopt;
      for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] < 'A' || text[i] > 'Z' || text.find(text[i]) != i) return std::nullopt;
      return v;
    }
  }
  return std::nullopt;
}

Diagnostic machineFileDiagnostic(Severity s, const char* code, int line, int column, int length,
                                 std::vector<std::string> args) {
  return Diagnostic{s, code, {line, column, length, 0}, std::move(args)};
}

}  // namespace

MachineFileRead parseMachineFile(std::string_view text, const std::string& fileName) {
  MachineFileRead out;
  auto& diags = out.diagnostics;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // a BOM from a Windows editor

  struct Line {
    int number;
    std::string_view line, key, value;
  };
  std::vector<Line> lines;
  int lineNumber = 0;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = text.substr(start, end - start);
    ++lineNumber;
    start = end + 1;
    std::string_view content = trim(line.substr(0, std::min(line.find('#'), line.size())));
    if (content.empty()) {
      if (end == text.size()) break;
      continue;
    }
    const std::size_t eq = content.find('=');
    const std::string_view key = eq == std::string_view::npos ? std::string_view() : trim(content.substr(0, eq));
    if (key.empty()) {
      diags.push_back(machineFileDiagnostic(Severity::Error, core::codes::kNotKeyValue, lineNumber,
                                            columnOf(line, content), lengthOf(content), {fileName}));
    } else {
      lines.push_back({lineNumber, line, key, trim(content.substr(eq + 1))});
    }
    if (end == text.size()) break;
  }

  MachineDefinition m;
  std::map<std::string_view, int> lineOfKey;
  // A base first, so the file's own keys override it.
  for (const Line& l : lines) {
    if (l.key != "base") continue;
    lineOfKey["base"] = l.number;
    const MachineProfile* base = detail::loadedMachine(l.value);
    if (!base) {
      const std::string known = detail::loadedMachineIds();
      diags.push_back(machineFileDiagnostic(Severity::Error, core::codes::kMachineUnknownBase, l.number,
                                            columnOf(l.line, l.value), std::max(1, lengthOf(l.value)),
                                            {fileName, std::string(l.value), known}));
      continue;
    }
    m.profile = *base;
    m.id = base->id;
    m.nameEn = base->nameEn;
    m.nameTh = base->nameTh;
    m.letters = base->letters;
    m.oneShots.assign(base->oneShotsWithMotion.begin(), base->oneShotsWithMotion.end());
    m.mCodes.assign(base->mCodes.begin(), base->mCodes.end());
    m.errorsAsWarnings.assign(base->errorsAsWarnings.begin(), base->errorsAsWarnings.end());
  }
  const bool hasBase = lineOfKey.count("base") != 0;

  for (const Line& l : lines) {
    if (l.key == "base") continue;
    const Key* key = nullptr;
    for (const Key& k : kKeys)
      if (k.name == l.key) key = &k;
    if (!key) {
      m.otherKeys.push_back({std::string(l.key), l.number});  // machine.cfg's keys: machine/machine_files.h
      continue;
    }
    const int valueColumn = l.value.empty() ? columnOf(l.line, l.key) + lengthOf(l.key) : columnOf(l.line, l.value);
    const auto value = readValue(*key, l.value);
    if (!value) {
      const auto [en, th] = expected(*key);
      diags.push_back(machineFileDiagnostic(Severity::Error, core::codes::kMachineValueBad, l.number, valueColumn,
                                            std::max(1, lengthOf(l.value)),
                                            {fileName, std::string(l.key), std::string(l.value), en, th}));
      continue;
    }
    if (lineOfKey.count(key->name))
      diags.push_back(machineFileDiagnostic(Severity::Warning, core::codes::kParameterTwice, l.number,
                                            columnOf(l.line, l.key), lengthOf(l.key), {fileName, std::string(l.key)}));
    lineOfKey[key->name] = l.number;
    key->set(m, *value);
  }
  if (!hasBase)
    for (const Key& k : kKeys)
      if (!lineOfKey.count(k.name) && !optionalKey(k.name))
        diags.push_back(machineFileDiagnostic(Severity::Error, core::codes::kMachineKeyMissing, 0, 0, 0,
                                              {fileName, std::string(k.name)}));
  if (hasBase && !lineOfKey.count("id"))
    diags.push_back(machineFileDiagnostic(Severity::Error, core::codes::kMachineKeyMissing, 0, 0, 0, {fileName, "id"}));

  if (std::any_of(diags.begin(), diags.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; }))
    return out;
  m.file = fileName;
  m.text = std::string(text);
  out.machine = std::move(m);
  return out;
}

}  // namespace klueng::core::gcode
