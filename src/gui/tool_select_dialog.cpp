#include "gui/tool_select_dialog.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPainter>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "gui/language.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/messages.h"
#include "render/lathe_painters.h"

namespace klueng::gui {

namespace io = core::io;

QString writableConfigDir(const QString& dir, QString* error) {
  const QFileInfo dirInfo(dir);
  bool writable = dirInfo.isDir() && dirInfo.isWritable();
  for (const char* name : {"tools.cfg", "offset.cfg"}) {
    const QFileInfo f(QDir(dir).filePath(QString::fromLatin1(name)));
    if (f.exists() && !f.isWritable()) writable = false;
  }
  if (writable) return dir;
  std::string err;
  const std::string user = io::ensureUserConfigDir(&err);
  if (user.empty() && error) *error = QString::fromStdString(err);
  return QString::fromStdString(user);
}

// The bitmap with the tool's controlled point, scaled to fit, on a 1 mm grid.
class ToolPreview : public QWidget {
 public:
  explicit ToolPreview(QWidget* parent) : QWidget(parent) {
    setMinimumSize(260, 220);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
  }
  void setSprite(const render::ToolSprite& sprite, const QString& message) {
    sprite_ = sprite;
    message_ = message;
    update();
  }
  const render::ToolSprite& sprite() const { return sprite_; }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    p.fillRect(rect(), Qt::white);
    p.setPen(QColor(160, 160, 160));
    p.drawRect(rect().adjusted(0, 0, -1, -1));
    if (sprite_.isNull()) {
      p.setPen(palette().color(QPalette::WindowText));
      p.drawText(rect().adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap, message_);
      return;
    }
    const QImage& img = sprite_.image();
    const double scale = std::max(1.0, std::floor(std::min((width() - 40.0) / img.width(), (height() - 40.0) / img.height())));
    const QSizeF size(img.width() * scale, img.height() * scale);
    const QPointF origin((width() - size.width()) / 2.0, (height() - size.height()) / 2.0);
    // 1 mm grid (2 pixels) behind the bitmap.
    p.setPen(QColor(235, 235, 235));
    const double mm = scale * render::ToolSprite::pixelsPerMm;
    for (double x = origin.x(); x <= origin.x() + size.width() + 0.5; x += mm) p.drawLine(QPointF(x, origin.y()), QPointF(x, origin.y() + size.height()));
    for (double y = origin.y(); y <= origin.y() + size.height() + 0.5; y += mm) p.drawLine(QPointF(origin.x(), y), QPointF(origin.x() + size.width(), y));
    p.setRenderHint(QPainter::SmoothPixmapTransform, false);
    p.drawImage(QRectF(origin, size), img);
    // Cutting-edge bounding box and the controlled point.
    const QRect box = sprite_.cuttingEdgeBox();
    if (!box.isEmpty()) {
      p.setPen(QPen(QColor(0, 120, 220), 1.0, Qt::DashLine));
      p.setBrush(Qt::NoBrush);
      p.drawRect(QRectF(origin + QPointF(box.left(), box.top()) * scale, QSizeF(box.width(), box.height()) * scale));
      const QPointF cp = origin + sprite_.controlledPointPx() * scale;
      p.setRenderHint(QPainter::Antialiasing);
      p.setPen(QPen(render::palette().controlledPoint, 2.0));
      p.drawEllipse(cp, 5.0, 5.0);
      p.drawLine(cp - QPointF(9, 0), cp + QPointF(9, 0));
      p.drawLine(cp - QPointF(0, 9), cp + QPointF(0, 9));
    }
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(rect().adjusted(6, 4, -6, -4), Qt::AlignBottom | Qt::AlignLeft, message_);
  }

 private:
  render::ToolSprite sprite_;
  QString message_;
};

