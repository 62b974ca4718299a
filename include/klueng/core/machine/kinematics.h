#pragma once
// Spindle speed and machining time of one move (SPEC 10): feed per minute,
// feed per revolution at constant rpm, and under G96 with the rpm recomputed
// continuously along the move as the diameter changes.
#include "klueng/core/comp/segment.h"
#include "klueng/core/machine/sink.h"

namespace klueng::core::machine {

// Spindle rpm with the tool's controlled point at radius xRadius: 0 when the
// spindle is stopped or S is not set; S under G97; under G96
// 1000 * S / (pi * D), D = 2 * |xRadius|, clamped to ctx.rpmCap.
double spindleRpm(const MotionContext& ctx, double xRadius);

// Time in seconds of a feed move (G01/G02/G03) along `path` under ctx.
// G98: length / F. G99: the integral of ds / (F * rpm(x(s))), in closed form
// between the kinks of the clamp (lines and arcs). Returns +inf when
// the feed cannot advance (F or rpm is 0).
double feedMoveSeconds(const Segment& path, const MotionContext& ctx);

// Time in seconds of a rapid leg with the axes at their own rates (each axis
// moves at its full rapid rate until it arrives). Arcs (bridging arcs of a
// compensated rapid) run at the slower rate along their length.
double rapidSeconds(const Segment& path, double rapidX, double rapidZ);

// Acceleration (issue 11; machine.cfg accel_x / accel_z in mm/s², 0 = off).
// A controller without look-ahead starts and stops every move: it speeds up at
// the axis limit, cruises at the programmed speed and slows down again; a move
// too short to reach its speed is a triangle of speed over time.
struct Ramp {
  double seconds = 0.0;  // the whole move
  double up = 0.0;       // speeding up at the start
  double down = 0.0;     // slowing down at the end
};
// A move of `length` mm that takes `cruiseSeconds` at its programmed speeds,
// vStart at its start and vEnd at its end (mm/s), with path acceleration
// `accel` (mm/s², <= 0: no ramps, the cruise time unchanged).
Ramp rampMove(double length, double cruiseSeconds, double vStart, double vEnd, double accel);
// The path acceleration a segment allows with these axis limits (mm/s², X
// radial; <= 0 = that axis does not limit): a line is held by the axis whose
// share of the motion reaches its limit first, an arc by the lower limit.
// 0 when neither axis limits (acceleration off).
double pathAcceleration(const Segment& path, double accelX, double accelZ);
// One axis travelling `distance` mm at `rate` mm/s with `accel` mm/s².
double axisSeconds(double distance, double rate, double accel);
// ... and how far it is after `t` seconds.
double axisDistanceAt(double t, double distance, double rate, double accel);

}  // namespace klueng::core::machine
