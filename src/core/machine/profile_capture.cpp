// The capturing sink a G70-G73 reads its profile through (profile_capture.h).
#include "machine/profile_capture.h"

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/gcode/address_table.h"

namespace klueng::core::machine::detail {

void ProfileCapture::motion(const MotionCall& m) {
  cycles::Step s;
  s.kind = m.kind == MoveKind::Rapid ? cycles::StepKind::Rapid : cycles::StepKind::Feed;
  s.path = m.path;
  s.where = m.where;
  // F, S, T of a G70 profile apply from the block's move on.
  s.feed = pendingFeed_;
  s.sWord = pendingS_;
  s.tWord = pendingT_;
  pendingFeed_ = 0.0;
  pendingS_ = pendingT_ = nullptr;
  end_ = m.path.end;
  add(s, m.blockIndex);
}

void ProfileCapture::dwell(const DwellCall& d) {
  if (!withFeed_) return;
  cycles::Step s;
  s.kind = cycles::StepKind::Dwell;
  s.seconds = d.seconds;
  s.path = Segment::line(end_, end_);
  add(s, d.blockIndex);
}

void ProfileCapture::compensation(NoseCompMode mode, double, int) {
  if (!withFeed_) return;
  cycles::Step s;
  s.kind = cycles::StepKind::Compensation;
  s.comp = mode;
  s.path = Segment::line(end_, end_);
  add(s, block_);
}

bool ProfileCapture::refuse(const std::string& what, const gcode::Word* where) {
  alarm(Diagnostic{Severity::Alarm,
                   codes::kProfileCommandNotAllowed,
                   where ? where->range : SourceRange{line_, 1, 0},
                   {what, std::to_string(line_)}});
  return false;
}

bool ProfileCapture::blockAllowed(const CodeWord* motion, const CodeWord* cycle, const CodeWord* oneShot,
                                  const CodeWord* single) {
  for (const CodeWord* c : {cycle, single})
    if (c) return refuse(c->word->text(), c->word);
  if (motion && motion->info->action == gcode::CodeAction::Thread) return refuse(motion->word->text(), motion->word);
  if (oneShot && oneShot->info->action != gcode::CodeAction::Dwell) return refuse(oneShot->word->text(), oneShot->word);
  return true;
}

// A T in a G70 profile: its offset counts from this block's own target on,
// and the cycle changes the tool when it gets there. The roughing cycles ignore it.
bool ProfileCapture::tool(const gcode::Word& t) {
  if (!withFeed_) return true;
  pendingT_ = &words_.emplace_back(t);
  const int number = gcode::splitToolNumber(t.code()).offset;
  if (number == 0) {
    mach_.offsetX = mach_.offsetZ = 0.0;
  } else if (number > 0 && number <= io::kOffsetCount) {  // a negative T (a typing slip the check reports) names none
    const io::Offset& o = offsets_.at(number);
    mach_.offsetX = o.x;
    mach_.offsetZ = o.z;
  }
  return true;
}

// A profile's M codes are not the cycle's business; a call is refused.
bool ProfileCapture::mCodes(const CodeWord* ms, std::size_t& count) {
  for (std::size_t i = 0; i < count; ++i)
    if (ms[i].info->group == gcode::ModalGroup::MSubprogram) return refuse(ms[i].word->text(), ms[i].word);
  count = 0;
  return true;
}

}  // namespace klueng::core::machine::detail
