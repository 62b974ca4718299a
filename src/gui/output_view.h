#pragma once
// The output screen (SPEC 12): the stock as a lathe section (both halves), the
// chuck, the tool bitmap at its controlled point, the path trail (rapid
// dashed, feed solid), X and Z rulers that follow zoom and pan.
// Wheel = zoom about the mouse, drag = pan, fitToView() = everything in sight.
//
// Public API (F1 puts an OutputView in the main window)
//   OutputView view(parent);  view.setRunController(&controller);
//     - follows the controller: programReset -> rebuild, frameAdvanced -> move the
//       tool, cut the stock, extend the trail
//   fitToView()            zoom to stock + chuck + tool path
//   zoomIn() zoomOut()     keyboard/menu zoom
//   setShowPath(bool)      show/hide the trail
//   toolItemPos()          the tool item's scene position == controlled point (z, -radius)
//   renderToImage(size)    the drawing (no rulers) as an image, e.g. for PNG export
//   pixelsPerMm()          current zoom
//   scene()                the QGraphicsScene (mm units, Y up = -scene y)
#include <QGraphicsView>
#include <QImage>
#include <QPointer>
#include <optional>
#include <vector>

#include "gui/part_overlay.h"
#include "klueng/core/geometry.h"
#include "klueng/core/units.h"

namespace klueng::gui {

class RunController;
class OutputRuler;
class StockItem;
class ChuckItem;
class ToolItem;
class TrailItem;
class MarkerItem;

class OutputView : public QGraphicsView {
  Q_OBJECT
 public:
  explicit OutputView(QWidget* parent = nullptr);
  ~OutputView() override;

  void setRunController(RunController* controller);
  RunController* runController() const { return controller_; }

  QPointF toolItemPos() const;
  // What the viewport shows, in scene coordinates (tests).
  QRectF visibleSceneRect() const { return mapToScene(viewport()->rect()).boundingRect(); }
  bool toolVisible() const;
  double pixelsPerMm() const;
  QImage renderToImage(const QSize& size);
  void setShowPath(bool show);
  // The Part panel's marks over the section (issue 10), empty to clear.
  void setPartOverlay(const PartOverlay& overlay);
  const PartOverlay& partOverlay() const;
  // Measure: each left click puts a point (snapped to the part's edges); two make
  // a reading (measured()). Off clears the points.
  void setMeasuring(bool on);
  bool isMeasuring() const { return measuring_; }
  // A measurement (one or two points) is drawn; a new program takes it away.
  bool hasMeasurement() const;
  void clearMeasurement();
  // While a run cuts the stock again the Part marks do not fit it: hidden, kept.
  void setPartOverlayHidden(bool hidden);
  bool isPartOverlayShown() const;
  // The point under a scene position, snapped to the stock's profile and faces within `pixels`.
  QPointF snapped(const QPointF& scenePos, double pixels = 6.0) const;
  // The unit of the rulers and the measure reading (View ▸ Units shown); the scene stays in mm.
  void setUnits(const core::UnitFormat& units);
  const core::UnitFormat& units() const { return units_; }
  // The rulers' tick labels (tests).
  QStringList rulerLabels(bool zAxis) const;
  // The ruler thickness in pixels (the viewport margins).
  static constexpr int kRulerSize = 24;

 public slots:
  void fitToView();
  void zoomIn();
  void zoomOut();
  void rebuild();      // from the controller's job, timeline and stock
  void updateFrame();  // tool pose, stock and trail at the controller's time

 signals:
  void zoomChanged(double pixelsPerMm);
  // Mouse position in work coordinates (X as diameter), for a coordinate readout.
  void cursorPositionChanged(double xDiameter, double z);
  // The measure tool's reading: "ΔZ 20.000   ΔØ 10.000   d 22.361   ∠ 26.57°".
  void measured(const QString& reading);

 protected:
  void wheelEvent(QWheelEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void scrollContentsBy(int dx, int dy) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void drawBackground(QPainter* painter, const QRectF& rect) override;
  void changeEvent(QEvent* event) override;

 public:
  // Paint events of the viewport since construction (frame-rate probe).
  qint64 paintCount() const { return paints_; }
  const StockItem* stockItem() const { return stock_; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  void zoomBy(double factor, const QPoint& anchorViewportPos);
  void updateRulers();
  void clearTrail();
  void appendTrail(double time);
  QRectF contentRect() const;
  QRectF fitRect() const;

  QPointer<RunController> controller_;
  OutputRuler* xRuler_ = nullptr;  // vertical ruler at the left: X (diameter)
  OutputRuler* zRuler_ = nullptr;  // horizontal ruler at the top: Z
  QWidget* corner_ = nullptr;
  StockItem* stock_ = nullptr;
  ChuckItem* chuck_ = nullptr;
  ToolItem* tool_ = nullptr;
  MarkerItem* marker_ = nullptr;
  PartOverlayItem* overlay_ = nullptr;
  MeasureItem* measure_ = nullptr;
  bool measuring_ = false;
  core::UnitFormat units_;
  std::optional<QPointF> measureA_, measureB_;
  std::vector<TrailItem*> trail_;  // completed chunks, then the live one
  int trailMoves_ = 0;             // timeline moves already in the trail
  double trailTime_ = 0.0;
  QRectF pathBounds_;
  QRectF cutBounds_;  // feed moves only: what fit-to-view frames
  QPointF lastToolPos_;
  QPointF toolStart_;  // where the tool is parked before the run (kept in the fitted view)
  bool showPath_ = true;
  bool fitPending_ = true;
  // The view is as Fit left it (no zoom or pan since): a resize fits again, so a
  // window laid out after its first fit never keeps a tiny viewport's wide view.
  bool fitKept_ = false;
  const void* fittedTimeline_ = nullptr;
  qint64 paints_ = 0;
};

}  // namespace klueng::gui