ToolSelectDialog::ToolSelectDialog(const QString& configDir, QWidget* parent)
    : QDialog(parent), configDir_(configDir), savedDir_(configDir) {
  const std::string dir = configDir.toStdString();
  auto tools = io::readToolTable(dir + "/tools.cfg");
  tools_ = tools.value.value_or(io::ToolTable{});
  tools_.folder = dir;
  auto offsets = io::readOffsetTable(dir + "/offset.cfg");
  offsets_ = offsets.value.value_or(io::OffsetTable{});
  for (auto& d : tools.diagnostics) loadDiagnostics_.push_back(d);
  for (auto& d : offsets.diagnostics) loadDiagnostics_.push_back(d);

  list_ = new QListWidget(this);
  list_->setMaximumWidth(260);
  for (int t = 1; t <= io::kToolCount; ++t) list_->addItem(QString());
  nameLabel_ = new QLabel(this);
  nameEdit_ = new QLineEdit(this);
  browseButton_ = new QPushButton(this);
  offsetLabel_ = new QLabel(this);
  offsetSpin_ = new QSpinBox(this);
  offsetSpin_->setRange(1, io::kOffsetCount);
  tipInfo_ = new QLabel(this);
  preview_ = new ToolPreview(this);
  problems_ = new QLabel(this);
  problems_->setWordWrap(true);
  problems_->setStyleSheet(QStringLiteral("color: #b00000"));
  buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);

  auto* right = new QGridLayout;
  right->addWidget(nameLabel_, 0, 0);
  auto* nameRow = new QHBoxLayout;
  nameRow->addWidget(nameEdit_, 1);
  nameRow->addWidget(browseButton_);
  right->addLayout(nameRow, 0, 1);
  right->addWidget(offsetLabel_, 1, 0);
  auto* offsetRow = new QHBoxLayout;
  offsetRow->addWidget(offsetSpin_);
  offsetRow->addWidget(tipInfo_, 1);
  right->addLayout(offsetRow, 1, 1);
  right->addWidget(preview_, 2, 0, 1, 2);
  right->setRowStretch(2, 1);
  auto* top = new QHBoxLayout;
  top->addWidget(list_);
  top->addLayout(right, 1);
  auto* main = new QVBoxLayout(this);
  main->addLayout(top, 1);
  main->addWidget(problems_);
  main->addWidget(buttons_);

  connect(list_, &QListWidget::currentRowChanged, this, &ToolSelectDialog::onToolRowChanged);
  connect(nameEdit_, &QLineEdit::textEdited, this, &ToolSelectDialog::onNameEdited);
  connect(browseButton_, &QPushButton::clicked, this, &ToolSelectDialog::browse);
  connect(offsetSpin_, &QSpinBox::valueChanged, this, &ToolSelectDialog::updatePreview);
  connect(buttons_, &QDialogButtonBox::accepted, this, &ToolSelectDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);

  retranslate();
  list_->setCurrentRow(0);
  resize(720, 480);
}

io::ToolTable ToolSelectDialog::toolTable() const { return tools_; }

int ToolSelectDialog::currentTool() const { return list_->currentRow() + 1; }

void ToolSelectDialog::setCurrentTool(int tool) { list_->setCurrentRow(std::clamp(tool, 1, io::kToolCount) - 1); }

void ToolSelectDialog::setBitmapName(int tool, const QString& name) {
  setCurrentTool(tool);
  nameEdit_->setText(name);
  onNameEdited(name);
}

const render::ToolSprite& ToolSelectDialog::previewSprite() const { return preview_->sprite(); }

QString ToolSelectDialog::resolve(const QString& name) const {
  if (name.isEmpty()) return {};
  if (QFileInfo(name).isAbsolute()) return name;
  return QDir(configDir_).filePath(name);
}

void ToolSelectDialog::onToolRowChanged(int row) {
  if (row < 0) return;
  nameEdit_->setText(QString::fromStdString(tools_.bitmap[static_cast<std::size_t>(row)]));
  // Tool n is usually used with offset n (T0101): preview with that offset's tip.
  offsetSpin_->setValue(row + 1);
  updatePreview();
}

void ToolSelectDialog::onNameEdited(const QString& text) {
  const int row = list_->currentRow();
  if (row < 0) return;
  tools_.bitmap[static_cast<std::size_t>(row)] = text.trimmed().toStdString();
  retranslate();
  updatePreview();
}

void ToolSelectDialog::browse() {
  const QString start = nameEdit_->text().isEmpty() ? configDir_ : QFileInfo(resolve(nameEdit_->text())).absolutePath();
  const QString file = QFileDialog::getOpenFileName(this, tr("Tool bitmap"), start, tr("Tool bitmaps (*.bmp *.png)"));
  if (file.isEmpty()) return;
  // Names under the configuration folder stay relative, so the folder can move.
  const QString relative = QDir(configDir_).relativeFilePath(file);
  const QString name = relative.startsWith(QStringLiteral("..")) ? file : relative;
  nameEdit_->setText(name);
  onNameEdited(name);
}

