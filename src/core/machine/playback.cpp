// Playing a timeline back (playback.h).
#include "klueng/core/machine/playback.h"

#include <algorithm>

#include "klueng/core/machine/flow_view.h"

namespace klueng::core::machine {

namespace {
const StateSnapshot& at(const Timeline& t, int i) { return t.snapshots[static_cast<std::size_t>(i)]; }
}  // namespace

StopTarget nextStop(const Timeline& timeline, const StopRequest& request) {
  const int count = static_cast<int>(timeline.snapshots.size());
  const int next = request.done + 1;
  StopTarget target{count - 1, request.endTime, true, false};
  if (next >= count) return target;
  if (request.command != RunCommand::Go) {
    int stop = next;
    if (request.command == RunCommand::StepOver || request.command == RunCommand::StepOut) {
      const int level = request.done >= 0 ? at(timeline, request.done).callLevel : 0;
      const int want = request.command == RunCommand::StepOut ? std::max(0, level - 1) : level;
      stop = nextSnapshotAtLevel(timeline, request.done, want);
      if (stop < 0) stop = count - 1;
    }
    target.snapshot = stop;
    target.time = std::min(at(timeline, stop).time, request.endTime);
    target.isEnd = stop == count - 1 && at(timeline, stop).time >= request.endTime - kPlaybackEps;
    return target;
  }
  for (int j = next; j < count; ++j) {
    const StateSnapshot& s = at(timeline, j);
    // The block the run resumes on has been stopped at already: its breakpoint lets it run.
    const bool breakHere = j > next && s.file == 0 &&
                           ((request.breakpoints && request.breakpoints->count(s.line)) ||
                            (request.runToLine > 0 && s.line >= request.runToLine));
    if (breakHere) return {j - 1, std::min(at(timeline, j - 1).time, request.endTime), false, true};
    // M00, M01 with the switch on (M02/M30 end the run anyway).
    if (s.stopped && j < count - 1 && (!s.optionalStop || request.optionalStop))
      return {j, std::min(s.time, request.endTime), false, false};
  }
  return target;
}

StopTarget stepBackStop(const Timeline& timeline, int done, double time) {
  const double doneTime = done >= 0 ? at(timeline, done).time : 0.0;
  int target = time <= doneTime + kPlaybackEps ? done - 1 : done;
  target = std::max(target, -1);
  return {target, target >= 0 ? at(timeline, target).time : 0.0, false, false};
}

double limitTravel(const Timeline& timeline, double from, double dt, double maxMm) {
  // Walk the path from `from` and stop after maxMm of tool travel.
  const auto& moves = timeline.moves;
  double t = from;
  double budget = maxMm;
  int i = std::max(0, timeline.moveAt(from));
  while (t < from + dt && i < static_cast<int>(moves.size())) {
    const Move& m = moves[static_cast<std::size_t>(i)];
    const double span = m.tEnd - m.tStart;
    const double end = std::min(m.tEnd, from + dt);
    if (span > 0 && end > t && m.kind != MoveKind::Dwell) {
      // Along the move's own speed profile (slower while it accelerates).
      const double length = m.path.length();
      const double done = m.fractionAt(t);
      const double distance = (m.fractionAt(end) - done) * length;
      if (distance > budget && length > 0.0) return m.timeAt(done + budget / length) - from;
      budget -= distance;
    }
    t = std::max(t, end);
    ++i;
  }
  return dt;
}

int shownSnapshot(const Timeline& timeline, int done, double time) {
  const int count = static_cast<int>(timeline.snapshots.size());
  const double doneTime = done >= 0 ? at(timeline, done).time : 0.0;
  if (time > doneTime + kPlaybackEps && done + 1 < count) return done + 1;
  return done;
}

Pose poseAt(const Timeline& timeline, int done, double time) {
  Pose p;
  if (!timeline.moves.empty()) p.position = timeline.positionAt(time);
  const int k = shownSnapshot(timeline, done, time);
  // Stopped by an alarm: the alarmed block's modal words are in force.
  const bool atAlarm = timeline.alarm && timeline.flow.alarmState &&
                       k + 1 >= static_cast<int>(timeline.snapshots.size()) &&
                       time >= timeline.cycleTime() - kPlaybackEps;
  if (atAlarm || (k >= 0 && k < static_cast<int>(timeline.snapshots.size()))) {
    const StateSnapshot& snap = atAlarm ? *timeline.flow.alarmState : at(timeline, k);
    p.hasState = true;
    p.machine = snap.machine;
    p.programmedFeed = snap.modal.feed;
    p.feedMode = snap.modal.feedMode;
    p.rpm = snap.machine.rpm;
  }
  // Inside a move: its feed, and the rpm as G96 changes it along the move.
  const double doneTime =
      done >= 0 && done < static_cast<int>(timeline.snapshots.size()) ? at(timeline, done).time : 0.0;
  const int m = timeline.moveAt(time);
  if (m >= 0 && time < timeline.moves[static_cast<std::size_t>(m)].tEnd - kPlaybackEps &&
      time > doneTime + kPlaybackEps) {
    const Move& move = timeline.moves[static_cast<std::size_t>(m)];
    const double f = move.fractionAt(time);
    p.feedMmPerMin = move.feed;
    p.rpm = move.rpm + (move.rpmEnd - move.rpm) * f;
    p.machine.spindle = move.spindle;
  }
  return p;
}

}  // namespace klueng::core::machine
