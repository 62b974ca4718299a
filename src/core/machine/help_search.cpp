// Help search (issue 11): every word of the query must be in a code's help —
// its code, names, examples, explanation or the words teachers use for it.
#include <algorithm>
#include <cctype>
#include <string>

#include "klueng/core/machine/explain.h"
#include "klueng/core/machine/help.h"

namespace klueng::core::machine {

namespace {

using gcode::CodeAction;

// What a student types looking for a code, beyond its name (GLOSSARY.md terms).
std::string_view keywords(CodeAction a) {
  switch (a) {
    case CodeAction::Rapid: return "rapid positioning traverse fast move เคลื่อนที่เร็ว";
    case CodeAction::Line: return "linear straight line feed cut turning taper กลึงเส้นตรง กลึงปอก กลึงเรียว";
    case CodeAction::ArcCw:
    case CodeAction::ArcCcw: return "arc circle radius fillet round corner ส่วนโค้ง รัศมี มุมมน";
    case CodeAction::Thread:
    case CodeAction::BoxThreading:
    case CodeAction::ThreadCutting: return "thread threading pitch lead screw เกลียว กลึงเกลียว ระยะพิตช์";
    case CodeAction::BoxTurning: return "turning cycle roughing box simple กลึงปอก วัฏจักร";
    case CodeAction::BoxFacing:
    case CodeAction::FaceRoughing: return "facing face roughing กลึงปาดหน้า ปาดหน้า";
    case CodeAction::TurnRoughing: return "roughing rough turning stock removal od id กลึงปอกหยาบ กลึงหยาบ";
    case CodeAction::Finishing: return "finishing finish pass contour กลึงละเอียด กลึงเก็บผิว";
    case CodeAction::PatternRepeating: return "pattern repeating casting forging profile กลึงตามแบบ งานหล่อ";
    case CodeAction::ReturnToInitialLevel:
    case CodeAction::ReturnToRPoint: return "drilling return level initial r point เจาะ ระดับถอยกลับ จุด R";
    case CodeAction::Absolute:
    case CodeAction::Incremental: return "absolute incremental distance mode สัมบูรณ์ สัมพัทธ์";
    case CodeAction::FacePecking:
    case CodeAction::Drilling:
    case CodeAction::SpotDrilling:
    case CodeAction::PeckDrilling: return "drilling drill hole peck centre เจาะ เจาะรู เจาะจิก";
    case CodeAction::Grooving: return "grooving groove parting off undercut กลึงร่อง ร่อง ตัดขาด";
    case CodeAction::CompOff:
    case CodeAction::CompLeft:
    case CodeAction::CompRight: return "nose radius compensation tnrc offset ชดเชยรัศมีจมูกมีด";
    case CodeAction::ConstantSurface: return "css surface speed cutting speed ความเร็วตัด ความเร็วผิว";
    case CodeAction::ConstantRpm: return "rpm spindle speed ความเร็วรอบ";
    case CodeAction::FeedPerMinute:
    case CodeAction::FeedPerRev: return "feed rate อัตราป้อน";
    case CodeAction::Inch:
    case CodeAction::Metric: return "units inch metric millimetre หน่วย นิ้ว มิลลิเมตร";
    case CodeAction::Dwell: return "dwell wait pause delay หยุดรอ หน่วงเวลา";
    case CodeAction::ReferenceCheck:
    case CodeAction::ReferenceReturn:
    case CodeAction::SecondReferenceReturn:
    case CodeAction::ReturnFromReference: return "reference point home return จุดอ้างอิง";
    case CodeAction::CoordinateSet: return "spindle limit clamp max rpm coordinate จำกัดความเร็วรอบ ตั้งพิกัด";
    case CodeAction::SpindleCw:
    case CodeAction::SpindleCcw:
    case CodeAction::SpindleStop: return "spindle start stop rotation เพลา หมุน";
    case CodeAction::CoolantOn:
    case CodeAction::CoolantOff: return "coolant flood น้ำหล่อเย็น สารหล่อเย็น";
    case CodeAction::LocalCall:
    case CodeAction::SubprogramCall:
    case CodeAction::SubprogramReturn:
    case CodeAction::MacroCall:
    case CodeAction::MacroModalCall: return "subprogram subroutine call macro โปรแกรมย่อย มาโคร";
    case CodeAction::ProgramStop:
    case CodeAction::OptionalStop:
    case CodeAction::ProgramEnd: return "stop end program หยุด จบโปรแกรม";
    default: return "";
  }
}

// Lower-case ASCII letters; Thai and digits stay as they are.
std::string folded(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string codeName(const gcode::CodeInfo& row) {
  std::string s(1, row.letter);
  if (row.number < 10) s += '0';
  return s + std::to_string(row.number);
}

}  // namespace

std::vector<HelpHit> searchHelp(std::string_view query, gcode::Dialect dialect) {
  std::vector<std::string> terms;
  std::string term;
  for (char c : folded(query) + " ") {
    if (c == ' ' || c == '\t' || c == ',') {
      if (!term.empty()) terms.push_back(term);
      term.clear();
    } else {
      term += c;
    }
  }
  std::vector<HelpHit> hits;
  if (terms.empty()) return hits;
  // The machine's own rows, under its G-code system's numbers (G33 in system B).
  std::vector<const gcode::CodeInfo*> rows;
  for (const gcode::CodeInfo& a : gcode::codeTable()) {
    if (!a.in(dialect)) continue;
    if (const gcode::CodeInfo* own =
            gcode::findCode(a.letter, gcode::numberInSystem(a.letter, a.number, dialect), dialect);
        own && own->action == a.action)
      rows.push_back(own);
  }
  for (const gcode::CodeInfo& s : gcode::systemOnlyRows())
    if (const gcode::CodeInfo* own = gcode::findCode(s.letter, s.number, dialect); own && own->action == s.action)
      rows.push_back(own);
  for (const gcode::CodeInfo* ownRow : rows) {
    const gcode::CodeInfo& row = *ownRow;
    const std::string code = folded(codeName(row));
    const std::string names = folded(std::string(row.nameEn) + " " + std::string(row.nameTh));
    const std::string rest =
        folded(std::string(row.exampleEn) + " " + std::string(row.exampleTh) + " " +
               explainCode(row.letter, row.number, dialect, Lang::En) + " " +
               explainCode(row.letter, row.number, dialect, Lang::Th) + " " + std::string(keywords(row.action)));
    int score = 0;
    bool all = true;
    for (const std::string& t : terms) {
      // "g1" finds G01 as the control reads it.
      const bool isCode =
          t == code || (t.size() >= 2 && t[0] == code[0] && t.find_first_not_of("0123456789", 1) == std::string::npos &&
                        std::stoi(t.substr(1, 6)) == row.number);
      if (isCode)
        score += 100;
      else if (names.find(t) != std::string::npos)
        score += 10;
      else if (rest.find(t) != std::string::npos)
        score += 1;
      else
        all = false;
    }
    if (all && std::none_of(hits.begin(), hits.end(),
                            [&row](const HelpHit& h) { return h.letter == row.letter && h.number == row.number; }))
      hits.push_back({row.letter, row.number, score});
  }
  std::stable_sort(hits.begin(), hits.end(), [](const HelpHit& a, const HelpHit& b) { return a.score > b.score; });
  return hits;
}

}  // namespace klueng::core::machine
