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

}  // namespace klueng::core::machine
