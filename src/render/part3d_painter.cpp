#include "render/part3d_painter.h"

#include <QPolygonF>
#include <algorithm>
#include <cmath>

namespace klueng::render {

namespace {

using core::Vec2;
using Vec3 = Eigen::Vector3d;  // (X = Z of the lathe, Y = toward the viewer, U = up)

constexpr double kPi = 3.14159265358979323846;

double rad(double deg) { return deg * kPi / 180.0; }

// Douglas-Peucker on a polyline, iteratively.
std::vector<Vec2> simplify(const std::vector<Vec2>& pts, double tolerance) {
  if (pts.size() < 3) return pts;
  std::vector<char> keep(pts.size(), 0);
  keep.front() = keep.back() = 1;
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, pts.size() - 1}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const Vec2 d = pts[b] - pts[a];
    const double len = d.norm();
    double worst = -1.0;
    std::size_t at = a;
    for (std::size_t k = a + 1; k < b; ++k) {
      const Vec2 v = pts[k] - pts[a];
      const double dist = len > 0.0 ? std::abs(d.x() * v.y() - d.y() * v.x()) / len : v.norm();
      if (dist > worst) worst = dist, at = k;
    }
    if (worst > tolerance) {
      keep[at] = 1;
      stack.emplace_back(a, at);
      stack.emplace_back(at, b);
    }
  }
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < pts.size(); ++k)
    if (keep[k]) out.push_back(pts[k]);
  return out;
}

struct Quad {
  QPolygonF poly;
  double depth;
  QColor colour;
};

class Projector {
 public:
  Projector(const QRectF& viewport, const Camera3D& cam, double sceneRadius, const Vec3& centre)
      : cy_(std::cos(rad(cam.yaw))),
        sy_(std::sin(rad(cam.yaw))),
        cp_(std::cos(rad(cam.pitch))),
        sp_(std::sin(rad(cam.pitch))),
        centre_(centre) {
    scale_ = 0.5 * std::min(viewport.width(), viewport.height()) / std::max(1e-6, sceneRadius) * cam.zoom;
    origin_ = viewport.center() + cam.pan;
  }
  // View space: x right, y up, z toward the viewer.
  Vec3 view(const Vec3& w) const {
    const Vec3 p = w - centre_;
    const double x = p.x() * cy_ - p.y() * sy_;
    const double depthYaw = p.x() * sy_ + p.y() * cy_;
    return {x, p.z() * cp_ - depthYaw * sp_, depthYaw * cp_ + p.z() * sp_};
  }
  Vec3 direction(const Vec3& d) const {
    const double x = d.x() * cy_ - d.y() * sy_;
    const double depthYaw = d.x() * sy_ + d.y() * cy_;
    return {x, d.z() * cp_ - depthYaw * sp_, depthYaw * cp_ + d.z() * sp_};
  }
  QPointF screen(const Vec3& v) const { return origin_ + QPointF(v.x() * scale_, -v.y() * scale_); }

 private:
  double cy_, sy_, cp_, sp_;
  Vec3 centre_;
  double scale_ = 1.0;
  QPointF origin_;
};

Vec3 onTurn(double z, double r, double theta) { return {z, r * std::sin(theta), r * std::cos(theta)}; }

QColor shaded(const QColor& base, const Vec3& viewNormal) {
  static const Vec3 light = Vec3(-0.35, 0.55, 0.75).normalized();
  const double lambert = std::max(0.0, viewNormal.normalized().dot(light));
  const double k = 0.38 + 0.62 * lambert;
  return QColor::fromRgbF(std::min(1.0, base.redF() * k + 0.08 * lambert * lambert),
                          std::min(1.0, base.greenF() * k + 0.08 * lambert * lambert),
                          std::min(1.0, base.blueF() * k + 0.08 * lambert * lambert));
}

