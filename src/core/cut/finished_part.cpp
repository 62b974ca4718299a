#include "klueng/core/cut/finished_part.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace klueng::core::cut {

FinishedPart::FinishedPart(const Stock& stock) : stock_(&stock), volume_(stock.volume()) {
  const int n = stock.columnCount();
  first_ = 0;
  while (first_ < n && stock.outerRadius(first_) <= 0.0) ++first_;
  last_ = n - 1;
  while (last_ >= 0 && stock.outerRadius(last_) <= 0.0) --last_;
  if (first_ > last_) return;
  auto row = [&](double z, int i) { return ProfileRow{z, 2.0 * stock.outerRadius(i), 2.0 * stock.innerRadius(i)}; };
  rows_.reserve(static_cast<std::size_t>(last_ - first_ + 3));
  rows_.push_back(row(stock.zLeft(first_), first_));
  for (int i = first_; i <= last_; ++i) rows_.push_back(row(stock.zCentre(i), i));
  rows_.push_back(row(stock.zRight(last_), last_));
}

double FinishedPart::rightFaceZ() const { return empty() ? 0.0 : stock_->zRight(last_); }
double FinishedPart::leftFaceZ() const { return empty() ? 0.0 : stock_->zLeft(first_); }

namespace {

// Linear interpolation between the two column centres around z (exact on
// cylinders, cones and chamfers; a step is spread over one column).
std::optional<double> sampleAt(const Stock& stock, double z, bool outer) {
  const int i = stock.columnAt(z);
  if (i < 0 || stock.outerRadius(i) <= 0.0) return std::nullopt;
  auto value = [&](int k) { return 2.0 * (outer ? stock.outerRadius(k) : stock.innerRadius(k)); };
  const int j = z < stock.zCentre(i) ? i - 1 : i + 1;
  if (j < 0 || j >= stock.columnCount() || stock.outerRadius(j) <= 0.0) return value(i);
  const double w = std::abs(z - stock.zCentre(i)) / stock.resolution();
  return (1.0 - w) * value(i) + w * value(j);
}

}  // namespace

std::optional<double> FinishedPart::outerDiameterAt(double z) const { return sampleAt(*stock_, z, true); }

std::optional<double> FinishedPart::innerDiameterAt(double z) const { return sampleAt(*stock_, z, false); }

std::pair<double, double> FinishedPart::stepExtent(double z, double tolerance) const {
  const int i = stock_->columnAt(z);
  if (i < 0) return {z, z};
  const double d = stock_->outerRadius(i);
  const double tol = tolerance / 2.0;  // diameter tolerance, compared in radius
  int a = i, b = i;
  while (a > 0 && std::abs(stock_->outerRadius(a - 1) - d) <= tol) --a;
  while (b + 1 < stock_->columnCount() && std::abs(stock_->outerRadius(b + 1) - d) <= tol) ++b;
  return {stock_->zLeft(a), stock_->zRight(b)};
}

double FinishedPart::stepLength(double z, double tolerance) const {
  const auto [a, b] = stepExtent(z, tolerance);
  return b - a;
}

double FinishedPart::maxDiameter() const {
  double m = 0.0;
  for (int i = first_; i <= last_; ++i) m = std::max(m, stock_->outerRadius(i));
  return 2.0 * m;
}

std::vector<Vec2> FinishedPart::outerProfile() const {
  std::vector<Vec2> out;
  if (empty()) return out;
  out.emplace_back(stock_->zLeft(first_), 0.0);
  double prev = -1.0;
  for (int i = first_; i <= last_; ++i) {
    const double r = stock_->outerRadius(i);
    if (r != prev) {
      if (i != first_) out.emplace_back(stock_->zLeft(i), prev);
      out.emplace_back(stock_->zLeft(i), r);
      prev = r;
    }
  }
  out.emplace_back(rightFaceZ(), prev);
  out.emplace_back(rightFaceZ(), 0.0);
  return out;
}

