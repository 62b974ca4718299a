#include "klueng/core/help/explain.h"

#include <cmath>
#include <numbers>
#include <string_view>
#include <vector>

#include "klueng/core/gcode/address_table.h"
#include "klueng/core/gcode/decimal_point.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/gcode/word_format.h"

namespace klueng::core::machine {

namespace {

using gcode::Block;
using gcode::CodeAction;
using gcode::Word;

// "30", "-59.8", "0.25": what the number says, no trailing zeros.
std::string plain(double v) {
  std::string s = gcode::formatFixed(v, 3);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string pick(gcode::Phrase p, Lang lang) { return std::string(lang == Lang::Th ? p.th : p.en); }

class Explainer {
 public:
  Explainer(const Block& b, const StateSnapshot* after, gcode::Dialect dialect, Lang lang,
            std::string_view statementText)
      : b_(b), after_(after), dialect_(dialect), th_(lang == Lang::Th), lang_(lang), statementText_(statementText) {}

  std::string run() {
    std::string head;
    for (const Word& w : b_.words) head += (head.empty() ? "" : " ") + w.text();
    if (b_.statement().kind != gcode::StatementKind::None) {
      std::string text(statementText_);
      while (!text.empty() && (text.back() == ' ' || text.back() == '\r')) text.pop_back();
      if (!head.empty() && text.empty()) text = head;
      return (text.empty() ? std::string() : text + ": ") + statement();
    }
    codes('G');
    tool();
    spindleWords();
    motion();
    codes('M');
    if (clauses_.empty()) {
      if (const Word* f = b_.find('F')) add(feedText(f->value));
      if (b_.find('N') && b_.words.size() == 1) add(th_ ? "หมายเลขบล็อก" : "a block number");
      if (!b_.words.empty() && b_.words.front().letter == 'O') add(th_ ? "หมายเลขโปรแกรม" : "the program's number");
    }
    std::string out = head + ":";
    for (std::size_t i = 0; i < clauses_.size(); ++i) out += (i == 0 ? " " : "; ") + clauses_[i];
    if (clauses_.empty()) out += th_ ? " ไม่มีคำสั่งให้เครื่องทำงาน" : " nothing for the machine to do";
    return out;
  }

 private:
  void add(std::string s) {
    if (!s.empty()) clauses_.push_back(std::move(s));
  }

  const gcode::CodeInfo* info(const Word& w) const {
    return w.hasDecimalPoint ? nullptr : gcode::findCode(w.letter, w.code(), dialect_);
  }

  std::string feedText(double f) const {
    const bool perMinute = after_ ? after_->modal.feedMode == FeedMode::PerMinute : false;
    if (!after_) return th_ ? "อัตราป้อน F" + plain(f) : "feed F" + plain(f);
    if (th_) return "ป้อน " + plain(f) + (perMinute ? " มม./นาที" : " มม./รอบ");
    return plain(f) + (perMinute ? " mm per minute" : " mm per revolution");
  }

  void codes(char letter) {
    for (const Word* w : b_.all(letter)) {
      const gcode::CodeInfo* row = info(*w);
      if (!row || row->group == gcode::ModalGroup::Motion) continue;  // motion: with its target below
      std::string text = explainCode(letter, w->code(), dialect_, lang_);
      switch (row->action) {
        case CodeAction::Dwell:
          if (const Word* t = b_.find('X') ? b_.find('X') : b_.find('U'))
            text += th_ ? " " + plain(t->value) + " วินาที" : " " + plain(t->value) + " s";
          else if (const Word* p = b_.find('P'))
            text += th_ ? " P" + plain(p->value) : " P" + plain(p->value);
          break;
        case CodeAction::CoordinateSet:
          if (const Word* s = b_.find('S'))
            text = th_ ? "จำกัดความเร็วรอบเพลาไม่เกิน " + plain(s->value) + " รอบ/นาที"
                       : "limit the spindle to " + plain(s->value) + " rpm";
          else
            text = th_ ? "ตั้งพิกัดให้ตำแหน่งมีดปัจจุบันอ่านค่าตามที่กำหนด"
                       : "set the coordinates so the tool here reads the given X and Z";
          break;
        case CodeAction::LocalCall:
        case CodeAction::SubprogramCall:
          if (const Word* p = b_.find('P')) {
            const std::string n = plain(p->value);
            text = row->action == CodeAction::LocalCall
                       ? (th_ ? "เรียกบล็อกตั้งแต่ N" + n + " เป็นโปรแกรมย่อยแล้วกลับมา"
                              : "run the blocks from N" + n + " as a subprogram and come back")
                       : (th_ ? "เรียกโปรแกรมย่อย O" + n + " แล้วกลับมา" : "run subprogram O" + n + " and come back");
          }
          break;
        default: break;
      }
      add(w->text() + " " + text);
      if (gcode::isCuttingCycle(row->action)) cycleWords(row->action);
    }
  }

  // The words of a cycle block, said plainly (the first G71/G72 block has depth U and retract R).
  void cycleWords(CodeAction a) {
    const Word* p = b_.find('P');
    const Word* q = b_.find('Q');
    const bool profile = a == CodeAction::Finishing || a == CodeAction::TurnRoughing || a == CodeAction::FaceRoughing ||
                         a == CodeAction::PatternRepeating;
    if (profile && p && q)
      add(th_ ? "รูปร่างจากบล็อก N" + plain(p->value) + " ถึง N" + plain(q->value)
              : "the profile is blocks N" + plain(p->value) + " to N" + plain(q->value));
    const Word* u = b_.find('U');
    const Word* r = b_.find('R');
    if ((a == CodeAction::TurnRoughing || a == CodeAction::FaceRoughing) && u && r && !p)
      add(th_ ? "ป้อนลึกเที่ยวละ " + plain(u->value) + " มม. ถอยมีด " + plain(r->value) + " มม."
              : "depth of cut " + plain(u->value) + " mm per pass, retract " + plain(r->value) + " mm");
    else if (profile && p && u)
      add(th_ ? "เผื่อกลึงละเอียด U" + plain(u->value) + " (เส้นผ่าศูนย์กลาง)"
              : "finishing allowance U" + plain(u->value) + " on the diameter");
    if (const Word* f = b_.find('F'); f && profile) add(feedText(f->value));
  }

  void tool() {
    const Word* t = b_.find('T');
    if (!t || t->expr >= 0) return;
    const int code = t->code();
    // T1 .. T99 name a station alone; T0101 a station and its offset.
    const auto [station, offset] = code >= 100 ? gcode::splitToolNumber(code) : gcode::ToolNumber{code, 0};
    const std::string s = gcode::formatFixed(station, 0), o = gcode::formatFixed(offset, 0);
    const std::string two = (station < 10 ? "0" : "") + s, twoOffset = (offset < 10 ? "0" : "") + o;
    if (offset == 0)
      add(th_ ? "เปลี่ยนมีดตัดหมายเลข " + two + " ยกเลิกออฟเซต" : "turn to tool " + two + ", no offset");
    else
      add(th_ ? "เปลี่ยนมีดตัดหมายเลข " + two + " ใช้ออฟเซต " + twoOffset
              : "turn to tool " + two + " with offset " + twoOffset);
  }

  void spindleWords() {
    const Word* s = b_.find('S');
    if (!s || s->expr >= 0) return;
    for (const Word* g : b_.all('G'))
      if (const gcode::CodeInfo* row = info(*g); row && row->action == CodeAction::CoordinateSet)
        return;  // G50 S: said above
    const bool surface = after_ && after_->modal.spindleMode == SpindleMode::ConstantSurface;
    if (surface)
      add(th_ ? "ความเร็วตัด " + plain(s->value) + " ม./นาที" : "cutting speed " + plain(s->value) + " m/min");
    else if (after_)
      add(th_ ? "ความเร็วรอบ " + plain(s->value) + " รอบ/นาที" : "spindle speed " + plain(s->value) + " rpm");
    else
      add(th_ ? "ค่า S" + plain(s->value) : "S" + plain(s->value));
  }

  void motion() {
    const Word* x = b_.find('X');
    const Word* z = b_.find('Z');
    const Word* u = b_.find('U');
    const Word* w = b_.find('W');
    const Word* g = nullptr;
    const gcode::CodeInfo* row = nullptr;
    for (const Word* c : b_.all('G'))
      if (const gcode::CodeInfo* r = info(*c)) {
        if (r->group == gcode::ModalGroup::Motion) g = c, row = r;
        if (r->group == gcode::ModalGroup::NonModal || r->group == gcode::ModalGroup::CannedCycle)
          return;  // their words are theirs
      }
    if (!(x || z || u || w) && !g) return;
    CodeAction a = row ? row->action : CodeAction::None;
    if (!row && after_) {
      static constexpr CodeAction kModes[] = {CodeAction::Rapid, CodeAction::Line, CodeAction::ArcCw,
                                              CodeAction::ArcCcw, CodeAction::Thread};
      a = kModes[static_cast<int>(after_->modal.motion)];
    }
    // No G word: the modal motion's row in the dialect says it.
    const gcode::CodeInfo* modal = g ? nullptr : gcode::findAction('G', a, dialect_);
    std::string text = g       ? explainCode('G', g->code(), dialect_, lang_)
                       : modal ? pick(modal->says, lang_)
                               : std::string();
    if (text.empty()) return;
    if ((a == CodeAction::ArcCw || a == CodeAction::ArcCcw) && b_.find('R'))
      text += (th_ ? " รัศมี " : " of radius ") + plain(b_.find('R')->value);
    std::string target;
    if (x) target += "Ø" + plain(x->value);
    if (u)
      target += std::string(target.empty() ? "" : " ") +
                (th_ ? "U" + plain(u->value) + " (ระยะเส้นผ่าศูนย์กลาง)" : "U" + plain(u->value) + " on the diameter");
    if (z) target += std::string(target.empty() ? "" : th_ ? " " : " at ") + "Z" + plain(z->value);
    if (w)
      target += std::string(target.empty() ? "" : " ") +
                (th_ ? "W" + plain(w->value) + " ตามแนวแกน Z" : "W" + plain(w->value) + " along Z");
    if (!target.empty()) text += (th_ ? " ไปที่ " : " to ") + target;
    const bool feedMove = a == CodeAction::Line || a == CodeAction::ArcCw || a == CodeAction::ArcCcw;
    if (a == CodeAction::Thread) {
      if (const Word* f = b_.find('F'))
        text += th_ ? " ระยะพิตช์ " + plain(f->value) + " มม." : ", lead " + plain(f->value) + " mm";
    } else if (feedMove && after_ && after_->modal.feed > 0.0) {
      text += (th_ ? " " : ", ") + feedText(after_->modal.feed);
    } else if (feedMove && b_.find('F')) {
      text += (th_ ? " " : ", ") + feedText(b_.find('F')->value);
    }
    add(text);
    if (feedMove && after_ && after_->modal.spindleMode == SpindleMode::ConstantSurface && after_->modal.sWord > 0.0 &&
        after_->machine.rpm > 0.0) {
      const std::string rpm = gcode::formatFixed(std::round(after_->machine.rpm), 0);
      add(th_ ? "ที่ความเร็วตัด " + plain(after_->modal.sWord) + " ม./นาที (G96) เพลาหมุน " + rpm + " รอบ/นาที ที่ตำแหน่งนี้"
              : "at " + plain(after_->modal.sWord) + " m/min (G96) the spindle turns " + rpm + " rpm here");
    }
  }

  std::string statement() const {
    using K = gcode::StatementKind;
    switch (b_.statement().kind) {
      case K::Assign: return th_ ? "กำหนดค่าให้ตัวแปรมาโคร" : "give a macro variable a value";
      case K::Goto: return th_ ? "กระโดดไปยังบล็อกที่กำหนด" : "jump to the given block";
      case K::If:
        return b_.statement().then
                   ? (th_ ? "ถ้าเงื่อนไขเป็นจริง กำหนดค่าให้ตัวแปร" : "if the condition holds, give a variable a value")
                   : (th_ ? "ถ้าเงื่อนไขเป็นจริง กระโดดไปยังบล็อกที่กำหนด" : "if the condition holds, jump to the given block");
      case K::While: return th_ ? "ทำซ้ำถึง END ตราบที่เงื่อนไขยังเป็นจริง" : "repeat up to END while the condition holds";
      case K::Do: return th_ ? "ทำซ้ำถึง END ไม่รู้จบ (ออกด้วย GOTO)" : "repeat up to END without end (GOTO leaves)";
      case K::End: return th_ ? "จบช่วงทำซ้ำ กลับไปที่ WHILE/DO" : "end of the loop: back to its WHILE/DO";
      case K::Output: return th_ ? "ส่งข้อมูลออกภายนอก (ไม่มีผลกับการกลึง)" : "send data out (nothing to machine)";
      default: return {};
    }
  }

  const Block& b_;
  const StateSnapshot* after_;
  gcode::Dialect dialect_;
  bool th_;
  Lang lang_;
  std::string_view statementText_;
  std::vector<std::string> clauses_;
};

}  // namespace

std::string explainCode(char letter, int number, gcode::Dialect dialect, Lang lang) {
  const gcode::CodeInfo* row = gcode::findCode(letter, number, dialect);
  return row ? pick(row->says, lang) : std::string();
}

std::string explainPass(const Timeline& timeline, int moveIndex, Lang lang) {
  const auto& moves = timeline.moves;
  if (moveIndex < 0 || moveIndex >= static_cast<int>(moves.size())) return {};
  const int block = moves[static_cast<std::size_t>(moveIndex)].blockIndex;
  int first = moveIndex, last = moveIndex;
  while (first > 0 && moves[static_cast<std::size_t>(first - 1)].blockIndex == block) --first;
  while (last + 1 < static_cast<int>(moves.size()) && moves[static_cast<std::size_t>(last + 1)].blockIndex == block)
    ++last;
  int passes = 0, current = 0;
  bool inPass = false;
  for (int i = first; i <= last; ++i) {
    const MoveKind k = moves[static_cast<std::size_t>(i)].kind;
    const bool feed = k == MoveKind::Line || k == MoveKind::Arc || k == MoveKind::Thread;
    if (feed && !inPass) ++passes;
    inPass = feed || (inPass && k == MoveKind::Dwell);
    if (i == moveIndex) current = passes;
  }
  if (passes <= 1 || current == 0) return {};
  return lang == Lang::Th ? "เที่ยวที่ " + std::to_string(current) + " จาก " + std::to_string(passes)
                          : "pass " + std::to_string(current) + " of " + std::to_string(passes);
}

std::string explainBlock(const gcode::Block& block, const StateSnapshot& after, gcode::Dialect dialect, Lang lang,
                         std::string_view statementText) {
  return Explainer(block, &after, dialect, lang, statementText).run();
}

std::string explainLineText(std::string_view lineText, int fileLine, const StateSnapshot* after, gcode::Dialect dialect,
                            Lang lang, bool lengthsInIncrements) {
  gcode::Program program = gcode::parse(lineText, fileLine);
  if (program.blocks.empty()) return {};
  // The units in force where it ran; unknown without a run: the dialect's power-on units.
  const gcode::InputUnits units =
      after ? (after->modal.units == Units::Inch ? gcode::InputUnits::Inch : gcode::InputUnits::Millimetre)
            : gcode::machineProfile(dialect).powerOnUnits;
  if (lengthsInIncrements) gcode::readLengthsInIncrements(program, units, dialect);
  return Explainer(program.blocks.front(), after, dialect, lang, lineText).run();
}

std::string explainWords(const gcode::Block& block, gcode::Dialect dialect, Lang lang, std::string_view statementText) {
  return Explainer(block, nullptr, dialect, lang, statementText).run();
}

}  // namespace klueng::core::machine
