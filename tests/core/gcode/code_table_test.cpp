// The code table (SPEC 4, 6, 7, 13) and the message catalog of the gcode module.
#include <gtest/gtest.h>

#include <cstring>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <set>
#include <string>

#include "../../../src/core/gcode/diagnostic_codes.h"
#include "klueng/core/gcode/address_table.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/messages.h"

namespace klueng::core::gcode {
namespace {

bool hasThai(std::string_view s) { return s.find("\xE0\xB8") != std::string_view::npos; }

TEST(CodeTable, ClassicIsExactlyTheSpecList) {
  const std::set<int> g = {0,  1,  2,  3,  4,  20, 21, 27, 28, 29, 32, 40, 41, 42, 50,
                           96, 97, 98, 99, 70, 71, 72, 73, 74, 75, 76, 90, 92, 94};
  const std::set<int> m = {0, 1, 2, 3, 4, 5, 8, 9, 41, 86, 87, 91, 30, 98, 99};
  for (int n = 0; n < 100; ++n) {
    EXPECT_EQ(findCode('G', n, Dialect::Classic) != nullptr, g.count(n) == 1) << "G" << n;
    EXPECT_EQ(findCode('M', n, Dialect::Classic) != nullptr, m.count(n) == 1) << "M" << n;
  }
}

TEST(CodeTable, FanucAddsItsCodes) {
  for (int n : {18, 53, 54, 55, 56, 57, 58, 59, 80}) {
    EXPECT_NE(findCode('G', n, Dialect::Fanuc), nullptr) << "G" << n;
    EXPECT_EQ(findCode('G', n, Dialect::Classic), nullptr) << "G" << n;
  }
  for (int n = 0; n < 100; ++n) {
    if (findCode('G', n, Dialect::Classic)) {
      EXPECT_NE(findCode('G', n, Dialect::Fanuc), nullptr) << "G" << n;
    }
  }
  EXPECT_NE(findCode('M', 42, Dialect::Fanuc), nullptr);
  EXPECT_EQ(findCode('M', 77, Dialect::Fanuc), nullptr);
  EXPECT_EQ(findCode('X', 1, Dialect::Fanuc), nullptr);
  EXPECT_EQ(findCode('G', -1, Dialect::Fanuc), nullptr);
  EXPECT_EQ(findCode('G', 100, Dialect::Fanuc), nullptr);
}

TEST(CodeTable, DialectMeanings) {
  EXPECT_EQ(lookupCode('M', 41, Dialect::Classic)->group, ModalGroup::MCAxis);
  EXPECT_EQ(lookupCode('M', 41, Dialect::Fanuc)->group, ModalGroup::MGear);
  EXPECT_TRUE(lookupCode('G', 99, Dialect::Classic)->mustStandAlone());
  EXPECT_FALSE(lookupCode('G', 99, Dialect::Fanuc)->mustStandAlone());
  EXPECT_TRUE(lookupCode('M', 30, Dialect::Classic)->mustStandAlone());
  EXPECT_FALSE(lookupCode('G', 7, Dialect::Fanuc).has_value());
}

TEST(CodeTable, ModalGroupsOfSection6) {
  const std::pair<int, ModalGroup> rows[] = {
      {0, ModalGroup::Motion},    {1, ModalGroup::Motion},       {2, ModalGroup::Motion},
      {3, ModalGroup::Motion},    {32, ModalGroup::Motion},      {90, ModalGroup::Motion},
      {4, ModalGroup::NonModal},  {27, ModalGroup::NonModal},    {28, ModalGroup::NonModal},
      {29, ModalGroup::NonModal}, {50, ModalGroup::NonModal},    {20, ModalGroup::Units},
      {21, ModalGroup::Units},    {40, ModalGroup::NoseComp},    {41, ModalGroup::NoseComp},
      {42, ModalGroup::NoseComp}, {96, ModalGroup::SpindleMode}, {97, ModalGroup::SpindleMode},
      {98, ModalGroup::FeedMode}, {99, ModalGroup::FeedMode}};
  for (const auto& [n, group] : rows)
    for (Dialect d : {Dialect::Fanuc, Dialect::Classic}) EXPECT_EQ(findCode('G', n, d)->group, group) << "G" << n;
}

TEST(CodeTable, InBlockOrderOfSection7) {
  for (int n : {20, 21, 40, 41, 42, 96, 97, 98, 99}) EXPECT_EQ(findCode('G', n, Dialect::Classic)->phase, Phase::State);
  for (int n : {3, 4, 8, 41, 86, 87, 91}) EXPECT_EQ(findCode('M', n, Dialect::Classic)->phase, Phase::BeforeMotion);
  for (int n : {0, 1, 2, 3, 4, 27, 28, 29, 32, 50}) EXPECT_EQ(findCode('G', n, Dialect::Classic)->phase, Phase::Motion);
  for (int n : {5, 9, 0, 1, 2, 30}) EXPECT_EQ(findCode('M', n, Dialect::Classic)->phase, Phase::AfterMotion);
}

TEST(CodeTable, EveryRowHasEnglishAndThaiHelp) {
  for (const CodeInfo& row : codeTable()) {
    const std::string code = std::string(1, row.letter) + std::to_string(row.number);
    EXPECT_NE(row.dialects, 0) << code;
    EXPECT_FALSE(row.nameEn.empty()) << code;
    EXPECT_TRUE(hasThai(row.nameTh)) << code;
    EXPECT_TRUE(hasThai(row.exampleTh)) << code;
    // The example starts with the code itself, e.g. "G01 Z-30. F0.2 - ...".
    char prefix[5];
    std::snprintf(prefix, sizeof prefix, "%c%02d", row.letter, row.number);
    EXPECT_EQ(row.exampleEn.substr(0, std::strlen(prefix)), prefix) << code;
    EXPECT_EQ(row.exampleTh.substr(0, std::strlen(prefix)), prefix) << code;
  }
}

TEST(Catalog, EveryGcodeDiagnosticHasEnglishAndThai) {
  for (const char* code : codes::kAll) {
    const MessageText* m = findMessage(code);
    ASSERT_NE(m, nullptr) << code;
    EXPECT_FALSE(m->en.empty()) << code;
    EXPECT_TRUE(hasThai(m->th)) << code;
    // Same placeholders in both languages.
    for (const char* ph : {"{0}", "{1}", "{2}"})
      EXPECT_EQ(m->en.find(ph) == std::string_view::npos, m->th.find(ph) == std::string_view::npos) << code << ph;
  }
  // Rule 13 (stock size) belongs to the file reader's catalog part, not here.
  EXPECT_EQ(std::count_if(std::begin(codes::kAll), std::end(codes::kAll),
                          [](const char* c) { return std::string_view(c) == "E213"; }),
            0);
}

}  // namespace
}  // namespace klueng::core::gcode