// Quads of a profile turned from theta0 to theta1; `inward` flips the normals
// (a bore's surface faces the axis).
void revolve(const std::vector<Vec2>& profile, double theta0, double theta1, int steps, bool inward,
             const QColor& colour, const Projector& proj, std::vector<Quad>& out) {
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const Vec2 a = profile[k], b = profile[k + 1];
    if (a.y() <= 0.0 && b.y() <= 0.0) continue;  // on the axis: no surface
    const Vec2 t = b - a;
    Vec2 n2(-t.y(), t.x());  // outward for a profile run left to right with material below it
    if (inward) n2 = -n2;
    if (n2.norm() <= 0.0) continue;
    n2.normalize();
    for (int j = 0; j < steps; ++j) {
      const double t0 = theta0 + (theta1 - theta0) * j / steps, t1 = theta0 + (theta1 - theta0) * (j + 1) / steps;
      const double tm = (t0 + t1) / 2.0;
      const Vec3 normal = proj.direction(Vec3(n2.x(), n2.y() * std::sin(tm), n2.y() * std::cos(tm)));
      if (normal.z() <= 0.0) continue;  // faces away
      const Vec3 p[4] = {proj.view(onTurn(a.x(), a.y(), t0)), proj.view(onTurn(b.x(), b.y(), t0)),
                         proj.view(onTurn(b.x(), b.y(), t1)), proj.view(onTurn(a.x(), a.y(), t1))};
      Quad q;
      for (const Vec3& v : p) q.poly << proj.screen(v);
      q.depth = (p[0].z() + p[1].z() + p[2].z() + p[3].z()) / 4.0;
      q.colour = shaded(colour, normal);
      out.push_back(std::move(q));
    }
  }
}

// A closed (z, r) outline in one section plane: theta 0 (up) or pi/2 (front).
QPolygonF inPlane(const std::vector<Vec2>& outline, double theta, const Projector& proj) {
  QPolygonF poly;
  for (const Vec2& p : outline) poly << proj.screen(proj.view(onTurn(p.x(), p.y(), theta)));
  return poly;
}

}  // namespace

std::vector<Vec2> simplifiedProfile(const core::cut::Stock& stock, bool outer, double tolerance) {
  std::vector<Vec2> pts;
  const int n = stock.columnCount();
  const double jump = std::max(3.0 * stock.resolution(), 0.02);
  const auto radius = [&](int i) {
    if (stock.outerRadius(i) <= 0.0) return 0.0;
    return outer ? stock.outerRadius(i) : stock.innerRadius(i);
  };
  if (n == 0) return pts;
  // The outside starts and ends on the bore (or the axis): the end faces are part of it.
  const auto innerAt = [&](int i) { return stock.outerRadius(i) > 0.0 ? stock.innerRadius(i) : 0.0; };
  if (outer) pts.emplace_back(stock.zLeft(0), innerAt(0));
  pts.emplace_back(stock.zLeft(0), radius(0));
  for (int i = 0; i < n; ++i) {
    pts.emplace_back(stock.zCentre(i), radius(i));
    if (i + 1 < n && std::abs(radius(i + 1) - radius(i)) > jump) {
      pts.emplace_back(stock.zRight(i), radius(i));
      pts.emplace_back(stock.zRight(i), radius(i + 1));
    }
  }
  pts.emplace_back(stock.zRight(n - 1), radius(n - 1));
  if (outer) pts.emplace_back(stock.zRight(n - 1), innerAt(n - 1));
  // Far more points than a view shows (a 1 m bar at 0.01 mm): coarsen until it is light.
  std::vector<Vec2> out = simplify(pts, tolerance);
  for (double tol = tolerance * 4.0; out.size() > 1500; tol *= 4.0) out = simplify(pts, tol);
  return out;
}

