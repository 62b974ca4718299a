#include "klueng/core/messages.h"

#include <fmt/args.h>
#include <fmt/format.h>

#include <algorithm>
#include <unordered_map>
#include <vector>

#include "catalog_parts.h"
#include "klueng/core/units.h"

namespace klueng::core {

std::span<const MessageText> allMessages() {
  static const std::vector<MessageText> all = [] {
    std::vector<MessageText> v;
    for (auto part : {catalog::gcodeMessages(), catalog::ioMessages(), catalog::machineMessages(),
                      catalog::compMessages(), catalog::cutMessages(), catalog::designMessages(),
                      catalog::cliMessages(), catalog::controlMessages(), catalog::renderMessages()})
      v.insert(v.end(), part.begin(), part.end());
    return v;
  }();
  return all;
}

const MessageText* findMessage(std::string_view code) {
  static const std::unordered_map<std::string_view, const MessageText*> index = [] {
    std::unordered_map<std::string_view, const MessageText*> m;
    for (const auto& t : allMessages()) m.emplace(t.code, &t);
    return m;
  }();
  auto it = index.find(code);
  return it == index.end() ? nullptr : it->second;
}

std::string formatWithPlace(std::string_view file, const Diagnostic& d, Lang lang) {
  std::string where(file);
  if (d.range.line > 0) where += fmt::format(":{}:{}", d.range.line, std::max(d.range.column, 1));
  return fmt::format("{}: {} {}: {}", where, severityName(d.severity, lang), d.code, formatMessage(d, lang));
}

namespace {

// The GUI's words for the codes whose CLI text names a command-line flag. The
// menu paths are the main window's menus (action_table.cpp and klueng_th.ts):
// a GUI test holds them to the menus.
constexpr MessageText kGuiWording[] = {
    {"W111",
     "{0} has no decimal point and is read as {1} (calculator-type input); a control with standard decimal point input "
     "reads it as {2}: if that is meant, write {3} or choose that reading in File ▸ Job details",
     "{0} ไม่มีจุดทศนิยมจึงถูกอ่านเป็น {1} (การป้อนค่าแบบเครื่องคิดเลข) เครื่องที่ตั้งการป้อนจุดทศนิยมแบบมาตรฐานจะอ่านเป็น {2} ถ้าต้องการค่านั้น "
     "ให้เขียน {3} หรือเลือกการอ่านแบบนั้นที่ แฟ้ม ▸ รายละเอียดงาน"},
    {"I107",
     "the program names no units (no G20 or G21) and its sizes are in {0} ({1} and its other cycle depths, feeds "
     "and speeds are {0} values): it is read in {0}; choose the power-on units in Tool setting if that is wrong",
     "โปรแกรมไม่ได้ระบุหน่วย (ไม่มี G20 หรือ G21) และขนาดต่าง ๆ เป็นหน่วย {0} ({1} รวมทั้งระยะป้อนลึก "
     "อัตราป้อน และความเร็วอื่น ๆ เป็นค่าในหน่วย {0}) จึงอ่านเป็น {0}: ถ้าไม่ถูกต้องให้เลือกหน่วยเมื่อเปิดเครื่องที่ ตั้งค่ามีดตัด"},
    {"I103",
     "lengths without a decimal point are read in least input increments (0.001 mm, 0.0001 in), as a standard Fanuc or "
     "Haas reads them: {0} on line {1} is {2}; change it in File ▸ Job details",
     "ความยาวที่ไม่มีจุดทศนิยมอ่านเป็นหน่วยป้อนค่าที่เล็กที่สุด (0.001 มม., 0.0001 นิ้ว) แบบที่เครื่อง Fanuc หรือ Haas ทั่วไปอ่าน: {0} ในบรรทัดที่ "
     "{1} คือ {2} เปลี่ยนได้ที่ แฟ้ม ▸ รายละเอียดงาน"},
    {"I104",
     "lengths without a decimal point are read in whole millimetres or inches (calculator-type input), as the "
     "program's numbers show: {0} on line {1} is {2}; change it in File ▸ Job details",
     "ความยาวที่ไม่มีจุดทศนิยมอ่านเป็นมิลลิเมตรหรือนิ้วเต็มหน่วย (การป้อนค่าแบบเครื่องคิดเลข) ตามที่ตัวเลขในโปรแกรมบอก: {0} ในบรรทัดที่ {1} คือ "
     "{2} เปลี่ยนได้ที่ แฟ้ม ▸ รายละเอียดงาน"},
    {"I102", "blocks with errors or warnings that are {1} forms: {0}; choose {1} in Tool setting ▸ G-code dialect",
     "บล็อกที่ผิดพลาดหรือมีคำเตือน {0} บล็อกเป็นรูปแบบของ {1}: เลือก {1} ที่ ตั้งค่ามีดตัด ▸ ภาษาจีโค้ด"},
    {"I155", "stock {0} is the default: the program has no approach to infer it from; set it in File ▸ Job details",
     "ชิ้นงาน {0} เป็นค่าเริ่มต้น: โปรแกรมไม่มีตำแหน่งเข้าหาชิ้นงานให้ประมาณได้ ตั้งค่าได้ที่ แฟ้ม ▸ รายละเอียดงาน"},
};

// A size argument in Thai words (issue 28 item 8): "Ø50 x 100 mm" -> "Ø50 x 100 มม.",
// "Ø2 x 4 in" -> "Ø2 x 4 นิ้ว". Only sizes: text starting with Ø or a digit.
std::string localSize(const std::string& a, Lang lang) {
  if (lang != Lang::Th || a.empty()) return a;
  const bool size = a.rfind("\xC3\x98", 0) == 0 || (a[0] >= '0' && a[0] <= '9');
  const auto endsWith = [&](std::string_view tail) {
    return a.size() > tail.size() && a.compare(a.size() - tail.size(), tail.size(), tail) == 0;
  };
  if (size && endsWith(" mm")) return a.substr(0, a.size() - 3) + " มม.";
  if (size && endsWith(" in")) return a.substr(0, a.size() - 3) + " นิ้ว";
  return a;
}

// Byte offsets of the code points of `text` (a lead byte is any byte that is not 10xxxxxx).
std::vector<std::size_t> codePointStarts(std::string_view text) {
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < text.size(); ++i)
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) starts.push_back(i);
  return starts;
}