// The address table (issue 12): one list of letters for the checker, the editor and its tool tips.
namespace klueng::core::gcode {
namespace {

TEST(AddressTable, EveryLatheLetterIsThereOnceWithBothMeanings) {
  std::string letters;
  for (const AddressInfo& a : addressTable()) {
    letters += a.letter;
    EXPECT_FALSE(a.meaningEn.empty()) << a.letter;
    // Thai letters (U+0E00-U+0E7F are E0 B8 80 .. E0 B9 BF in UTF-8).
    EXPECT_NE(a.meaningTh.find("\xE0\xB8"), std::string_view::npos) << a.letter;
    EXPECT_EQ(addressInfo(a.letter), &a);
  }
  EXPECT_EQ(letters, "ACDEFGHIJKLMNOPQRSTUWXZ");
  for (char missing : {'B', 'V', 'Y', 'a', '#'}) EXPECT_EQ(addressInfo(missing), nullptr) << missing;
}

TEST(AddressTable, RuleTwoLettersAreOncePerBlock) {
  // SPEC 4 rule 2: G, M, P, Q and L may repeat (G00 G40 G97, M03 M08, a cycle's P and Q).
  for (const AddressInfo& a : addressTable())
    EXPECT_EQ(a.oncePerBlock, std::string_view("GMPQL").find(a.letter) == std::string_view::npos) << a.letter;
  EXPECT_EQ(addressInfo('X')->kind, AddressKind::Axis);
  EXPECT_EQ(addressInfo('T')->kind, AddressKind::Tool);
  EXPECT_EQ(addressInfo('X')->meaningEn, "X position (diameter)");
}

}  // namespace
}  // namespace klueng::core::gcode