int paintPart3D(QPainter& painter, const QRectF& viewport, const Scene3D& scene, const Camera3D& camera) {
  if (!scene.stock || scene.stock->columnCount() == 0) return 0;
  const core::cut::Stock& stock = *scene.stock;
  // Fit the whole bar and the chuck body, whatever has been cut.
  double zMin = -stock.length(), zMax = 0.0, rMax = stock.diameter() / 2.0;
  if (scene.chuck) {
    zMin = std::min(zMin, scene.chuck->bodyZMin());
    rMax = std::max(rMax, scene.chuck->bodyXMax());
  }
  const Vec3 centre((zMin + zMax) / 2.0, 0.0, 0.0);
  const double sceneRadius = std::hypot((zMax - zMin) / 2.0, rMax) * 1.05;
  const Projector proj(viewport, camera, sceneRadius, centre);

  const std::vector<Vec2> outer = simplifiedProfile(stock, true);
  const std::vector<Vec2> inner = simplifiedProfile(stock, false);
  const int steps = std::max(8, scene.angularSteps);
  // The quarter toward the viewer and up is cut away: theta from 90° to 360°.
  const double theta0 = camera.cutaway ? kPi / 2.0 : 0.0;
  const int turnSteps = camera.cutaway ? steps * 3 / 4 : steps;
  std::vector<Quad> quads;
  const QColor steel(168, 182, 198), bore(150, 160, 172), chuck(86, 86, 92);
  revolve(outer, theta0, 2.0 * kPi, turnSteps, false, steel, proj, quads);
  revolve(inner, theta0, 2.0 * kPi, turnSteps, true, bore, proj, quads);
  if (scene.chuck) {
    const core::cut::Chuck& c = *scene.chuck;
    const std::vector<Vec2> body{{c.bodyZMin(), c.bodyXMin()},
                                 {c.bodyZMin(), c.bodyXMax()},
                                 {c.bodyZMax(), c.bodyXMax()},
                                 {c.bodyZMax(), c.bodyXMin()}};
    revolve(body, theta0, 2.0 * kPi, turnSteps, false, chuck, proj, quads);
    // Three jaws, 30° wide, at 150°, 270° and 30° (the last one only without the cutaway).
    const std::vector<Vec2> jaw{
        {c.jawZMin(), c.jawXMin()}, {c.jawZMin(), c.jawXMax()}, {c.jawZMax(), c.jawXMax()}, {c.jawZMax(), c.jawXMin()}};
    for (const double at : {150.0, 270.0, 30.0}) {
      if (camera.cutaway && at < 90.0) continue;
      revolve(jaw, rad(at - 15.0), rad(at + 15.0), 3, false, chuck.lighter(120), proj, quads);
    }
  }
  std::sort(quads.begin(), quads.end(), [](const Quad& a, const Quad& b) { return a.depth < b.depth; });

  painter.save();
  painter.setClipRect(viewport);
  painter.setRenderHint(QPainter::Antialiasing, false);  // seams between quads would show
  for (const Quad& q : quads) {
    painter.setPen(QPen(q.colour, 0));
    painter.setBrush(q.colour);
    painter.drawPolygon(q.poly);
  }
  painter.setRenderHint(QPainter::Antialiasing, true);
  if (camera.cutaway) {
    // The two section faces: what lies between the bore (or the axis) and the outside.
    std::vector<Vec2> section = outer;
    for (auto it = inner.rbegin(); it != inner.rend(); ++it) section.push_back(*it);
    const QColor face(214, 220, 228);
    for (const auto& [theta, normal] : {std::pair{0.0, Vec3(0, 1, 0)}, std::pair{kPi / 2.0, Vec3(0, 0, 1)}}) {
      const Vec3 n = proj.direction(normal);
      if (n.z() <= 0.0) continue;
      painter.setPen(QPen(QColor(60, 72, 88), 1.0));
      painter.setBrush(shaded(face, n));
      painter.drawPolygon(inPlane(section, theta, proj));
    }
  }
  // The tool in the upper section plane.
  const auto drawTool = [&](const std::vector<std::vector<Vec2>>& shapes, const QColor& colour) {
    painter.setPen(QPen(colour.darker(160), 1.0));
    painter.setBrush(colour);
    for (const auto& shape : shapes) painter.drawPolygon(inPlane(shape, 0.0, proj));
  };
  drawTool(scene.toolHolder, QColor(40, 40, 44));
  drawTool(scene.toolCutting, QColor(224, 160, 0));
  painter.restore();
  return static_cast<int>(quads.size());
}

}  // namespace klueng::render