std::string formatText(const MessageText* t, const Diagnostic& d, Lang lang) {
  if (!t) {
    std::string s = d.code;
    for (const auto& a : d.args) s += " " + elideMessageArg(a, lang);
    return s;
  }
  fmt::dynamic_format_arg_store<fmt::format_context> store;
  // A unit argument (units.h) reads as the unit's name in the message's language;
  // a size with its unit ("Ø50 mm") speaks Thai units under Thai.
  for (const auto& a : d.args) {
    const char* unit = unitArgText(a, lang);
    store.push_back(unit ? std::string(unit) : localSize(elideMessageArg(a, lang), lang));
  }
  // Missing args are a bug in the caller; show the template rather than throw.
  for (std::size_t i = d.args.size(); i < 8; ++i) store.push_back(std::string("?"));
  const std::string_view text = lang == Lang::Th ? t->th : t->en;
  try {
    return fmt::vformat(text, store);
  } catch (const fmt::format_error&) {
    return std::string(text);
  }
}

}  // namespace

std::string elideMessageArg(std::string_view text, Lang lang) {
  if (text.size() <= kMaxMessageArgChars) return std::string(text);  // fewer code points than bytes
  const std::vector<std::size_t> starts = codePointStarts(text);
  if (starts.size() <= kMaxMessageArgChars) return std::string(text);
  constexpr std::size_t kHead = kMaxMessageArgChars * 3 / 4;
  constexpr std::size_t kTail = kMaxMessageArgChars / 5;
  const std::size_t left = starts.size() - kHead - kTail;
  const std::string_view head = text.substr(0, starts[kHead]);
  const std::string_view tail = text.substr(starts[starts.size() - kTail]);
  if (lang == Lang::Th) return fmt::format("{} … [ตัดออก {} ตัวอักษร] … {}", head, left, tail);
  return fmt::format("{} … [{} characters left out] … {}", head, left, tail);
}

const MessageText* findGuiMessage(std::string_view code) {
  for (const MessageText& t : kGuiWording)
    if (t.code == code) return &t;
  return nullptr;
}

std::string formatMessage(const Diagnostic& d, Lang lang) { return formatText(findMessage(d.code), d, lang); }

std::string formatMessage(const Diagnostic& d, Lang lang, Surface surface) {
  const MessageText* gui = surface == Surface::Gui ? findGuiMessage(d.code) : nullptr;
  return formatText(gui ? gui : findMessage(d.code), d, lang);
}

std::string_view severityName(Severity s, Lang lang) {
  switch (s) {
    case Severity::Warning: return lang == Lang::Th ? "คำเตือน" : "warning";
    case Severity::Error: return lang == Lang::Th ? "ข้อผิดพลาด" : "error";
    case Severity::Alarm: return lang == Lang::Th ? "สัญญาณเตือน" : "alarm";
    case Severity::Note: return lang == Lang::Th ? "หมายเหตุ" : "note";
  }
  return "error";
}

}  // namespace klueng::core
