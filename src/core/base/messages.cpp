#include "klueng/core/messages.h"

#include <fmt/args.h>
#include <fmt/format.h>

#include <algorithm>
#include <unordered_map>
#include <vector>

#include "catalog_parts.h"

namespace klueng::core {

std::span<const MessageText> allMessages() {
  static const std::vector<MessageText> all = [] {
    std::vector<MessageText> v;
    for (auto part : {catalog::gcodeMessages(), catalog::ioMessages(), catalog::machineMessages(),
                      catalog::compMessages(), catalog::cutMessages(), catalog::designMessages(), catalog::cliMessages()})
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

std::string formatMessage(const Diagnostic& d, Lang lang) {
  const MessageText* t = findMessage(d.code);
  if (!t) {
    std::string s = d.code;
    for (const auto& a : d.args) s += " " + a;
    return s;
  }
  fmt::dynamic_format_arg_store<fmt::format_context> store;
  for (const auto& a : d.args) store.push_back(a);
  // Missing args are a bug in the caller; show the template rather than throw.
  for (std::size_t i = d.args.size(); i < 8; ++i) store.push_back(std::string("?"));
  const std::string_view text = lang == Lang::Th ? t->th : t->en;
  try {
    return fmt::vformat(text, store);
  } catch (const fmt::format_error&) {
    return std::string(text);
  }
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
