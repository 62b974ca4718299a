#include "klueng/core/control/control.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "klueng/core/comp/nose_comp.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/geometry.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/kinematics.h"
#include "klueng/core/number_read.h"

namespace klueng::core::control {

namespace {

namespace kc = core::codes;
using machine::Move;
using machine::MoveKind;
using machine::SpindleDir;

double round3(double v) { return std::round(v * 1000.0) / 1000.0; }
std::string mm3(double v) { return fmt::format("{:.3f}", round3(v) == 0.0 ? 0.0 : round3(v)); }

// The word of a code action in this dialect ("G97", "M03"): dialects are data (gcode/code_table.h).
std::string controlCodeWord(gcode::CodeAction action, gcode::Dialect dialect) {
  for (const gcode::CodeInfo& row : gcode::codeTable()) {
    if (row.action != action || !row.in(dialect)) continue;
    const int n = gcode::numberInSystem(row.letter, row.number, dialect);
    if (n >= 0) return fmt::format("{}{:02d}", row.letter, n);
  }
  return {};
}

const char* modeKey(Mode m) {
  switch (m) {
    case Mode::Edit: return "EDIT";
    case Mode::Memory: return "MEM";
    case Mode::Mdi: return "MDI";
    case Mode::Jog: return "JOG";
    case Mode::Handle: return "HANDLE";
    case Mode::ZeroReturn: return "ZERO RETURN";
  }
  return "";
}

// A deterministic spread of tool lengths, so every station needs its own touch-off.
AxisValues defaultTip(const io::MachineConfig& m, int station) {
  const double dz = round3(std::fmod(station * 17.371, 40.0) - 20.0);
  const double dx = round3(std::fmod(station * 11.913, 24.0) - 12.0);
  return {m.referenceX + dx, m.referenceZ + dz};
}

Vec2 barPoint(const AxisValues& v) { return zx(v.z, v.x / 2.0); }

}  // namespace

Layout layoutFor(gcode::Dialect dialect) { return dialect == gcode::Dialect::Haas ? Layout::Haas : Layout::Fanuc; }

int stepFeedOverride(int percent, int steps) { return std::clamp((percent / 10 + steps) * 10, 0, 150); }

int stepRapidOverride(int percent, int steps) {
  static constexpr std::array<int, 4> kSteps{0, 25, 50, 100};
  int i = 0;
  while (i + 1 < 4 && kSteps[static_cast<std::size_t>(i)] < percent) ++i;
  return kSteps[static_cast<std::size_t>(std::clamp(i + steps, 0, 3))];
}

int stepSpindleOverride(int percent, int steps) { return std::clamp((percent / 10 + steps) * 10, 50, 120); }

namespace {

// The feed mode of each move (G98 / G99), from the snapshots that end its blocks.
std::vector<machine::FeedMode> movesFeedMode(const machine::Timeline& timeline) {
  std::vector<machine::FeedMode> feedMode(timeline.moves.size(), machine::FeedMode::PerRev);
  std::size_t next = 0;
  for (const machine::StateSnapshot& s : timeline.snapshots)
    for (; next < feedMode.size() && next < static_cast<std::size_t>(s.moveEnd); ++next)
      feedMode[next] = s.modal.feedMode;
  return feedMode;
}

// How long a move takes at these overrides (+inf: it never ends, feed override 0).
double overriddenSeconds(const Move& in, machine::FeedMode feedMode, const Overrides& o, const io::MachineConfig& m,
                         bool dryRun, double dryRunFeed) {
  const double feed = o.feed / 100.0, spindle = o.spindle / 100.0;
  const double d = in.tEnd - in.tStart;
  switch (in.kind) {
    case MoveKind::Rapid:
      return o.rapid <= 0
                 ? machine::rapidSeconds(in.path, std::min(kRapidF0Rate, m.rapidX), std::min(kRapidF0Rate, m.rapidZ))
                 : d * 100.0 / o.rapid;
    case MoveKind::Dwell: return d;
    case MoveKind::Thread: return d / spindle;  // the feed override is ignored while threading
    case MoveKind::Line:
    case MoveKind::Arc:
      if (feed <= 0.0) return std::numeric_limits<double>::infinity();
      if (dryRun) return in.path.length() / (dryRunFeed * feed) * 60.0;
      return feedMode == machine::FeedMode::PerMinute ? d / feed : d / (feed * spindle);
  }
  return d;
}

}  // namespace

OverrideClock::OverrideClock(const machine::Timeline& timeline, const Overrides& o, const io::MachineConfig& m,
                             bool dryRun, double dryRunFeed)
    : timeline_(&timeline) {
  const std::vector<machine::FeedMode> feedMode = movesFeedMode(timeline);
  rate_.reserve(timeline.moves.size());
  for (std::size_t i = 0; i < timeline.moves.size(); ++i) {
    const Move& mv = timeline.moves[i];
    const double d = mv.tEnd - mv.tStart;
    const double nd = overriddenSeconds(mv, feedMode[i], o, m, dryRun, dryRunFeed);
    rate_.push_back(d <= 0.0 ? 1.0 : !std::isfinite(nd) ? 0.0 : nd <= 0.0 ? 1.0 : d / nd);
  }
}

double OverrideClock::advance(double t, double seconds) const {
  if (!timeline_ || timeline_->moves.empty() || seconds <= 0.0) return t + std::max(0.0, seconds);
  const std::vector<Move>& moves = timeline_->moves;
  const int n = static_cast<int>(moves.size());
  int i = t < moves.front().tStart ? 0 : timeline_->moveAt(t);
  double left = seconds;
  while (i < n) {
    const Move& m = moves[static_cast<std::size_t>(i)];
    if (t < m.tStart) {  // between moves: the timeline's own time
      const double gap = m.tStart - t;
      if (left <= gap) return t + left;
      t = m.tStart;
      left -= gap;
    }
    if (t >= m.tEnd) {
      ++i;
      continue;
    }
    const double r = rate(i);
    if (r <= 0.0) return t;  // feed override 0: the axes stand
    const double need = (m.tEnd - t) / r;
    if (left <= need) return t + left * r;
    t = m.tEnd;
    left -= need;
    ++i;
  }
  return t + left;  // past the last move
}

machine::Timeline withOverrides(const machine::Timeline& timeline, const Overrides& o, const io::MachineConfig& m,
                                bool dryRun, double dryRunFeed) {
  machine::Timeline out = timeline;
  const std::vector<machine::FeedMode> feedMode = movesFeedMode(timeline);
  const double spindle = o.spindle / 100.0;
  double t = 0.0;
  for (std::size_t i = 0; i < out.moves.size(); ++i) {
    const Move& in = timeline.moves[i];
    Move& mv = out.moves[i];
    const double d = in.tEnd - in.tStart;
    const double nd = overriddenSeconds(in, feedMode[i], o, m, dryRun, dryRunFeed);
    if (in.kind != MoveKind::Dwell && nd > 0.0 && std::isfinite(nd) && d > 0.0) {
      mv.feed = in.feed * d / nd;
      mv.rampUp = static_cast<float>(in.rampUp * nd / d);
      mv.rampDown = static_cast<float>(in.rampDown * nd / d);
    }
    mv.rpm = in.rpm * spindle;
    mv.rpmEnd = in.rpmEnd * spindle;
    mv.tStart = t;
    mv.tEnd = t + nd;
    t = mv.tEnd;
  }
  for (machine::StateSnapshot& s : out.snapshots)
    if (s.moveEnd > 0 && static_cast<std::size_t>(s.moveEnd) <= out.moves.size())
      s.time = out.moves[static_cast<std::size_t>(s.moveEnd - 1)].tEnd;
  return out;
}

std::optional<MeasureInput> parseMeasureInput(std::string_view text) {
  auto trim = [](std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
  };
  text = trim(text);
  if (text.size() < 2) return std::nullopt;
  MeasureInput in;
  const char a = static_cast<char>(std::toupper(static_cast<unsigned char>(text.front())));
  if (a != 'X' && a != 'Z') return std::nullopt;
  in.axis = a == 'X' ? Axis::X : Axis::Z;
  const std::string_view number = trim(text.substr(1));
  if (number.empty() || number.front() == '+') return std::nullopt;
  const auto [end, ec] = readDouble(number.data(), number.data() + number.size(), in.value);
  if (ec != std::errc{} || end != number.data() + number.size() || !std::isfinite(in.value)) return std::nullopt;
  return in;
}

Control::Control(machine::MachineSetup setup, io::JobHeader stock, gcode::Dialect dialect)
    : setup_(std::move(setup)), header_(std::move(stock)), dialect_(dialect), layout_(layoutFor(dialect)) {
  const io::MachineConfig& m = setup_.machine;
  for (int s = 1; s <= io::kMaxStations; ++s) trueTips_[static_cast<std::size_t>(s - 1)] = defaultTip(m, s);
  for (int n = 1; n <= io::kOffsetCount; ++n) {
    OffsetRow& r = row(n);
    r.wear = {setup_.offsets.at(n).x, setup_.offsets.at(n).z};
    // A station with a tool has its true geometry, as a machine set up the day before.
    if (n <= io::kMaxStations && !setup_.tools.bitmapPath(n).empty()) r.geometry = trueGeometry(n);
  }
  // Power on: the turret stands where it was switched off, short of the reference point.
  machine_ = {std::min(0.0, m.startX - m.referenceX), std::min(-50.0, m.startZ - m.referenceZ - 50.0)};
  rebuildSim();
}

std::string Control::controlLabel(std::string_view code) const {
  const bool fanuc = layout_ == Layout::Fanuc;
  if (code == kc::kNotReferenced) return fanuc ? "PS0224 ZERO RETURN NOT FINISHED" : "ZERO RETURN REQUIRED";
  if (code == kc::kOvertravel) return fanuc ? "OT0500 OVERTRAVEL (SOFT 1)" : "TRAVEL LIMIT";
  return std::string(code);
}

AxisValues Control::trueTip(int station) const { return trueTips_.at(static_cast<std::size_t>(station - 1)); }
void Control::setTrueTip(int station, AxisValues tip) { trueTips_.at(static_cast<std::size_t>(station - 1)) = tip; }

AxisValues Control::trueGeometry(int station) const {
  const AxisValues t = trueTip(station);
  return {-t.x - shift_.x, -t.z - shift_.z};
}

void Control::forgetGeometry() {
  for (OffsetRow& r : rows_) {
    r.geometry = {};
    r.measuredX = r.measuredZ = false;
  }
  exercise_ = true;
}

void Control::setMode(Mode m) {
  mode_ = m;
  if (m != Mode::Mdi) mdiTarget_.reset();
}

void Control::setHandleStep(int step) { handleStep_ = step >= 100 ? 100 : step >= 10 ? 10 : 1; }

AxisValues Control::absolutePosition() const {
  const OffsetRow& r = row(station_);
  return {machine_.x - r.geometry.x - r.wear.x - shift_.x, machine_.z - r.geometry.z - r.wear.z - shift_.z};
}

AxisValues Control::relativePosition() const {
  return {machine_.x - relativeOrigin_.x, machine_.z - relativeOrigin_.z};
}

void Control::originRelative(Axis a) {
  (a == Axis::X ? relativeOrigin_.x : relativeOrigin_.z) = a == Axis::X ? machine_.x : machine_.z;
}

AxisValues Control::distanceToGo() const {
  if (!mdiTarget_) return {};
  return {mdiTarget_->x - machine_.x, mdiTarget_->z - machine_.z};
}

AxisValues Control::tip() const {
  const AxisValues t = trueTip(station_);
  return {machine_.x + t.x, machine_.z + t.z};
}

AxisValues Control::travelMin() const {
  const io::MachineConfig& m = setup_.machine;
  return {std::min(0.0, m.travelXMin - m.referenceX), std::min(0.0, m.travelZMin - m.referenceZ)};
}

AxisValues Control::travelMax() const {
  const io::MachineConfig& m = setup_.machine;
  return {std::min(0.0, m.travelXMax - m.referenceX), std::min(0.0, m.travelZMax - m.referenceZ)};
}

std::optional<Diagnostic> Control::indexTurret(int station) {
  if (alarm_) return diag(Severity::Alarm, kc::kResetFirst, {alarm_->code});
  if (station < 1 || station > setup_.machine.turretStations)
    return diag(Severity::Error, kc::kMeasureWithoutTool, {fmt::format("{:02d}", station)});
  station_ = station;
  touchedStopped_ = false;
  mdiTarget_.reset();
  return std::nullopt;
}

void Control::setSpindle(SpindleDir dir) { spindle_ = dir; }

double Control::actualRpm() const {
  if (spindle_ == SpindleDir::Stopped) return 0.0;
  return std::min(sWord_ * overrides_.spindle / 100.0, setup_.machine.maxSpindleRpm);
}

Diagnostic Control::diag(Severity s, const char* code, std::vector<std::string> args) const {
  Diagnostic d;
  d.severity = s;
  d.code = code;
  d.args = std::move(args);
  return d;
}

bool Control::motionAllowed(Mode wanted, const char* key, MotionResult& out) {
  if (alarm_) {
    out.stop = diag(Severity::Alarm, kc::kResetFirst, {alarm_->code});
    return false;
  }
  if (mode_ != wanted) {
    out.stop = diag(Severity::Note, kc::kKeyNotInMode, {key, modeKey(wanted)});
    return false;
  }
  if (overrides_.feed == 0 && wanted != Mode::ZeroReturn) {
    out.stop = diag(Severity::Note, kc::kFeedOverrideZero);
    return false;
  }
  return true;
}

void Control::rebuildSim() {
  cut::CutSetup cs = cut::CutSetup::from(header_, setup_);
  cut::CutOptions options;
  // Fine enough that a handwheel click of 0.001 mm into the face takes a chip.
  options.resolution = std::clamp(cs.stockLength / 100000.0, 0.001, cut::kDefaultResolution);
  options.checkpointBudgetBytes = 0;
  sim_ = std::make_unique<cut::CutSimulator>(moves_, cs, options);
}

MotionResult Control::runMoves(std::vector<Move> moves) {
  MotionResult result;
  if (moves.empty()) return result;
  const double t0 = moves_.cycleTime();
  for (Move& m : moves) {
    m.tStart += t0;
    m.tEnd += t0;
    moves_.moves.push_back(m);
  }
  const double removedBefore = sim_->removedVolume();
  sim_->advanceTo(moves_.cycleTime());
  result.moved = true;
  if (const auto& a = sim_->alarm()) {
    Diagnostic stop = *a;
    // The turret stops just short of where it touched, and the record of the
    // moves is cut back there, so the bar replays without the alarm.
    const double tAlarm = sim_->time();
    int i = moves_.moveAt(tAlarm);
    if (i < 0) i = 0;
    Move& hit = moves_.moves[static_cast<std::size_t>(i)];
    const double length = hit.path.length();
    const double s = hit.tEnd > hit.tStart ? hit.fractionAt(tAlarm) : 0.0;
    const double back = length > 0.0 ? std::max(0.0, s - 0.002 / length) : 0.0;
    moves_.moves.resize(static_cast<std::size_t>(i) + 1);
    if (back <= 0.0) {
      moves_.moves.pop_back();
    } else {
      hit.path = Segment::line(hit.path.start, hit.path.pointAt(back));
      hit.tEnd = hit.tStart + (hit.tEnd - hit.tStart) * back;
    }
    rebuildSim();
    sim_->advanceTo(moves_.cycleTime());
    if (stop.code == kc::kCutWithSpindleStopped) {
      touchedStopped_ = true;
      stop = diag(Severity::Warning, kc::kTouchedSpindleStopped,
                  {fmt::format("{:02d}", station_), stop.args.size() > 0 ? stop.args[0] : "",
                   stop.args.size() > 1 ? stop.args[1] : ""});
      notices_.push_back(stop);
      result.cut = true;
    } else {
      alarm_ = stop;
    }
    result.stop = stop;
  } else {
    result.cut = sim_->removedVolume() > removedBefore;
  }
  if (result.cut && spindle_ != SpindleDir::Stopped) touchedStopped_ = false;
  // Where the turret is now: the tip at the end of the last move, less the tool's tip vector.
  if (!moves_.moves.empty()) {
    const Move& last = moves_.moves.back();
    const int tool = last.tool >= 1 && last.tool <= io::kMaxStations ? last.tool : station_;
    const AxisValues t = trueTip(tool);
    machine_ = {2.0 * xOf(last.path.end) - t.x, zOf(last.path.end) - t.z};
  }
  return result;
}

MotionResult Control::moveTo(const AxisValues& wanted, bool rapid, double feed) {
  MotionResult result;
  AxisValues target = wanted;
  std::optional<Diagnostic> limit;
  // Soft limits hold once the axis knows where it is (after its zero return).
  const AxisValues lo = travelMin(), hi = travelMax();
  auto clampAxis = [&](double& v, double from, double mn, double mx, const char* axis, bool ref) {
    if (!ref) return;
    if (v > mx && v > from) {
      v = std::max(from, mx);
      limit = diag(Severity::Alarm, kc::kOvertravel, {controlLabel(kc::kOvertravel), axis, mm3(mx)});
    } else if (v < mn && v < from) {
      v = std::min(from, mn);
      limit = diag(Severity::Alarm, kc::kOvertravel, {controlLabel(kc::kOvertravel), axis, mm3(mn)});
    }
  };
  clampAxis(target.x, machine_.x, lo.x, hi.x, "X", referenced(Axis::X));
  clampAxis(target.z, machine_.z, lo.z, hi.z, "Z", referenced(Axis::Z));
  if (limit && limit->args.size() > 0 && layout_ == Layout::Fanuc && limit->args.size() > 2) {
    const bool plus = (limit->args[1] == "X" ? wanted.x > machine_.x : wanted.z > machine_.z);
    limit->args[0] = plus ? "OT0500 + OVERTRAVEL (SOFT 1)" : "OT0501 - OVERTRAVEL (SOFT 1)";
  }
  if (target == machine_) {
    if (limit) alarm_ = limit;
    result.stop = limit;
    return result;
  }
  const AxisValues t = trueTip(station_);
  Move m;
  m.path = Segment::line(barPoint({machine_.x + t.x, machine_.z + t.z}), barPoint({target.x + t.x, target.z + t.z}));
  m.kind = rapid ? MoveKind::Rapid : MoveKind::Line;
  m.tool = station_;
  m.offset = station_ <= io::kOffsetCount ? station_ : 0;
  if (m.offset > 0) m.noseCentre = -setup_.offsets.at(m.offset).r * comp::tipVector(setup_.offsets.at(m.offset).tip);
  m.spindle = spindle_;
  m.rpm = m.rpmEnd = actualRpm();
  const io::MachineConfig& mc = setup_.machine;
  if (rapid) {
    const double f = overrides_.rapid / 100.0;
    const double rx = overrides_.rapid <= 0 ? std::min(kRapidF0Rate, mc.rapidX) : mc.rapidX * f;
    const double rz = overrides_.rapid <= 0 ? std::min(kRapidF0Rate, mc.rapidZ) : mc.rapidZ * f;
    m.feed = std::max(rx, rz);
    m.tEnd = machine::rapidSeconds(m.path, rx, rz);
  } else {
    m.feed = feed;
    m.tEnd = m.path.length() / feed * 60.0;
  }
  MotionResult r = runMoves({m});
  if (!r.stop && limit) {
    alarm_ = limit;
    r.stop = limit;
  }
  return r;
}

MotionResult Control::zeroReturn(Axis a) {
  MotionResult r;
  if (!motionAllowed(Mode::ZeroReturn, a == Axis::X ? "+X" : "+Z", r)) return r;
  AxisValues target = machine_;
  (a == Axis::X ? target.x : target.z) = 0.0;
  const bool wasRef = referenced(a);
  referenced_[a == Axis::X ? 0 : 1] = false;  // no soft limit on the way home
  r = moveTo(target, true, 0.0);
  referenced_[a == Axis::X ? 0 : 1] = wasRef || !alarm_;
  if (!alarm_) r.moved = true;
  return r;
}

bool Control::homedForJog(Axis a, MotionResult& out) const {
  // Haas: "before you can jog an axis, the machine must establish its home position" (NGC
  // operator's manual, Jog Mode; Setting 53 Jog w/o Zero Return is OFF at power-on). A Fanuc
  // jogs before its reference return, without soft limits.
  if (layout_ != Layout::Haas || referenced(a)) return true;
  out.stop = diag(Severity::Alarm, kc::kNotReferenced, {controlLabel(kc::kNotReferenced), a == Axis::X ? "X" : "Z"});
  return false;
}

MotionResult Control::jog(Axis a, double distance, bool rapid) {
  MotionResult r;
  if (!motionAllowed(Mode::Jog, a == Axis::X ? (distance > 0 ? "+X" : "-X") : (distance > 0 ? "+Z" : "-Z"), r))
    return r;
  if (!homedForJog(a, r)) return r;
  AxisValues target = machine_;
  (a == Axis::X ? target.x : target.z) += distance;
  return moveTo(target, rapid, jogFeed * overrides_.feed / 100.0);
}

MotionResult Control::handle(int clicks) {
  MotionResult r;
  if (!motionAllowed(Mode::Handle, "HANDLE", r)) return r;
  if (!homedForJog(handleAxis_, r)) return r;
  AxisValues target = machine_;
  // Whole micrometres: a click never leaves the 0.001 mm grid (X in diameter, as the display).
  double& v = handleAxis_ == Axis::X ? target.x : target.z;
  v = std::round(v * 1000.0 + static_cast<double>(clicks) * handleStep_) / 1000.0;
  // A hand turning the wheel: about 2 m/min at ×100.
  return moveTo(target, false, 2000.0);
}

std::vector<Diagnostic> Control::runMdi(std::string_view text) {
  MotionResult gate;
  if (!motionAllowed(Mode::Mdi, "CYCLE START", gate)) return {*gate.stop};
  if (!referenced(Axis::X) || !referenced(Axis::Z))
    return {diag(Severity::Alarm, kc::kNotReferenced,
                 {controlLabel(kc::kNotReferenced), !referenced(Axis::X) && !referenced(Axis::Z) ? "X Z"
                                                    : !referenced(Axis::X)                       ? "X"
                                                                                                 : "Z"})};
  // What the control remembers between MDI blocks, as blocks before the typed ones
  // (each on its own line: some machines want G98/G99 alone).
  std::vector<std::string> prefix;
  prefix.push_back(fmt::format("T{:02d}{:02d}", station_, station_));
  using gcode::CodeAction;
  const bool css = mdiModal_ && mdiModal_->spindleMode == machine::SpindleMode::ConstantSurface;
  if (mdiModal_) {
    prefix.push_back(controlCodeWord(
        mdiModal_->feedMode == machine::FeedMode::PerMinute ? CodeAction::FeedPerMinute : CodeAction::FeedPerRev,
        dialect_));
    if (mdiModal_->feed > 0.0) prefix.push_back(fmt::format("F{}", mdiModal_->feed));
  }
  if (css)
    prefix.push_back(fmt::format("{} S{}", controlCodeWord(CodeAction::ConstantSurface, dialect_), mdiModal_->sWord));
  else
    prefix.push_back(fmt::format("{} S{}", controlCodeWord(CodeAction::ConstantRpm, dialect_), sWord_));
  if (spindle_ != SpindleDir::Stopped)
    prefix.push_back(
        controlCodeWord(spindle_ == SpindleDir::Cw ? CodeAction::SpindleCw : CodeAction::SpindleCcw, dialect_));
  if (coolant) prefix.push_back(controlCodeWord(CodeAction::CoolantOn, dialect_));
  if (mdiModal_ && (mdiModal_->motion == machine::MotionMode::Line || mdiModal_->motion == machine::MotionMode::Rapid))
    prefix.push_back(controlCodeWord(
        mdiModal_->motion == machine::MotionMode::Line ? CodeAction::Line : CodeAction::Rapid, dialect_));
  io::ProgramFile file;
  file.header = header_;
  file.plainGcode = true;
  for (const std::string& p : prefix) file.gcode += p + "\n";
  file.gcode += std::string(text);
  file.gcodeFirstLine = 1 - static_cast<int>(prefix.size());
  machine::MachineSetup setup = runSetup();
  const AxisValues now = tip();
  setup.machine.startX = now.x;
  setup.machine.startZ = now.z;
  job::JobInput input;
  input.file = file;
  input.setup = setup;
  input.inferTools = false;  // the turret as it stands at the panel
  input.folder = std::string();
  input.run.dialect = dialect_;
  input.run.optionalStop = optionalStop;
  input.run.blockSkip = blockDelete;
  const std::shared_ptr<const job::Job> job = job::makeJob(std::move(input));
  std::vector<Diagnostic> out = job->diagnostics();
  if (job->hasErrors() || !job->timeline()) return out;
  const machine::Timeline run = withOverrides(*job->timeline(), overrides_, setup_.machine, dryRun, jogFeed);
  if (!run.moves.empty()) {
    const Move& last = run.moves.back();
    const int tool = last.tool >= 1 && last.tool <= io::kMaxStations ? last.tool : station_;
    const AxisValues t = trueTip(tool);
    mdiTarget_ = AxisValues{2.0 * xOf(last.path.end) - t.x, zOf(last.path.end) - t.z};
  }
  const MotionResult r = runMoves(run.moves);
  mdiTarget_.reset();
  if (r.stop) out.push_back(*r.stop);
  if (run.alarm) {
    alarm_ = run.alarm;
    out.push_back(*run.alarm);
  }
  if (!run.snapshots.empty()) {
    const machine::StateSnapshot& s = run.snapshots.back();
    mdiModal_ = s.modal;
    spindle_ = s.machine.spindle;
    coolant = s.machine.coolant;
    if (s.modal.spindleMode == machine::SpindleMode::ConstantRpm && s.modal.sWord > 0.0) sWord_ = s.modal.sWord;
    if (s.machine.tool >= 1 && s.machine.tool <= setup_.machine.turretStations) station_ = s.machine.tool;
  }
  return out;
}

std::optional<Diagnostic> Control::cycleStartRefusal(const std::vector<int>& stationsUsed) const {
  if (alarm_) return diag(Severity::Alarm, kc::kResetFirst, {alarm_->code});
  if (!referenced(Axis::X) || !referenced(Axis::Z))
    return diag(Severity::Alarm, kc::kNotReferenced,
                {controlLabel(kc::kNotReferenced), !referenced(Axis::X) && !referenced(Axis::Z) ? "X Z"
                                                   : !referenced(Axis::X)                       ? "X"
                                                                                                : "Z"});
  if (exercise_) {
    std::string missing;
    for (int s : stationsUsed) {
      if (s < 1 || s > io::kMaxStations) continue;
      const OffsetRow& r = row(s);
      if (!r.measuredX || !r.measuredZ) missing += fmt::format("{}T{:02d}", missing.empty() ? "" : " ", s);
    }
    if (!missing.empty()) return diag(Severity::Alarm, kc::kToolsNotTouchedOff, {missing});
  }
  return std::nullopt;
}

void Control::reset() {
  alarm_.reset();
  mdiTarget_.reset();
}

std::optional<Diagnostic> Control::measure(int n, Axis a, double value) {
  if (n < 1 || n > io::kOffsetCount) return diag(Severity::Error, kc::kMeasureWithoutTool, {fmt::format("{:02d}", n)});
  if (setup_.tools.bitmapPath(station_).empty())
    return diag(Severity::Error, kc::kMeasureWithoutTool, {fmt::format("{:02d}", station_)});
  OffsetRow& r = row(n);
  if (a == Axis::X) {
    r.geometry.x = round3(machine_.x - value - shift_.x);
    r.measuredX = true;
  } else {
    r.geometry.z = round3(machine_.z - value - shift_.z);
    r.measuredZ = true;
  }
  if (touchedStopped_) return diag(Severity::Warning, kc::kMeasuredAfterStoppedTouch, {fmt::format("{:02d}", n)});
  return std::nullopt;
}

std::optional<Diagnostic> Control::measureWorkShift(double z) {
  if (setup_.tools.bitmapPath(station_).empty())
    return diag(Severity::Error, kc::kMeasureWithoutTool, {fmt::format("{:02d}", station_)});
  shift_.z = round3(machine_.z - row(station_).geometry.z - z);
  if (touchedStopped_) return diag(Severity::Warning, kc::kMeasuredAfterStoppedTouch, {"G54"});
  return std::nullopt;
}

double Control::micrometer(double z) const {
  const cut::Stock& s = sim_->stock();
  const int c = s.columnAt(z);
  if (c < 0) return 0.0;
  return round3(2.0 * s.outerRadius(c));
}

AxisValues Control::touchOffError(int station) const {
  const OffsetRow& r = row(station);
  const AxisValues t = trueTip(station);
  return {round3((r.geometry.x + shift_.x) + t.x), round3((r.geometry.z + shift_.z) + t.z)};
}

std::optional<Diagnostic> Control::compareTouchOff(const std::vector<int>& stations) const {
  int worst = 0;
  double worstSize = -1.0;
  for (int s : stations) {
    if (s < 1 || s > io::kMaxStations) continue;
    const AxisValues e = touchOffError(s);
    const double size = std::max(std::abs(e.x), std::abs(e.z));
    if (size > worstSize) {
      worstSize = size;
      worst = s;
    }
  }
  if (worst == 0) return std::nullopt;
  const AxisValues e = touchOffError(worst);
  return diag(Severity::Note, kc::kOffsetsCompared, {fmt::format("{:02d}", worst), mm3(e.x), mm3(e.z)});
}

machine::MachineSetup Control::runSetup() const {
  machine::MachineSetup out = setup_;
  for (int n = 1; n <= io::kMaxStations; ++n) {
    const OffsetRow& r = row(n);
    const AxisValues t = trueTip(n);
    io::Offset& o = out.offsets.at(n);
    // To the nanometre: the sum of 0.001 mm entries carries no float noise into offset.cfg text.
    o.x = std::round((r.wear.x + ((r.geometry.x + shift_.x) + t.x)) * 1e6) / 1e6;
    o.z = std::round((r.wear.z + ((r.geometry.z + shift_.z) + t.z)) * 1e6) / 1e6;
  }
  return out;
}

}  // namespace klueng::core::control
