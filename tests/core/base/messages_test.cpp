#include "klueng/core/messages.h"

#include <gtest/gtest.h>

#include <set>

#include "klueng/core/diagnostic_codes.h"

namespace klueng::core {
namespace {

TEST(Messages, EveryCodeIsUniqueAndHasBothLanguages) {
  std::set<std::string_view> seen;
  for (const auto& m : allMessages()) {
    EXPECT_TRUE(seen.insert(m.code).second) << "duplicate code " << m.code;
    EXPECT_FALSE(m.en.empty()) << m.code;
    EXPECT_FALSE(m.th.empty()) << m.code;
    EXPECT_NE(m.en, m.th) << m.code << " has no real Thai text";
  }
}

// Issue 28 item 8: the stock's size reads in Thai units in Thai ("มม.", "นิ้ว"), as is, in English.
TEST(Messages, StockSizesSpeakThaiUnits) {
  const Diagnostic mm{Severity::Note,
                      codes::kStockFromHeader,
                      {},
                      {"\xC3\x98"
                       "50 x 100 mm"}};
  EXPECT_EQ(formatMessage(mm, Lang::Th), "ชิ้นงาน Ø50 x 100 มม. จากส่วนหัวของงานในไฟล์");
  EXPECT_EQ(formatMessage(mm, Lang::En), "stock Ø50 x 100 mm from the file's job header");
  const Diagnostic inch{Severity::Note,
                        codes::kStockFromHeader,
                        {},
                        {"\xC3\x98"
                         "2 x 4 in"}};
  EXPECT_EQ(formatMessage(inch, Lang::Th), "ชิ้นงาน Ø2 x 4 นิ้ว จากส่วนหัวของงานในไฟล์");
  // Not a size: left alone.
  const Diagnostic word{Severity::Note,
                        codes::kStockFromFirstApproach,
                        {},
                        {"\xC3\x98"
                         "3 x 25 mm",
                         "N10 G00 X1.5 (come in)"}};
  EXPECT_EQ(formatMessage(word, Lang::Th),
            "ชิ้นงาน Ø3 x 25 มม. ประมาณจาก N10 G00 X1.5 (come in) (ตำแหน่งเข้าหาชิ้นงานครั้งแรก)");
}

TEST(Messages, UnknownCodeFallsBackToCodeAndArgs) {
  Diagnostic d{Severity::Error, "Z999", {3, 4, 1}, {"X", "5"}};
  EXPECT_EQ(formatMessage(d, Lang::En), "Z999 X 5");
}

// Issue 28 item 7: what the GUI shows names GUI places, never a CLI flag; the
// CLI keeps its flags. Every catalog text that names a flag has a GUI text
// with the same placeholders, in both languages.
TEST(Messages, TheGuiNamesItsOwnPlacesNotFlags) {
  for (const auto& m : allMessages()) {
    const bool namesAFlag = m.en.find("--") != std::string_view::npos || m.th.find("--") != std::string_view::npos;
    if (!namesAFlag || m.code == "I150") continue;  // I150: the stock came from --stock, the CLI only
    if (m.code.front() == 'C') continue;            // the CLI's own texts (usage, options): never shown in the GUI
    const MessageText* gui = findGuiMessage(m.code);
    ASSERT_NE(gui, nullptr) << m.code << " names a flag and has no GUI text";
    EXPECT_EQ(gui->en.find("--"), std::string_view::npos) << m.code;
    EXPECT_EQ(gui->th.find("--"), std::string_view::npos) << m.code;
    EXPECT_NE(gui->en, gui->th) << m.code;
    for (int i = 0; i < 6; ++i) {
      const std::string slot = "{" + std::to_string(i) + "}";
      if (m.code == "I102" && i == 2) continue;  // the dialect's CLI name (haas), only for --dialect
      EXPECT_EQ(m.en.find(slot) != std::string_view::npos, gui->en.find(slot) != std::string_view::npos)
          << m.code << slot;
      EXPECT_EQ(m.th.find(slot) != std::string_view::npos, gui->th.find(slot) != std::string_view::npos)
          << m.code << slot;
    }
  }
  Diagnostic stock{Severity::Note, "I155", {}, {"Ø50 x 100 mm"}};
  EXPECT_EQ(
      formatMessage(stock, Lang::En, Surface::Gui),
      "stock Ø50 x 100 mm is the default: the program has no approach to infer it from; set it in File ▸ Job details");
  EXPECT_EQ(formatMessage(stock, Lang::Th, Surface::Gui),
            "ชิ้นงาน Ø50 x 100 มม. เป็นค่าเริ่มต้น: โปรแกรมไม่มีตำแหน่งเข้าหาชิ้นงานให้ประมาณได้ ตั้งค่าได้ที่ แฟ้ม ▸ รายละเอียดงาน");
  EXPECT_EQ(formatMessage(stock, Lang::En, Surface::Cli), formatMessage(stock, Lang::En));
  EXPECT_NE(formatMessage(stock, Lang::En).find("--stock"), std::string::npos);
  Diagnostic dialect{Severity::Note, "I102", {}, {"3", "Haas", "haas"}};
  EXPECT_EQ(formatMessage(dialect, Lang::En, Surface::Gui),
            "blocks with errors or warnings that are Haas forms: 3; choose Haas in Tool setting ▸ G-code dialect");
  EXPECT_EQ(formatMessage(dialect, Lang::Th, Surface::Gui),
            "บล็อกที่ผิดพลาดหรือมีคำเตือน 3 บล็อกเป็นรูปแบบของ Haas: เลือก Haas ที่ ตั้งค่ามีดตัด ▸ ภาษาจีโค้ด");
  EXPECT_EQ(formatMessage(dialect, Lang::En),
            "blocks with errors or warnings that are Haas forms: 3; choose the Haas dialect (--dialect haas)");
}

// Issue 42 item 6: a 10 MB tool name made a 10 MB message. An argument over
// kMaxMessageArgChars code points is shortened in its middle (never inside a Thai
// character) and the message says how much was left out; the args stay whole.
TEST(Messages, VeryLongArgumentsAreShortenedInTheMiddle) {
  const std::string name = "start-" + std::string(10 * 1024 * 1024, 'x') + "-end";
  const Diagnostic d{Severity::Error, codes::kNoSuchFile, {}, {name}};
  const std::string en = formatMessage(d, Lang::En);
  EXPECT_LT(en.size(), 2 * kMaxMessageArgChars);
  EXPECT_TRUE(en.starts_with("start-xxx")) << en.substr(0, 100);
  EXPECT_NE(en.find("-end: no such file"), std::string::npos);
  EXPECT_NE(en.find(" … [" + std::to_string(name.size() - kMaxMessageArgChars * 3 / 4 - kMaxMessageArgChars / 5) +
                    " characters left out] … "),
            std::string::npos);
  EXPECT_NE(formatMessage(d, Lang::Th).find("ตัวอักษร] …"), std::string::npos);
  EXPECT_EQ(d.args.front().size(), name.size());
  // Thai text is cut between characters, and a short text is left as it is.
  std::string thai;
  for (int i = 0; i < 3000; ++i) thai += "ก";
  const std::string cut = elideMessageArg(thai, Lang::En);
  EXPECT_LT(cut.size(), thai.size());
  EXPECT_TRUE(cut.starts_with("กกก"));
  EXPECT_TRUE(cut.ends_with("กกก"));
  EXPECT_EQ(elideMessageArg("short", Lang::En), "short");
}

}  // namespace
}  // namespace klueng::core
