// Unit tests of the helpers klueng-cli's commands share (src/cli/cli_common.h).
#include "cli_common.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <optional>

namespace klueng::cli {
namespace {

using core::Diagnostic;
using core::Lang;
using core::Severity;

TEST(CliCommon, JsonEscapeHandlesQuotesControlsThaiAndBrokenUtf8) {
  EXPECT_EQ(jsonEscape("plain"), "plain");
  EXPECT_EQ(jsonEscape("a\"b\\c"), "a\\\"b\\\\c");
  EXPECT_EQ(jsonEscape("l1\nl2\tx\r"), "l1\\nl2\\tx\\r");
  EXPECT_EQ(jsonEscape(std::string("\x01\x1f\x7f", 3)), "\\u0001\\u001f\\u007f");
  EXPECT_EQ(jsonEscape("กลึง"), "กลึง");
  EXPECT_EQ(jsonEscape("a\xFF"
                       "b\xE0\xB8"),
            "a\\ufffdb\\ufffd\\ufffd");
}

TEST(CliCommon, DiagnosticJsonHasTheSixFieldsWithEnglishSeverity) {
  const Diagnostic d{Severity::Warning, "F107", {17, 1, 0}, {"o.cfg", "16"}};
  EXPECT_EQ(diagnosticJson("dir/o.cfg", d, Lang::Th),
            R"({"file": "dir/o.cfg", "line": 17, "column": 1, "severity": "warning", "code": "F107", )"
            R"("message": "o.cfg: บรรทัดที่อยู่หลังบรรทัดที่ 16 จะไม่ถูกนำมาใช้"})");
}

TEST(CliCommon, GccStyleWithAndWithoutAPlace) {
  const Diagnostic placed{Severity::Error, "F111", {4, 3, 1}, {"job.txt", "2"}};
  EXPECT_EQ(formatGccStyle("job.txt", placed, Lang::En),
            "job.txt:4:3: error F111: stock diameter: the unit digit must be 0 (inch) or 1 (mm), not '2'");
  const Diagnostic whole{Severity::Error, "F101", {}, {"x.txt"}};
  EXPECT_EQ(formatGccStyle("x.txt", whole, Lang::Th), "x.txt: ข้อผิดพลาด F101: x.txt: ไม่พบไฟล์");
}

class ScopedLocale {
 public:
  ScopedLocale(std::optional<std::string> all, std::optional<std::string> messages, std::optional<std::string> lang) {
    save("LC_ALL", all);
    save("LC_MESSAGES", messages);
    save("LANG", lang);
  }
  ~ScopedLocale() {
    for (auto& [name, old] : saved_)
      if (old)
        ::setenv(name, old->c_str(), 1);
      else
        ::unsetenv(name);
  }

 private:
  void save(const char* name, const std::optional<std::string>& value) {
    const char* old = std::getenv(name);
    saved_.emplace_back(name, old ? std::optional<std::string>(old) : std::nullopt);
    if (value)
      ::setenv(name, value->c_str(), 1);
    else
      ::unsetenv(name);
  }
  std::vector<std::pair<const char*, std::optional<std::string>>> saved_;
};

TEST(CliCommon, LanguageFromTheFirstSetLocaleVariable) {
  {
    ScopedLocale l(std::nullopt, std::nullopt, "th_TH.UTF-8");
    EXPECT_EQ(langFromLocale(), Lang::Th);
  }
  {
    ScopedLocale l("", "th_TH", "en_US.UTF-8");  // an empty LC_ALL does not count
    EXPECT_EQ(langFromLocale(), Lang::Th);
  }
  {
    ScopedLocale l("C", std::nullopt, "th_TH.UTF-8");
    EXPECT_EQ(langFromLocale(), Lang::En);
  }
  {
    ScopedLocale l(std::nullopt, std::nullopt, std::nullopt);
    EXPECT_EQ(langFromLocale(), Lang::En);
  }
}

TEST(CliCommon, OptionValues) {
  EXPECT_EQ(parseLang("th"), Lang::Th);
  EXPECT_EQ(parseLang("en"), Lang::En);
  EXPECT_FALSE(parseLang("TH"));
  EXPECT_EQ(parseDialect("classic"), core::gcode::Dialect::Classic);
  EXPECT_EQ(parseDialect("fanuc"), core::gcode::Dialect::Fanuc);
  EXPECT_EQ(parseDialect("haas"), core::gcode::Dialect::Haas);
  EXPECT_FALSE(parseDialect("okuma"));
  EXPECT_FALSE(parseDialect("Fanuc"));
}

TEST(CliCommon, ShippedConfigLoadsCleanWithEveryBitmap) {
  const LoadedConfig config = loadConfig(KLUENG_SOURCE_DIR);
  EXPECT_FALSE(config.unreadable);
  EXPECT_TRUE(config.diagnostics.empty()) << config.diagnostics.front().diagnostic.code;
  EXPECT_EQ(config.toolsWithBitmap(), (std::optional<std::vector<int>>{{1, 2, 3, 4, 5, 6, 7, 8}}));
  EXPECT_EQ(config.setup.offsets.at(1).tip, 3);
  EXPECT_EQ(config.setup.machine.rapidZ, 8000.0);
  ASSERT_TRUE(config.bitmaps[2]);
  EXPECT_EQ(config.bitmaps[2]->width, 60);  // 30 mm at 2 px/mm
}

// Issue 30 item 5: the words a user reads come from the core's bilingual catalog
// (src/core/base/messages_*.cpp) or from tr(); no Thai text is written into the code
// of the CLI, the painters or the window (comments may quote it). Fails on the
// literal it finds, with its file and line.
TEST(CliSources, NoThaiLiteralBypassesTheCatalogOrTr) {
  namespace fs = std::filesystem;
  std::vector<std::string> found;
  for (const char* folder : {"src/cli", "src/render", "src/gui", "src/app"}) {
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(fs::path(KLUENG_SOURCE_DIR) / folder)) {
      const std::string ext = e.path().extension().string();
      if (ext != ".cpp" && ext != ".h") continue;
      std::ifstream in(e.path());
      std::string line;
      for (int n = 1; std::getline(in, line); ++n) {
        // Thai letters are U+0E00..U+0E7F: E0 B8 xx or E0 B9 xx in UTF-8.
        std::size_t thai = std::string::npos;
        for (std::size_t i = 0; i + 1 < line.size() && thai == std::string::npos; ++i)
          if (static_cast<unsigned char>(line[i]) == 0xE0 &&
              (static_cast<unsigned char>(line[i + 1]) == 0xB8 || static_cast<unsigned char>(line[i + 1]) == 0xB9))
            thai = i;
        if (thai == std::string::npos) continue;
        const std::size_t comment = line.find("//");
        if (comment < thai) continue;
        // A source text for tr() may hold a Thai example (the translation file has its Thai).
        if (line.find("tr(") < thai || line.find("KLUENG_TR(") < thai) continue;
        found.push_back(fs::relative(e.path(), KLUENG_SOURCE_DIR).string() + ":" + std::to_string(n));
      }
    }
  }
  std::string list;
  for (const std::string& f : found) list += f + "\n";
  EXPECT_TRUE(found.empty()) << list;
}

}  // namespace
}  // namespace klueng::cli
