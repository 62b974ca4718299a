#pragma once
// Internal: what the rows of the code table share (code_table.cpp: the G codes, code_table_m.cpp:
// the M codes): the short names of groups, phases and actions, the dialect masks, the phrases and
// search words several rows use, and the compile-time check that every row is complete.
#include <cstdint>
#include <span>
#include <string_view>

#include "klueng/core/gcode/code_table.h"

namespace klueng::core::gcode::table_rows {

using G = ModalGroup;
using P = Phase;
using A = CodeAction;
// Dialect masks of a row.
constexpr std::uint8_t kF = dialectBit(Dialect::Fanuc);
constexpr std::uint8_t kH = dialectBit(Dialect::Haas);
constexpr std::uint8_t kC = dialectBit(Dialect::Classic);
constexpr std::uint8_t kFH = kF | kH;
constexpr std::uint8_t kFC = kF | kC;
constexpr std::uint8_t kAll = kF | kH | kC;
// Flags of a row.
constexpr std::uint8_t kNoFlags = 0;
constexpr std::uint8_t kAlone = CodeInfo::kStandsAlone;
constexpr std::uint8_t kAtRest = CodeInfo::kSpindleAtRest;

// What a code does, as a teacher says it (Thai terms from GLOSSARY.md): shared by the rows of one action.
constexpr Phrase kReferenceReturnSays{"return to the reference point through the given point",
                                      "กลับสู่จุดอ้างอิงโดยผ่านจุดที่กำหนด"};
constexpr Phrase kWorkOffsetSays{"use this work coordinate system", "ใช้ระบบพิกัดงานนี้"};
constexpr Phrase kTurnRoughingSays{"rough turning cycle: take the profile down in passes along Z",
                                   "วัฏจักรกลึงปอกหยาบ: กลึงตามรูปร่างทีละเที่ยวตามแนวแกน Z"};
constexpr Phrase kFaceRoughingSays{"rough facing cycle: take the profile down in passes along X",
                                   "วัฏจักรกลึงปาดหน้าหยาบ: กลึงตามรูปร่างทีละเที่ยวตามแนวแกน X"};
constexpr Phrase kPatternRepeatingSays{"pattern repeating cycle: the profile again and again, closer each pass",
                                       "วัฏจักรกลึงตามแบบซ้ำ: กลึงตามรูปร่างซ้ำ เข้าใกล้ขึ้นทุกเที่ยว"};
constexpr Phrase kFacePeckingSays{"peck cycle along Z: feed in, back off to break the chip, again",
                                  "วัฏจักรเจาะจิกตามแนวแกน Z: ป้อนเข้า ถอยเพื่อตัดเศษ แล้วป้อนต่อ"};
constexpr Phrase kGroovingSays{"grooving cycle along X: plunge in pecks to break the chip",
                               "วัฏจักรกลึงร่องตามแนวแกน X: ป้อนเข้าเป็นช่วงเพื่อตัดเศษ"};
constexpr Phrase kThreadCuttingSays{"multi-pass threading cycle: the thread in passes of less and less depth",
                                    "วัฏจักรกลึงเกลียวหลายเที่ยว: ป้อนลึกลดลงทุกเที่ยว"};
constexpr Phrase kPeckDrillingSays{"peck drilling cycle: drill in pecks, back out to clear the chips",
                                   "วัฏจักรเจาะจิก: เจาะทีละช่วงแล้วถอยออกเพื่อคายเศษ"};
constexpr Phrase kFeedPerMinuteSays{"feed in mm per minute", "อัตราป้อนเป็นมม./นาที"};
constexpr Phrase kFeedPerRevSays{"feed in mm per revolution", "อัตราป้อนเป็นมม./รอบ"};
constexpr Phrase kProgramEndSays{"end of the program", "จบโปรแกรม"};
constexpr Phrase kSpindleClampSays{"apply the spindle brake", "ล็อกเบรกเพลา"};
constexpr Phrase kSpindleReleaseSays{"release the spindle brake", "ปลดเบรกเพลา"};
// What a student types looking for a code, beyond its name (GLOSSARY.md terms): shared by related rows.
constexpr std::string_view kAirBlastWords = "air blast jet chips ลมเป่า";
constexpr std::string_view kArcWords = "arc circle radius fillet round corner ส่วนโค้ง รัศมี มุมมน";
constexpr std::string_view kBrakeWords = "spindle brake lock clamp เบรก เพลา";
constexpr std::string_view kCAxisWords = "c-axis c axis indexing spindle position แกน c";
constexpr std::string_view kCallWords = "subprogram subroutine call macro โปรแกรมย่อย มาโคร";
constexpr std::string_view kChuckWords = "chuck clamp jaws grip หัวจับ จับชิ้นงาน";
constexpr std::string_view kCompWords = "nose radius compensation tnrc offset ชดเชยรัศมีจมูกมีด";
constexpr std::string_view kConveyorWords = "chip conveyor chips สายพาน เศษ";
constexpr std::string_view kCoolantWords = "coolant flood น้ำหล่อเย็น สารหล่อเย็น";
constexpr std::string_view kDistanceWords = "absolute incremental distance mode สัมบูรณ์ สัมพัทธ์";
constexpr std::string_view kDoorWords = "door automatic ประตู";
constexpr std::string_view kDrillingWords = "drilling drill hole peck centre เจาะ เจาะรู เจาะจิก";
constexpr std::string_view kFacingWords = "facing face roughing กลึงปาดหน้า ปาดหน้า";
constexpr std::string_view kFeedWords = "feed rate อัตราป้อน";
constexpr std::string_view kGearWords = "gear range low high spindle เกียร์";
constexpr std::string_view kGroovingWords = "grooving groove parting off undercut กลึงร่อง ร่อง ตัดขาด";
constexpr std::string_view kHighPressureWords = "coolant high pressure through tool สารหล่อเย็น แรงดันสูง";
constexpr std::string_view kPartsCatcherWords = "parts catcher tray finished part ถาดรับชิ้นงาน";
constexpr std::string_view kPatternWords = "pattern repeating casting forging profile กลึงตามแบบ งานหล่อ";
constexpr std::string_view kReferenceWords = "reference point home return จุดอ้างอิง";
constexpr std::string_view kRelayWords = "output relay signal รีเลย์";
constexpr std::string_view kReturnLevelWords = "drilling return level initial r point เจาะ ระดับถอยกลับ จุด R";
constexpr std::string_view kRoughingWords = "roughing rough turning stock removal od id กลึงปอกหยาบ กลึงหยาบ";
constexpr std::string_view kSpindleWords = "spindle start stop rotation เพลา หมุน";
constexpr std::string_view kStopWords = "stop end program หยุด จบโปรแกรม";
constexpr std::string_view kTailstockWords = "tailstock centre support ยันศูนย์ท้าย";
constexpr std::string_view kThreadChamferWords = "thread chamfer pull out เกลียว ลบมุม";
constexpr std::string_view kThreadWords = "thread threading pitch lead screw เกลียว กลึงเกลียว ระยะพิตช์";
constexpr std::string_view kUnitsWords = "units inch metric millimetre หน่วย นิ้ว มิลลิเมตร";
constexpr std::string_view kWorkOffsetWords = "work offset coordinate system zero ระบบพิกัดงาน ศูนย์งาน";

// Every row says what it does and has the words students look for it by, and its
// one-line examples open with its own code ("G04 U0.5 - ..."), in both languages:
// a row without them does not compile.
constexpr bool complete(const CodeInfo& row) {
  if (row.nameEn.empty() || row.nameTh.empty() || row.says.en.empty() || row.says.th.empty() || row.keywords.empty())
    return false;
  if (row.number < 0 || row.number >= kCodeNumbers) return false;
  // The example starts with the code as written, two digits at least: G04, G103.
  char code[4] = {row.letter, 0, 0, 0};
  std::size_t size = 1;
  if (row.number >= 100) code[size++] = static_cast<char>('0' + row.number / 100);
  code[size++] = static_cast<char>('0' + row.number / 10 % 10);
  code[size++] = static_cast<char>('0' + row.number % 10);
  const std::string_view own(code, size);
  return row.exampleEn.starts_with(own) && row.exampleTh.starts_with(own);
}
constexpr bool allComplete(std::span<const CodeInfo> rows) {
  for (const CodeInfo& row : rows)
    if (!complete(row)) return false;
  return true;
}

}  // namespace klueng::core::gcode::table_rows

namespace klueng::core::gcode::detail {
// The M-code rows (code_table_m.cpp), after the G-code rows in codeTable().
std::span<const CodeInfo> mCodeRows();
}  // namespace klueng::core::gcode::detail