std::vector<Vec2> FinishedPart::innerProfile() const {
  std::vector<Vec2> out;
  bool any = false;
  for (int i = first_; i <= last_; ++i) any = any || stock_->innerRadius(i) > 0.0;
  if (!any) return out;
  double prev = -1.0;
  for (int i = first_; i <= last_; ++i) {
    const double r = stock_->innerRadius(i);
    if (r != prev) {
      if (i != first_) out.emplace_back(stock_->zLeft(i), prev);
      out.emplace_back(stock_->zLeft(i), r);
      prev = r;
    }
  }
  out.emplace_back(rightFaceZ(), prev);
  return out;
}

std::string FinishedPart::toCsv() const {
  std::string out = "z,x_outer,x_inner\n";  // the header scripts read (README); the values are always mm, G20 too
  for (const ProfileRow& r : rows_)
    out += fmt::format("{:.4f},{:.4f},{:.4f}\n", r.z + 0.0, r.outerDiameter + 0.0, r.innerDiameter + 0.0);
  return out;
}

std::string FinishedPart::toSvg() const {
  const double margin = 5.0;
  const double zMin = -stock_->length() - margin, zMax = margin;
  const double rMax = std::max(stock_->diameter() / 2.0, 1.0) + margin;
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.3f}mm\" height=\"{:.3f}mm\" "
      "viewBox=\"{:.3f} {:.3f} {:.3f} {:.3f}\">\n",
      zMax - zMin, 2 * rMax, zMin, -rMax, zMax - zMin, 2 * rMax);
  auto polygon = [&](const std::vector<Vec2>& pts, double sign, const char* style) {
    if (pts.empty()) return;
    out += fmt::format("<polygon style=\"{}\" points=\"", style);
    for (const Vec2& p : pts) out += fmt::format("{:.4f},{:.4f} ", p.x() + 0.0, -sign * p.y() + 0.0);
    out += "\"/>\n";
  };
  const std::vector<Vec2> outer = outerProfile();
  polygon(outer, 1.0, "fill:#c8ccd2;stroke:#202020;stroke-width:0.1");
  polygon(outer, -1.0, "fill:#c8ccd2;stroke:#202020;stroke-width:0.1");
  std::vector<Vec2> inner = innerProfile();
  if (!inner.empty()) {
    inner.insert(inner.begin(), Vec2(inner.front().x(), 0.0));
    inner.emplace_back(inner.back().x(), 0.0);
    polygon(inner, 1.0, "fill:#ffffff;stroke:#202020;stroke-width:0.1");
    polygon(inner, -1.0, "fill:#ffffff;stroke:#202020;stroke-width:0.1");
  }
  out += fmt::format(
      "<line x1=\"{:.3f}\" y1=\"0\" x2=\"{:.3f}\" y2=\"0\" style=\"stroke:#2060c0;stroke-width:0.1;"
      "stroke-dasharray:4,1,1,1\"/>\n</svg>\n",
      zMin, zMax);
  return out;
}

std::string FinishedPart::toDxf() const {
  std::string out = "0\nSECTION\n2\nENTITIES\n";
  auto lines = [&](const std::vector<Vec2>& pts, const char* layer) {
    for (const double sign : {1.0, -1.0})
      for (std::size_t k = 1; k < pts.size(); ++k)
        out +=
            fmt::format("0\nLINE\n8\n{}\n10\n{:.4f}\n20\n{:.4f}\n30\n0.0\n11\n{:.4f}\n21\n{:.4f}\n31\n0.0\n", layer,
                        pts[k - 1].x() + 0.0, sign * pts[k - 1].y() + 0.0, pts[k].x() + 0.0, sign * pts[k].y() + 0.0);
  };
  lines(outerProfile(), "PART");
  lines(innerProfile(), "BORE");
  out += "0\nENDSEC\n0\nEOF\n";
  return out;
}

}  // namespace klueng::core::cut
