#include "klueng/core/machine/kinematics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace klueng::core::machine {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// 1 / rpm at radius x under G96, in minutes per revolution:
// rpm = min(C / |x|, cap)  =>  1 / rpm = max(|x| / C, 1 / cap).
struct InverseRpm {
  double c;       // 1000 * S / (2 pi): rpm times radius (mm)
  double invCap;  // 1 / cap, 0 when uncapped
  double operator()(double x) const { return std::max(std::abs(x) / c, invCap); }
  // Radii where the function has a kink.
  std::array<double, 3> kinks() const { return {0.0, invCap * c, -invCap * c}; }
};

// Integral of 1/rpm over the path length (mm * min / rev), exact: between the
// kinks the integrand is either constant (clamped) or |x| / C with x linear
// (lines) or cx + r sin(phi) (arcs), both integrated in closed form.
double integrateInverseRpm(const Segment& path, const InverseRpm& g) {
  std::array<double, 8> us{};
  std::size_t n = 0;
  const double xc = g.invCap * g.c;  // radius below which the rpm is clamped
  if (!path.isArc()) {
    const double x0 = xOf(path.start), x1 = xOf(path.end);
    us[n++] = 0.0;
    if (x1 != x0) {
      for (double k : g.kinks()) {
        const double u = (k - x0) / (x1 - x0);
        if (u > 0.0 && u < 1.0) us[n++] = u;
      }
    }
    us[n++] = 1.0;
    std::sort(us.begin(), us.begin() + static_cast<std::ptrdiff_t>(n));
    // The integrand is linear between kinks: the trapezoid rule is exact.
    double sum = 0.0;
    for (std::size_t i = 1; i < n; ++i) {
      const double xa = x0 + us[i - 1] * (x1 - x0), xb = x0 + us[i] * (x1 - x0);
      sum += 0.5 * (g(xa) + g(xb)) * (us[i] - us[i - 1]);
    }
    return sum * path.length();
  }
  const double r = path.radius();
  const double sweep = path.sweep();
  const double dir = path.ccw ? 1.0 : -1.0;
  const Vec2 a = path.start - path.centre;
  const double phi0 = std::atan2(xOf(a), zOf(a));  // angle in the (z, x) plane
  const double cx = xOf(path.centre);
  auto xAt = [&](double u) { return cx + r * std::sin(phi0 + dir * u); };
  us[n++] = 0.0;
  for (double k : g.kinks()) {
    const double s = (k - cx) / r;
    if (s < -1.0 || s > 1.0) continue;
    const double base = std::asin(s);
    for (double phi : {base, std::numbers::pi - base}) {
      double u = dir * (phi - phi0);
      u = std::fmod(u, 2 * std::numbers::pi);
      if (u < 0) u += 2 * std::numbers::pi;
      if (u > 0.0 && u < sweep) us[n++] = u;
    }
  }
  us[n++] = sweep;
  std::sort(us.begin(), us.begin() + static_cast<std::ptrdiff_t>(n));
  double sum = 0.0;
  for (std::size_t i = 1; i < n; ++i) {
    const double ua = us[i - 1], ub = us[i];
    if (ub <= ua) continue;
    const double xm = xAt(0.5 * (ua + ub));
    if (std::abs(xm) <= xc) {
      sum += (ub - ua) * g.invCap;
    } else {
      // integral of x du = cx (ub - ua) - (r / dir) (cos(phi0 + dir ub) - cos(phi0 + dir ua))
      const double integral = cx * (ub - ua) - dir * r * (std::cos(phi0 + dir * ub) - std::cos(phi0 + dir * ua));
      sum += (xm < 0 ? -integral : integral) / g.c;
    }
  }
  return sum * r;
}

}  // namespace

double spindleRpm(const MotionContext& ctx, double xRadius) {
  if (ctx.spindle == SpindleDir::Stopped || ctx.sWord <= 0.0) return 0.0;
  if (ctx.spindleMode == SpindleMode::ConstantRpm) return ctx.sWord;
  const double d = 2.0 * std::abs(xRadius);
  const double rpm = d > 0.0 ? 1000.0 * ctx.sWord / (std::numbers::pi * d) : kInf;
  return ctx.rpmCap > 0.0 ? std::min(rpm, ctx.rpmCap) : rpm;
}

