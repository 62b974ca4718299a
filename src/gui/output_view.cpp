#include "gui/output_view.h"

#include <QEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include "gui/output_items.h"
#include "gui/output_ruler.h"
#include "gui/run_controller.h"

namespace klueng::gui {

namespace {
constexpr int kTrailChunk = 4096;  // moves per completed trail item
constexpr double kMinPixelsPerMm = 0.05;
constexpr double kMaxPixelsPerMm = 400.0;
constexpr double kSceneMargin = 5000.0;  // mm of room to pan around the content
}  // namespace

OutputView::OutputView(QWidget* parent) : QGraphicsView(parent) {
  setScene(new QGraphicsScene(this));
  setRenderHint(QPainter::Antialiasing, false);
  setViewportUpdateMode(QGraphicsView::MinimalViewportUpdate);
  setOptimizationFlags(QGraphicsView::DontAdjustForAntialiasing);
  setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setDragMode(QGraphicsView::ScrollHandDrag);
  setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
  setResizeAnchor(QGraphicsView::AnchorViewCenter);
  setMouseTracking(true);
  setViewportMargins(kRulerSize, kRulerSize, 0, 0);
  setMinimumSize(200, 150);
  scene()->setItemIndexMethod(QGraphicsScene::NoIndex);

  zRuler_ = new OutputRuler(OutputRuler::Axis::Z, this, this);
  xRuler_ = new OutputRuler(OutputRuler::Axis::X, this, this);
  auto* corner = new QLabel(QStringLiteral("X\\Z"), this);
  corner->setAlignment(Qt::AlignCenter);
  corner->setStyleSheet(QStringLiteral("background: #ececE8; color: #505050; font-size: 8pt;"));
  corner_ = corner;

  stock_ = new StockItem;
  chuck_ = new ChuckItem;
  tool_ = new ToolItem;
  marker_ = new MarkerItem;
  scene()->addItem(chuck_);
  scene()->addItem(stock_);
  scene()->addItem(tool_);
  scene()->addItem(marker_);
  overlay_ = new PartOverlayItem;
  measure_ = new MeasureItem;
  measure_->setVisible(false);
  scene()->addItem(overlay_);
  scene()->addItem(measure_);
  rebuild();
}

OutputView::~OutputView() = default;

void OutputView::setRunController(RunController* controller) {
  if (controller_) disconnect(controller_, nullptr, this, nullptr);
  controller_ = controller;
  if (controller_) {
    connect(controller_, &RunController::programReset, this, &OutputView::rebuild);
    connect(controller_, &RunController::frameAdvanced, this, &OutputView::updateFrame);
    controller_->setMaxStepMm(1.0 / pixelsPerMm());
  }
  fitPending_ = true;
  rebuild();
}

double OutputView::pixelsPerMm() const { return std::abs(transform().m11()); }

QPointF OutputView::toolItemPos() const { return tool_->pos(); }

bool OutputView::toolVisible() const { return tool_->isVisible() && !tool_->sprite().isNull(); }

void OutputView::setShowPath(bool show) {
  showPath_ = show;
  for (TrailItem* t : trail_) t->setVisible(show);
}

QRectF OutputView::contentRect() const {
  QRectF r = stock_->boundingRect().united(chuck_->boundingRect());
  if (!pathBounds_.isNull()) r = r.united(pathBounds_);
  r = r.united(QRectF(lastToolPos_ - QPointF(1, 1), QSizeF(2, 2)));
  return r;
}

// What "fit" shows: the bar, the chuck and where the tool cuts, with room for
// the tool above and to the right, not the whole travel from the start point
// (which would shrink the part to a few pixels).
QRectF OutputView::fitRect() const {
  // The stock, the jaws that hold it with a little of the chuck's body behind
  // them, and every cut: the part fills the view (issue 28 item 8).
  const QRectF stock = stock_->boundingRect();
  QRectF chuck = chuck_->boundingRect();
  chuck.setLeft(std::max(chuck.left(), stock.left() - 10.0));
  QRectF r = stock.united(chuck);
  if (!cutBounds_.isNull()) r = r.united(cutBounds_);
  // The tool where it is parked before the run, with room for its holder above
  // and right of the tip, only when it is parked near the part: a start or home
  // far off (Z300) would shrink the part to a sliver (issue 28 item 8). Fit
  // frames the stock and the part; the wheel and the scroll bars reach the rest.
  if (!toolStart_.isNull()) {
    const QRectF tool(toolStart_.x() - 5.0, toolStart_.y() - 45.0, 45.0, 50.0);
    const double near = std::max(0.5 * std::max(r.width(), r.height()), 30.0);
    if (r.adjusted(-near, -near, near, near).contains(tool)) r = r.united(tool);
  }
  // A little room right of the face for the tool coming in, and above and below.
  const double side = std::clamp(0.2 * r.width(), 10.0, 40.0), room = std::clamp(0.08 * r.height(), 3.0, 15.0);
  return r.adjusted(0, -room, side, room);
}

void OutputView::clearTrail() {
  for (TrailItem* t : trail_) {
    scene()->removeItem(t);
    delete t;
  }
  trail_.clear();
  trailMoves_ = 0;
  trailTime_ = 0.0;
}

void OutputView::rebuild() {
  clearTrail();
  pathBounds_ = QRectF();
  cutBounds_ = QRectF();
  core::io::JobHeader header;
  core::io::MachineConfig machineCfg;
  if (controller_) {
    header = controller_->jobHeader();
    machineCfg = controller_->machineSetup().machine;
  }
  stock_->setShape(controller_ ? controller_->stockShape()
                               : render::stockShapeFromBlank(header.diameterMm(), header.lengthMm(), header.boreMm()));
  const auto* sim = controller_ && !controller_->isBusy() ? controller_->cutSimulator() : nullptr;
  chuck_->setChuck(sim ? sim->chuck()
                       : render::chuckFor(header.diameterMm(), header.lengthMm(), machineCfg.chuckGrip,
                                          machineCfg.chuckJawHeight, machineCfg.spindleBore));
  if (const auto* tl = controller_ ? controller_->timeline() : nullptr) {
    for (const auto& m : tl->moves)
      if (m.kind != core::machine::MoveKind::Dwell) {
        pathBounds_ = pathBounds_.united(segmentRect(m.path));
        if (m.kind != core::machine::MoveKind::Rapid) cutBounds_ = cutBounds_.united(segmentRect(m.path));
      }
  }
  lastToolPos_ = render::toScene(core::zx(machineCfg.startZ, machineCfg.startX / 2.0));
  toolStart_ = lastToolPos_;
  tool_->setSprite(render::ToolSprite(), nullptr);
  const QRectF content = contentRect();
  scene()->setSceneRect(content.adjusted(-kSceneMargin, -kSceneMargin, kSceneMargin, kSceneMargin));
  updateFrame();
  // A new program (timeline) is fitted once; after that zoom and pan are the user's.
  const void* timeline = controller_ ? controller_->timeline() : nullptr;
  if (timeline != fittedTimeline_) {
    fitPending_ = true;
    clearMeasurement();  // points measured on another program's part do not belong to this one
  }
  fittedTimeline_ = timeline;
  if (fitPending_ || !timeline) fitToView();
  scene()->update();
}

void OutputView::appendTrail(double time) {
  const auto* tl = controller_->timeline();
  if (!tl) return;
  if (time < trailTime_ - 1e-12) clearTrail();  // stepped back: draw the trail again
  trailTime_ = time;
  const auto& moves = tl->moves;
  const QRectF bounds = pathBounds_.adjusted(-1, -1, 1, 1);
  // Many moves at once (a fast run, a step back): repaint whole items, not each segment.
  int pending = 0;
  while (trailMoves_ + pending < static_cast<int>(moves.size()) &&
         moves[static_cast<std::size_t>(trailMoves_ + pending)].tEnd <= time + 1e-12 && pending <= 64)
    ++pending;
  const bool bulk = pending > 64;
  std::size_t firstTouched = trail_.empty() ? 0 : trail_.size() - 1;
  while (trailMoves_ < static_cast<int>(moves.size()) &&
         moves[static_cast<std::size_t>(trailMoves_)].tEnd <= time + 1e-12) {
    if (trail_.empty() || trail_.back()->moveCount() >= kTrailChunk) {
      auto* item = new TrailItem(bounds);
      item->setZValue(2);
      item->setVisible(showPath_);
      if (!trail_.empty()) trail_.back()->setPartial(nullptr, 0);
      scene()->addItem(item);
      trail_.push_back(item);
    }
    trail_.back()->append(moves[static_cast<std::size_t>(trailMoves_)], !bulk);
    ++trailMoves_;
  }
  if (bulk)
    for (std::size_t i = firstTouched; i < trail_.size(); ++i) trail_[i]->update();
  if (trail_.empty()) {
    auto* item = new TrailItem(bounds);
    item->setZValue(2);
    item->setVisible(showPath_);
    scene()->addItem(item);
    trail_.push_back(item);
  }
  // The move under way is drawn up to the tool.
  const core::machine::Move* partial = nullptr;
  double fraction = 0.0;
  if (trailMoves_ < static_cast<int>(moves.size())) {
    const auto& m = moves[static_cast<std::size_t>(trailMoves_)];
    if (time > m.tStart && m.tEnd > m.tStart) {
      partial = &m;
      fraction = m.fractionAt(time);
    }
  }
  trail_.back()->setPartial(partial, fraction);
}

void OutputView::updateFrame() {
  if (!controller_) return;
  const RunStatus status = controller_->status();
  const QPointF toolPos = render::toScene(status.position);
  // Material only changes where the tool has been since the last frame.
  const render::StockShape shape = controller_->stockShape();
  if (!(shape.fill == stock_->stockShape().fill)) {
    QRectF swept = QRectF(lastToolPos_, toolPos).normalized();
    if (!tool_->sprite().isNull()) swept = swept.united(tool_->boundingRect().translated(lastToolPos_));
    stock_->setShape(shape);
    if (!tool_->sprite().isNull()) swept = swept.united(tool_->boundingRect().translated(toolPos));
    stock_->updateRegion(swept.adjusted(-1, -1, 1, 1));
    if (controller_->state() != RunState::Running && controller_->state() != RunState::Stepping) stock_->update();
  }
  if (!controller_->isBusy()) {
    const core::cut::ToolShape* shapePtr = controller_->currentToolShape();
    if (shapePtr != tool_->identity())
      tool_->setSprite(shapePtr ? render::ToolSprite::fromShape(*shapePtr) : render::ToolSprite(), shapePtr);
  }
  tool_->setPos(toolPos);
  marker_->setPos(toolPos);
  lastToolPos_ = toolPos;
  appendTrail(controller_->currentTime());
}

void OutputView::fitToView() {
  const QRectF content = fitRect();
  if (content.isEmpty() || viewport()->width() < 10) return;
  fitInView(content.adjusted(-content.width() * 0.03, -content.height() * 0.04, content.width() * 0.03,
                             content.height() * 0.04),
            Qt::KeepAspectRatio);
  fitPending_ = false;
  fitKept_ = true;
  if (controller_) controller_->setMaxStepMm(1.0 / pixelsPerMm());
  updateRulers();
  emit zoomChanged(pixelsPerMm());
}

void OutputView::zoomIn() { zoomBy(1.25, viewport()->rect().center()); }
void OutputView::zoomOut() { zoomBy(0.8, viewport()->rect().center()); }

void OutputView::zoomBy(double factor, const QPoint& anchor) {
  fitKept_ = false;  // the user's zoom from now on
  const double now = pixelsPerMm();
  factor = std::clamp(now * factor, kMinPixelsPerMm, kMaxPixelsPerMm) / now;
  const QPointF before = mapToScene(anchor);
  const ViewportAnchor old = transformationAnchor();
  setTransformationAnchor(QGraphicsView::NoAnchor);
  scale(factor, factor);
  // Keep the scene point under the anchor where it was: scroll by how far it moved.
  const QPoint moved = mapFromScene(before) - anchor;
  horizontalScrollBar()->setValue(horizontalScrollBar()->value() + moved.x());
  verticalScrollBar()->setValue(verticalScrollBar()->value() + moved.y());
  setTransformationAnchor(old);
  if (controller_) controller_->setMaxStepMm(1.0 / pixelsPerMm());
  updateRulers();
  emit zoomChanged(pixelsPerMm());
}

void OutputView::wheelEvent(QWheelEvent* event) {
  const double steps = event->angleDelta().y() / 120.0;
  if (steps == 0) return;
  zoomBy(std::pow(1.2, steps), event->position().toPoint());
  event->accept();
}

void OutputView::resizeEvent(QResizeEvent* event) {
  QGraphicsView::resizeEvent(event);
  const QRect vp = viewport()->geometry();
  zRuler_->setGeometry(vp.left(), vp.top() - kRulerSize, vp.width(), kRulerSize);
  xRuler_->setGeometry(vp.left() - kRulerSize, vp.top(), kRulerSize, vp.height());
  corner_->setGeometry(vp.left() - kRulerSize, vp.top() - kRulerSize, kRulerSize, kRulerSize);
  if (fitPending_ || fitKept_) fitToView();
  updateRulers();
}

void OutputView::scrollContentsBy(int dx, int dy) {
  QGraphicsView::scrollContentsBy(dx, dy);
  updateRulers();
}

void OutputView::setUnits(const core::UnitFormat& units) {
  units_ = units;
  zRuler_->setUnits(units);
  xRuler_->setUnits(units);
  // A reading on screen is said again in the new unit.
  if (measureA_ && measureB_) emit measured(MeasureItem::reading(*measureA_, *measureB_, units_));
}

QStringList OutputView::rulerLabels(bool zAxis) const { return (zAxis ? zRuler_ : xRuler_)->visibleLabels(); }

void OutputView::updateRulers() {
  zRuler_->update();
  xRuler_->update();
}

void OutputView::mouseMoveEvent(QMouseEvent* event) {
  if (event->buttons() & Qt::LeftButton && dragMode() == QGraphicsView::ScrollHandDrag) fitKept_ = false;  // panned
  QGraphicsView::mouseMoveEvent(event);
  const core::Vec2 p = render::fromScene(snapped(mapToScene(event->position().toPoint())));
  emit cursorPositionChanged(core::diameterOf(p), core::zOf(p));
}

void OutputView::mousePressEvent(QMouseEvent* event) {
  if (!measuring_ || event->button() != Qt::LeftButton) {
    QGraphicsView::mousePressEvent(event);
    return;
  }
  const QPointF p = snapped(mapToScene(event->position().toPoint()));
  if (!measureA_ || measureB_) {
    measureA_ = p;
    measureB_.reset();
  } else {
    measureB_ = p;
    emit measured(MeasureItem::reading(*measureA_, *measureB_, units_));
  }
  measure_->setPoints(*measureA_, measureB_);
  measure_->setVisible(true);
  event->accept();
}

void OutputView::setMeasuring(bool on) {
  measuring_ = on;
  setDragMode(on ? QGraphicsView::NoDrag : QGraphicsView::ScrollHandDrag);
  viewport()->setCursor(on ? Qt::CrossCursor : Qt::OpenHandCursor);
  if (!on) {
    measureA_.reset();
    measureB_.reset();
    measure_->setVisible(false);
  }
}

void OutputView::setPartOverlay(const PartOverlay& overlay) { overlay_->setOverlay(overlay); }

bool OutputView::hasMeasurement() const { return measure_->isVisible(); }

void OutputView::clearMeasurement() {
  measureA_.reset();
  measureB_.reset();
  measure_->setVisible(false);
}

void OutputView::setPartOverlayHidden(bool hidden) { overlay_->setVisible(!hidden); }

bool OutputView::isPartOverlayShown() const { return overlay_->isVisible() && !overlay_->overlay().empty(); }

const PartOverlay& OutputView::partOverlay() const { return overlay_->overlay(); }

QPointF OutputView::snapped(const QPointF& scenePos, double pixels) const {
  const auto* sim = controller_ && !controller_->isBusy() ? controller_->cutSimulator() : nullptr;
  if (!sim) return scenePos;
  return snapToStock(sim->stock(), scenePos, pixels / std::max(1e-6, pixelsPerMm()));
}

void OutputView::mouseDoubleClickEvent(QMouseEvent* event) {
  fitToView();
  event->accept();
}

void OutputView::drawBackground(QPainter* painter, const QRectF& rect) {
  painter->fillRect(rect, render::palette().background);
}

void OutputView::paintEvent(QPaintEvent* event) {
  ++paints_;
  QGraphicsView::paintEvent(event);
}

void OutputView::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    setToolTip(tr("Output screen: wheel to zoom, drag to pan, double-click to fit"));
  }
  QGraphicsView::changeEvent(event);
}

QImage OutputView::renderToImage(const QSize& size) {
  QImage image(size, QImage::Format_ARGB32_Premultiplied);
  image.fill(render::palette().background);
  QPainter p(&image);
  scene()->render(&p, QRectF(), contentRect().adjusted(-5, -5, 5, 5), Qt::KeepAspectRatio);
  return image;
}

}  // namespace klueng::gui
