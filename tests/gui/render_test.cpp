// The render layer's geometry: the drawn stock equals the core's dexels, the
// outline has no seams, tool sprites put the core's controlled point where the
// tool is, arcs of the trail follow the core's segments.
#include <QTest>

#include "gui_test_runner.h"
#include "klueng/core/cut/stock.h"
#include "klueng/core/cut/tool_shape.h"
#include "klueng/core/geometry.h"
#include "render/lathe_painters.h"
#include "render/path_painter.h"
#include "render/tool_sprite.h"

using namespace klueng;

class RenderTest : public QObject {
  Q_OBJECT
 private slots:
  void stockShapeFollowsTheDexels() {
    core::cut::Stock stock(50.0, 100.0, 0.5);
    // A Ø30 step from Z-20 to Z0 and a Ø10 bore from Z-5 to Z0.
    int first = 0, last = -1;
    stock.columnRange(-20.0, 0.0, first, last);
    for (int i = first; i <= last; ++i) stock.remove(i, 15.0, 25.0);
    stock.columnRange(-5.0, 0.0, first, last);
    for (int i = first; i <= last; ++i) stock.remove(i, 0.0, 5.0);
    const render::StockShape s = render::stockShapeFromStock(stock);
    QVERIFY(s.containsMaterial(-10.0, 14.9));
    QVERIFY(!s.containsMaterial(-10.0, 15.1));
    QVERIFY(s.containsMaterial(-50.0, 24.9));
    QVERIFY(!s.containsMaterial(-50.0, 25.1));
    QVERIFY(!s.containsMaterial(-2.0, 4.9));  // the bore
    QVERIFY(s.containsMaterial(-2.0, 5.1));
    QVERIFY(!s.containsMaterial(1.0, 10.0));  // right of the face
    QCOMPARE(s.blank, QRectF(QPointF(-100.0, -25.0), QPointF(0.0, 0.0)));
    // Three runs of equal columns -> 3 rectangles (5 elements each); the outline has only real edges:
    // 3 outer tops + 1 bore top (lines), left face, step, bore wall, right face pieces.
    QCOMPARE(s.fill.elementCount(), 3 * 5);
    QVERIFY(s.outline.boundingRect() == QRectF(QPointF(-100.0, -25.0), QPointF(0.0, 0.0)));
  }

  void controlledPointOfEveryTip() {
    const QRect box(QPoint(10, 20), QPoint(19, 29));  // pixels 10..19 x 20..29
    const struct {
      int tip;
      QPointF expect;
    } cases[] = {
        {1, {20, 20}}, {2, {10, 20}}, {3, {10, 30}}, {4, {20, 30}}, {5, {20, 25}},
        {6, {15, 20}}, {7, {10, 25}}, {8, {15, 30}}, {0, {15, 25}}, {9, {15, 25}},
    };
    for (const auto& c : cases) QCOMPARE(render::controlledPointForTip(box, c.tip), c.expect);
  }

  void spriteFromTheCoresToolShapeSitsOnTheControlledPoint() {
    // 8 x 6 bitmap: holder on top, a red cutting edge at the bottom-left.
    core::io::RgbImage img;
    img.width = 8;
    img.height = 6;
    img.pixels.assign(48, 0xFFFFFF);
    for (int y = 0; y < 3; ++y)
      for (int x = 2; x < 8; ++x) img.pixels[static_cast<std::size_t>(y * 8 + x)] = 0x000000;
    for (int y = 3; y < 6; ++y)
      for (int x = 0; x < 4; ++x) img.pixels[static_cast<std::size_t>(y * 8 + x)] = 0xE0A000;
    const auto shape = core::cut::makeToolShape(img, "t.bmp", 0.4, 3);
    QVERIFY(shape.value.has_value());
    const render::ToolSprite sprite = render::ToolSprite::fromShape(*shape.value);
    QCOMPARE(sprite.controlledPointPx(), QPointF(shape.value->controlPixelX, shape.value->controlPixelY));
    QCOMPARE(sprite.controlledPointPx(), render::controlledPointForTip(sprite.cuttingEdgeBox(), 3));
    // Placed at (Z 10, X radius 5): the image's controlled pixel lands on that scene point, 2 px/mm.
    const QRectF r = sprite.sceneRect(render::toScene(10.0, 5.0));
    QCOMPARE(r.size(), QSizeF(4.0, 3.0));
    QCOMPARE(r.topLeft() + sprite.controlledPointPx() / 2.0, render::toScene(10.0, 5.0));
    // White is transparent, the holder opaque black.
    QCOMPARE(qAlpha(sprite.image().pixel(0, 0)), 0);
    QCOMPARE(sprite.image().pixel(5, 1), qRgb(0, 0, 0));
  }

  void trailArcsFollowTheSegment() {
    // G03 quarter circle R10 about (Z0, r0) from (10, 0) to (0, 10).
    const core::Segment arc = core::Segment::arc(core::zx(10, 0), core::zx(0, 10), core::zx(0, 0), true);
    QPainterPath path;
    render::appendSegment(path, arc, true);
    // Every point of the drawn arc lies on the circle, in the quarter the core's arc sweeps
    // (Qt's percent is not exactly arc length, so compare with the circle, not pointAt(s)).
    for (double s = 0.0; s <= 1.0; s += 0.05) {
      const core::Vec2 p = render::fromScene(path.pointAtPercent(s));
      QVERIFY2(std::abs(p.norm() - 10.0) < 0.02, qPrintable(QStringLiteral("s %1 radius %2").arg(s).arg(p.norm())));
      QVERIFY(p.x() >= -1e-6 && p.y() >= -1e-6);
    }
    QVERIFY(QLineF(path.pointAtPercent(0), render::toScene(arc.start)).length() < 1e-9);
    QVERIFY(QLineF(path.pointAtPercent(1), render::toScene(arc.end)).length() < 1e-6);
    // A clockwise arc from the same start goes the other way (downward, into -X).
    const core::Segment cw = core::Segment::arc(core::zx(10, 0), core::zx(0, -10), core::zx(0, 0), false);
    QPainterPath down;
    render::appendSegment(down, cw, true);
    QVERIFY(render::fromScene(down.pointAtPercent(0.5)).y() < -5.0);
    // Rapids and feeds go into separate paths.
    render::PathTrail trail;
    core::machine::Move rapid;
    rapid.kind = core::machine::MoveKind::Rapid;
    rapid.path = core::Segment::line(core::zx(50, 20), core::zx(2, 20));
    core::machine::Move feed;
    feed.kind = core::machine::MoveKind::Line;
    feed.path = core::Segment::line(core::zx(2, 20), core::zx(-30, 20));
    trail.append(rapid);
    trail.append(feed);
    QCOMPARE(trail.rapidPath().boundingRect(), QRectF(QPointF(2, -20), QPointF(50, -20)));
    QCOMPARE(trail.feedPath().boundingRect(), QRectF(QPointF(-30, -20), QPointF(2, -20)));
  }
};

KLUENG_GUI_TEST(RenderTest)
#include "render_test.moc"