double feedMoveSeconds(const Segment& path, const MotionContext& ctx) {
  const double len = path.length();
  if (len <= 0.0) return 0.0;
  if (ctx.feed <= 0.0) return kInf;
  if (ctx.feedMode == FeedMode::PerMinute) return len / ctx.feed * 60.0;
  if (ctx.spindle == SpindleDir::Stopped || ctx.sWord <= 0.0) return kInf;
  if (ctx.spindleMode == SpindleMode::ConstantRpm) return len / (ctx.feed * ctx.sWord) * 60.0;
  const InverseRpm g{1000.0 * ctx.sWord / (2.0 * std::numbers::pi), ctx.rpmCap > 0.0 ? 1.0 / ctx.rpmCap : 0.0};
  return integrateInverseRpm(path, g) / ctx.feed * 60.0;
}

double rapidSeconds(const Segment& path, double rapidX, double rapidZ) {
  if (path.isArc()) return path.length() / std::min(rapidX, rapidZ) * 60.0;
  const Vec2 d = path.end - path.start;
  return std::max(std::abs(zOf(d)) / rapidZ, std::abs(xOf(d)) / rapidX) * 60.0;
}

}  // namespace klueng::core::machine

namespace klueng::core::machine {

Ramp rampMove(double length, double cruiseSeconds, double vStart, double vEnd, double accel) {
  Ramp r{cruiseSeconds, 0.0, 0.0};
  if (accel <= 0.0 || length <= 0.0 || !std::isfinite(cruiseSeconds)) return r;
  const double up = vStart / accel, down = vEnd / accel;
  const double rampDistance = (vStart * up + vEnd * down) / 2.0;
  if (rampDistance <= length) {
    // Trapezoid: each ramp covers its distance at half the speed, so it adds
    // half its own time to the cruise time.
    r.seconds = cruiseSeconds + (up + down) / 2.0;
    r.up = up;
    r.down = down;
    return r;
  }
  // Triangle: up half the length and down again without reaching the speed.
  r.seconds = 2.0 * std::sqrt(length / accel);
  r.up = r.down = r.seconds / 2.0;
  return r;
}

double pathAcceleration(const Segment& path, double accelX, double accelZ) {
  const bool limitX = accelX > 0.0, limitZ = accelZ > 0.0;
  if (!limitX && !limitZ) return 0.0;
  if (path.isArc()) return limitX && limitZ ? std::min(accelX, accelZ) : (limitX ? accelX : accelZ);
  const Vec2 d = path.end - path.start;
  const double length = d.norm();
  if (length <= 0.0) return limitX && limitZ ? std::min(accelX, accelZ) : (limitX ? accelX : accelZ);
  double a = std::numeric_limits<double>::infinity();
  const double shareZ = std::abs(zOf(d)) / length, shareX = std::abs(xOf(d)) / length;
  if (limitZ && shareZ > 1e-12) a = std::min(a, accelZ / shareZ);
  if (limitX && shareX > 1e-12) a = std::min(a, accelX / shareX);
  return std::isfinite(a) ? a : 0.0;
}

double axisSeconds(double distance, double rate, double accel) {
  if (distance <= 0.0) return 0.0;
  if (accel <= 0.0) return distance / rate;
  if (distance >= rate * rate / accel) return distance / rate + rate / accel;
  return 2.0 * std::sqrt(distance / accel);
}

double axisDistanceAt(double t, double distance, double rate, double accel) {
  const double total = axisSeconds(distance, rate, accel);
  if (t <= 0.0) return 0.0;
  if (t >= total) return distance;
  if (accel <= 0.0) return rate * t;
  const double peak = std::min(rate, accel * total / 2.0);  // the speed it reaches
  const double ramp = peak / accel;
  if (t < ramp) return accel * t * t / 2.0;
  if (t <= total - ramp) return peak * ramp / 2.0 + peak * (t - ramp);
  const double rest = total - t;
  return distance - accel * rest * rest / 2.0;
}

}  // namespace klueng::core::machine