void ToolSelectDialog::updatePreview() {
  const int row = list_->currentRow();
  if (row < 0) return;
  const io::Offset& off = offsets_.at(offsetSpin_->value());
  tipInfo_->setText(tr("tip %1, nose radius %2 mm").arg(off.tip).arg(off.r, 0, 'f', 3));
  const QString name = nameEdit_->text().trimmed();
  if (name.isEmpty()) {
    preview_->setSprite(render::ToolSprite(), tr("Tool %1 has no bitmap.").arg(row + 1, 2, 10, QLatin1Char('0')));
    return;
  }
  const auto image = io::readImage(resolve(name).toStdString());
  if (!image.value) {
    const QString why = image.diagnostics.empty()
                            ? tr("cannot read the bitmap")
                            : QString::fromStdString(core::formatMessage(image.diagnostics.front(), Language::coreLang()));
    preview_->setSprite(render::ToolSprite(), why);
    return;
  }
  render::ToolSprite sprite = render::ToolSprite::fromImage(*image.value, off.tip);
  const QString info = sprite.cuttingEdgeBox().isEmpty()
                           ? tr("No cutting-edge pixels: every pixel is black (holder) or white (empty).")
                           : tr("%1 × %2 pixels = %3 × %4 mm; red cross = controlled point for tip %5")
                                 .arg(image.value->width)
                                 .arg(image.value->height)
                                 .arg(image.value->width / render::ToolSprite::pixelsPerMm)
                                 .arg(image.value->height / render::ToolSprite::pixelsPerMm)
                                 .arg(off.tip);
  preview_->setSprite(sprite, info);
}

void ToolSelectDialog::accept() {
  // Every named bitmap must load, so the saved table is one the loader accepts.
  QStringList problems;
  for (int t = 1; t <= io::kToolCount; ++t) {
    const QString name = QString::fromStdString(tools_.bitmap[static_cast<std::size_t>(t - 1)]);
    if (name.isEmpty()) continue;
    const auto image = io::readImage(resolve(name).toStdString());
    if (!image.value)
      problems << tr("Tool %1: %2").arg(t, 2, 10, QLatin1Char('0'))
                      .arg(image.diagnostics.empty() ? name
                                                     : QString::fromStdString(core::formatMessage(image.diagnostics.front(), Language::coreLang())));
  }
  if (!problems.isEmpty()) {
    QMessageBox::warning(this, windowTitle(), problems.join(QLatin1Char('\n')));
    return;
  }
  QString error;
  const QString target = writableConfigDir(configDir_, &error);
  if (target.isEmpty()) {
    QMessageBox::warning(this, windowTitle(), tr("Cannot save the tool table: %1").arg(error));
    return;
  }
  io::ToolTable out = tools_;
  if (QDir(target) != QDir(configDir_)) {
    // A per-user copy: names relative to the old folder must still find their bitmaps.
    for (auto& name : out.bitmap) {
      const QString q = QString::fromStdString(name);
      if (q.isEmpty() || QFileInfo(q).isAbsolute() || QFileInfo::exists(QDir(target).filePath(q))) continue;
      name = QFileInfo(resolve(q)).absoluteFilePath().toStdString();
    }
  }
  out.folder = target.toStdString();
  const std::string text = io::formatToolTable(out);
  const auto check = io::parseToolTable(text, out.folder, "tools.cfg");
  if (!check.ok()) {
    QMessageBox::warning(this, windowTitle(),
                         QString::fromStdString(core::formatMessage(check.diagnostics.front(), Language::coreLang())));
    return;
  }
  std::string writeError;
  if (!io::writeTextFileAtomic(target.toStdString() + "/tools.cfg", text, &writeError)) {
    QMessageBox::warning(this, windowTitle(), tr("Cannot save the tool table: %1").arg(QString::fromStdString(writeError)));
    return;
  }
  tools_ = out;
  savedDir_ = target;
  QDialog::accept();
}

void ToolSelectDialog::retranslate() {
  setWindowTitle(tr("Tool Select"));
  nameLabel_->setText(tr("Bitmap file:"));
  browseButton_->setText(tr("Browse..."));
  offsetLabel_->setText(tr("Preview with offset:"));
  nameEdit_->setPlaceholderText(tr("e.g. resources/tools/turning.bmp"));
  for (int t = 1; t <= io::kToolCount; ++t) {
    const QString name = QString::fromStdString(tools_.bitmap[static_cast<std::size_t>(t - 1)]);
    list_->item(t - 1)->setText(tr("Tool %1: %2").arg(t, 2, 10, QLatin1Char('0')).arg(name.isEmpty() ? tr("(none)") : QFileInfo(name).fileName()));
  }
  QStringList lines;
  for (const auto& d : loadDiagnostics_)
    if (core::isError(d.severity)) lines << QString::fromStdString(core::formatMessage(d, Language::coreLang()));
  problems_->setText(lines.join(QLatin1Char('\n')));
  problems_->setVisible(!lines.isEmpty());
  if (list_->currentRow() >= 0) updatePreview();
}

void ToolSelectDialog::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDialog::changeEvent(event);
}

}  // namespace klueng::gui