namespace klueng::core::gcode {
namespace {

// Issue 12: the interpreter and the cycles switch on what a code does. Every row of a
// group they act on says it; the rows the simulator only shows (G18, M10 chuck ...) say None.
TEST(CodeTable, EveryCodeTheInterpreterRunsHasItsAction) {
  const ModalGroup acted[] = {ModalGroup::Motion,      ModalGroup::NonModal,       ModalGroup::Units,
                              ModalGroup::NoseComp,    ModalGroup::SpindleMode,    ModalGroup::FeedMode,
                              ModalGroup::WorkOffset,  ModalGroup::CannedCycle,    ModalGroup::MacroModal,
                              ModalGroup::MSpindle,    ModalGroup::MCoolant,       ModalGroup::MCAxis,
                              ModalGroup::MBrake,      ModalGroup::MGear,          ModalGroup::MProgram,
                              ModalGroup::MSubprogram, ModalGroup::MThreadChamfer, ModalGroup::Plane};
  for (const CodeInfo& row : codeTable()) {
    const bool isActed = std::find(std::begin(acted), std::end(acted), row.group) != std::end(acted);
    if (row.action == CodeAction::NotSimulated)  // any group: the run stops there (A117)
      continue;
    if (isActed)
      EXPECT_NE(row.action, CodeAction::None) << row.letter << row.number;
    else
      EXPECT_EQ(row.action, CodeAction::None) << row.letter << row.number;
  }
  // A number with two meanings has two actions: M41 is the C axis (classic) or gear range 1 (Fanuc).
  EXPECT_EQ(findCode('M', 41, Dialect::Classic)->action, CodeAction::CAxisOn);
  EXPECT_EQ(findCode('M', 41, Dialect::Fanuc)->action, CodeAction::GearRange);
  EXPECT_EQ(findCode('M', 14, Dialect::Haas)->action, CodeAction::SpindleClamp);
  EXPECT_EQ(findCode('G', 30, Dialect::Fanuc)->action, CodeAction::SecondReferenceReturn);
  EXPECT_EQ(findCode('G', 71, Dialect::Haas)->action, CodeAction::TurnRoughing);
}

// Issue 30 item 3: one row per code carries what the explain bar says, what the
// help search finds it by and its example. A row without them fails here, for
// every machine under its own numbers (the ROMI's G33 and G78 in system B).
void expectComplete(const CodeInfo& row, const std::string& where) {
  const std::string code = codeWord(row);
  EXPECT_GE(row.says.en.size(), 6u) << where << " " << code;
  EXPECT_TRUE(hasThai(row.says.th)) << where << " " << code;
  EXPECT_NE(row.says.en, row.says.th) << where << " " << code;
  // What students type: English words and Thai ones.
  EXPECT_NE(row.keywords.find_first_of("abcdefghijklmnopqrstuvwxyz"), std::string_view::npos) << where << " " << code;
  EXPECT_TRUE(hasThai(row.keywords)) << where << " " << code;
  EXPECT_EQ(row.exampleEn.substr(0, code.size() + 1), code + " ") << where;
  EXPECT_EQ(row.exampleTh.substr(0, code.size() + 1), code + " ") << where;
  EXPECT_TRUE(hasThai(row.exampleTh)) << where << " " << code;
}

TEST(CodeTable, EveryRowSaysWhatItDoesHowItIsFoundAndAnExample) {
  for (const CodeInfo& row : codeTable()) expectComplete(row, "table");
  for (const CodeInfo& row : systemOnlyRows()) expectComplete(row, "systems B and C");
  Dialect romi{};
  ASSERT_TRUE(parseDialectId("romi-gl240m", romi));
  int rows = 0;
  for (const Dialect d : {Dialect::Fanuc, Dialect::Haas, Dialect::Classic, romi})
    for (const char letter : {'G', 'M'})
      for (int n = 0; n < 100; ++n)
        if (const CodeInfo* row = findCode(letter, n, d)) {
          EXPECT_EQ(row->number, n);
          expectComplete(*row, std::string(dialectName(d)));
          ++rows;
        }
  EXPECT_GT(rows, 200);
}

TEST(CodeTable, WordKindsAreTypedAndCheckedWhenTheTableIsBuilt) {
  constexpr WordKinds kinds = WordKinds().whole("PQ").positive("DF").length("U").dwell("X").increment("K");
  static_assert(kinds.of('P') == WordKind::Whole && kinds.of('Q') == WordKind::Whole);
  static_assert(kinds.of('D') == WordKind::Positive && kinds.of('U') == WordKind::Length);
  static_assert(kinds.of('X') == WordKind::Dwell && kinds.of('K') == WordKind::Increment);
  static_assert(kinds.of('Z') == WordKind::Default && kinds.of('p') == WordKind::Default && kinds.any());
  static_assert(!WordKinds().any());
  // The Haas G71 row: P#Q#D+I.K.U.W.F+S+ as the string once said it.
  const WordKinds& haas = findCode('G', 71, Dialect::Haas)->words;
  for (char c : {'P', 'Q'}) EXPECT_EQ(haas.of(c), WordKind::Whole) << c;
  for (char c : {'D', 'F', 'S'}) EXPECT_EQ(haas.of(c), WordKind::Positive) << c;
  for (char c : {'I', 'K', 'U', 'W'}) EXPECT_EQ(haas.of(c), WordKind::Length) << c;
  for (char c : {'X', 'Z', 'R', 'A'}) EXPECT_EQ(haas.of(c), WordKind::Default) << c;
}

TEST(CodeTable, ActionsFindTheMachinesOwnCodes) {
  Dialect romi{};
  ASSERT_TRUE(parseDialectId("romi-gl240m", romi));
  EXPECT_EQ(findAction('G', CodeAction::Thread, Dialect::Fanuc)->number, 32);
  EXPECT_EQ(findAction('G', CodeAction::Thread, romi)->number, 33);
  EXPECT_EQ(findAction('G', CodeAction::BoxThreading, Dialect::Fanuc)->number, 92);
  EXPECT_EQ(findAction('G', CodeAction::BoxThreading, romi)->number, 78);
  EXPECT_EQ(findAction('G', CodeAction::CoordinateSet, romi)->number, 92);
  EXPECT_EQ(findAction('G', CodeAction::FeedPerRev, romi)->number, 95);
  EXPECT_EQ(findAction('M', CodeAction::SubprogramCall, romi)->number, 98);
  EXPECT_EQ(findAction('G', CodeAction::MachineCoordinates, Dialect::Classic), nullptr);
  EXPECT_EQ(findAction('G', CodeAction::SpindleCw, Dialect::Fanuc), nullptr);  // an M code's action
  EXPECT_EQ(codeWord(*findAction('G', CodeAction::Rapid, romi)), "G00");

  const Program p = parse("G33 Z-20. F1.5 G1.5 G#1 M98 P10", 1);
  ASSERT_EQ(p.blocks.size(), 1u);
  const auto& w = p.blocks[0].words;
  ASSERT_EQ(w.size(), 7u);
  EXPECT_EQ(actionOf(w[0], romi), CodeAction::Thread);
  EXPECT_EQ(actionOf(w[0], Dialect::Fanuc), CodeAction::None);  // no G33 in system A
  EXPECT_EQ(actionOf(w[1], romi), CodeAction::None);            // Z
  EXPECT_EQ(actionOf(w[3], romi), CodeAction::None);            // G1.5
  EXPECT_EQ(actionOf(w[4], romi), CodeAction::None);            // G#1
  EXPECT_EQ(actionOf(w[5], romi), CodeAction::SubprogramCall);
}

// W104 names the modal motion by the machine's own code: a system-B thread is G33.
TEST(CodeTable, AModalThreadWithoutFeedIsNamedInTheMachinesNumbers) {
  Dialect romi{};
  ASSERT_TRUE(parseDialectId("romi-gl240m", romi));
  const auto w104 = [](const std::string& text, Dialect d) {
    CheckOptions o;
    o.dialect = d;
    o.modalRules = true;
    for (const Diagnostic& diag : check(parse(text, 1), o))
      if (diag.code == "W104") return diag.args.empty() ? std::string("?") : diag.args[0];
    return std::string();
  };
  EXPECT_EQ(w104("G97 S500 M03\nG00 X30. Z5.\nG32\nZ-20.\n", Dialect::Fanuc), "G32");
  EXPECT_EQ(w104("G97 S500 M03\nG00 X30. Z5.\nG33\nZ-20.\n", romi), "G33");
}

}  // namespace
}  // namespace klueng::core::gcode
