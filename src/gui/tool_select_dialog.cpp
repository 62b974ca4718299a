#include "gui/tool_select_dialog.h"

#include <QCheckBox>
#include <QComboBox>
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
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/messages.h"
#include "render/lathe_painters.h"

namespace klueng::gui {

namespace io = core::io;

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
    // True scale: screen pixels per millimetre, the same on both axes, whatever
    // the bitmap's own resolution (2 px/mm seed bitmaps, 10 px/mm library tools).
    const double ppm = sprite_.pixelsPerMm();
    const double mmW = img.width() / ppm, mmH = img.height() / ppm;
    const double mm = std::min((width() - 40.0) / mmW, (height() - 40.0) / mmH);
    const double scale = mm / ppm;  // screen pixels per bitmap pixel
    const QSizeF size(img.width() * scale, img.height() * scale);
    const QPointF origin((width() - size.width()) / 2.0, (height() - size.height()) / 2.0);
    // 1 mm grid (5 mm when 1 mm is too fine to see) behind the bitmap.
    p.setPen(QColor(235, 235, 235));
    const double step = mm >= 4.0 ? mm : 5.0 * mm;
    for (double x = origin.x(); x <= origin.x() + size.width() + 0.5; x += step)
      p.drawLine(QPointF(x, origin.y()), QPointF(x, origin.y() + size.height()));
    for (double y = origin.y(); y <= origin.y() + size.height() + 0.5; y += step)
      p.drawLine(QPointF(origin.x(), y), QPointF(origin.x() + size.width(), y));
    p.setRenderHint(QPainter::SmoothPixmapTransform, scale < 1.0);
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

ToolSelectDialog::ToolSelectDialog(const QString& configDir, QWidget* parent) : QDialog(parent), configDir_(configDir) {
  const std::string dir = configDir.toStdString();
  auto tools = io::readToolTable(dir + "/tools.cfg");
  auto offsets = io::readOffsetTable(dir + "/offset.cfg");
  for (auto& d : tools.diagnostics) loadDiagnostics_.push_back(d);
  for (auto& d : offsets.diagnostics) loadDiagnostics_.push_back(d);
  io::ToolTable table = tools.value.value_or(io::ToolTable{});
  table.folder = dir;
  build(table, offsets.value.value_or(io::OffsetTable{}));
}

ToolSelectDialog::ToolSelectDialog(const io::ToolTable& tools, const io::OffsetTable& offsets, const QString& configDir,
                                   QWidget* parent)
    : QDialog(parent), configDir_(configDir) {
  build(tools, offsets);
}

void ToolSelectDialog::build(const io::ToolTable& tools, const io::OffsetTable& offsets) {
  tools_ = tools;
  if (tools_.folder.empty()) tools_.folder = configDir_.toStdString();
  loaded_ = tools_;
  offsets_ = offsets;

  list_ = new QListWidget(this);
  list_->setMinimumWidth(300);
  list_->setMaximumWidth(380);
  for (int t = 1; t <= stationCount(); ++t) list_->addItem(QString());
  libraryLabel_ = new QLabel(this);
  libraryCombo_ = new QComboBox(this);
  libraryCombo_->addItem(QString(), QString());
  for (const io::LibraryTool& t : io::shippedToolLibrary().tools)
    libraryCombo_->addItem(QString(), QString::fromStdString(t.id));
  libraryCombo_->setObjectName(QStringLiteral("toolLibrary"));
  materialLabel_ = new QLabel(this);
  materialCombo_ = new QComboBox(this);
  materialCombo_->setObjectName(QStringLiteral("toolMaterial"));
  for (const char* id : {"", "hss", "carbide", "coated-carbide"})
    materialCombo_->addItem(QString(), QString::fromLatin1(id));
  jobOnly_ = new QCheckBox(this);
  jobOnly_->setObjectName(QStringLiteral("toolJobOnly"));
  choice_ = new QLabel(this);
  choice_->setWordWrap(true);
  choice_->setStyleSheet(QStringLiteral("color: #0050a0"));
  nameLabel_ = new QLabel(this);
  nameEdit_ = new QLineEdit(this);
  nameEdit_->setObjectName(QStringLiteral("toolBitmapName"));
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
  right->addWidget(libraryLabel_, 0, 0);
  right->addWidget(libraryCombo_, 0, 1);
  right->addWidget(nameLabel_, 1, 0);
  auto* nameRow = new QHBoxLayout;
  nameRow->addWidget(nameEdit_, 1);
  nameRow->addWidget(browseButton_);
  right->addLayout(nameRow, 1, 1);
  right->addWidget(jobOnly_, 2, 1);
  right->addWidget(materialLabel_, 3, 0);
  right->addWidget(materialCombo_, 3, 1);
  right->addWidget(offsetLabel_, 4, 0);
  auto* offsetRow = new QHBoxLayout;
  offsetRow->addWidget(offsetSpin_);
  offsetRow->addWidget(tipInfo_, 1);
  right->addLayout(offsetRow, 4, 1);
  right->addWidget(choice_, 5, 0, 1, 2);
  right->addWidget(preview_, 6, 0, 1, 2);
  right->setRowStretch(6, 1);
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
  connect(libraryCombo_, &QComboBox::activated, this, &ToolSelectDialog::onLibraryChosen);
  connect(jobOnly_, &QCheckBox::toggled, this, &ToolSelectDialog::onJobOnlyToggled);
  connect(materialCombo_, &QComboBox::activated, this, [this](int index) {
    if (!syncing_ && list_->currentRow() >= 0)
      setToolMaterial(list_->currentRow() + 1, materialCombo_->itemData(index).toString());
  });
  connect(offsetSpin_, &QSpinBox::valueChanged, this, &ToolSelectDialog::updatePreview);
  connect(buttons_, &QDialogButtonBox::accepted, this, &ToolSelectDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);

  retranslate();
  list_->setCurrentRow(0);
  resize(900, 560);
}

io::ToolTable ToolSelectDialog::toolTable() const { return tools_; }

int ToolSelectDialog::currentTool() const { return list_->currentRow() + 1; }

void ToolSelectDialog::setCurrentTool(int tool) { list_->setCurrentRow(std::clamp(tool, 1, stationCount()) - 1); }

int ToolSelectDialog::stationCount() const { return std::clamp(tools_.stations, 1, io::kMaxStations); }

void ToolSelectDialog::setBitmapName(int tool, const QString& name) {
  setCurrentTool(tool);
  nameEdit_->setText(name);
  onNameEdited(name);
}

const render::ToolSprite& ToolSelectDialog::previewSprite() const { return preview_->sprite(); }

QString ToolSelectDialog::resolve(const QString& name) const {
  if (name.isEmpty()) return {};
  if (name.startsWith(QLatin1String(io::kLibraryPrefix.data()))) {
    const io::LibraryTool* t =
        io::shippedToolLibrary().find(name.mid(int(io::kLibraryPrefix.size())).trimmed().toStdString());
    return t ? QString::fromStdString(io::shippedToolLibrary().bitmapPath(*t)) : QString();
  }
  if (QFileInfo(name).isAbsolute()) return name;
  return QDir(configDir_).filePath(name);
}

void ToolSelectDialog::onToolRowChanged(int row) {
  if (row < 0) return;
  // Tool n is usually used with offset n (T0101): preview with that offset's tip.
  syncing_ = true;
  offsetSpin_->setValue(row + 1);
  syncing_ = false;
  syncControls();
}

void ToolSelectDialog::onNameEdited(const QString& text) {
  const int row = list_->currentRow();
  if (row < 0) return;
  tools_.bitmap[static_cast<std::size_t>(row)] = text.trimmed().toStdString();
  beforeLibrary_[static_cast<std::size_t>(row)].reset();  // the typed name is the line now
  setOverride(row + 1, {});                               // typing a file name sets the station in tools.cfg
  retranslate();
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
  const QString name = shownEntry(row + 1);
  const io::LibraryTool* libraryTool =
      name.startsWith(QLatin1String(io::kLibraryPrefix.data()))
          ? io::shippedToolLibrary().find(name.mid(int(io::kLibraryPrefix.size())).trimmed().toStdString())
          : nullptr;
  io::Offset off = inference_.setup.offsets.at(offsetSpin_->value());
  const io::Offset& own = offsets_.at(offsetSpin_->value());
  // A tool guessed from a plain program brings its own nose (the core's I411): show that, not
  // the offset.cfg row meant for the table's tool.
  const bool guessedHere = inference_.fromProgram && inference_.choiceFor(row + 1) &&
                           name == QString::fromStdString(inference_.setup.tools.bitmap[static_cast<std::size_t>(row)]);
  if (guessedHere) {
    // off is already the run's row
  } else if (own.x != 0.0 || own.z != 0.0 || own.r != 0.0 || own.tip != 0) {
    off = own;
  } else if (libraryTool) {
    off = io::Offset{0.0, 0.0, libraryTool->noseRadius, libraryTool->tip};
  }
  tipInfo_->setText(tr("tip %1, nose radius %2 mm").arg(off.tip).arg(off.r, 0, 'f', 3));
  if (name.isEmpty()) {
    preview_->setSprite(render::ToolSprite(), tr("Tool %1 has no bitmap.").arg(row + 1, 2, 10, QLatin1Char('0')));
    return;
  }
  const auto image = io::readImage(resolve(name).toStdString());
  if (!image.value) {
    const QString why =
        image.diagnostics.empty()
            ? tr("cannot read the bitmap")
            : QString::fromStdString(core::formatMessage(image.diagnostics.front(), Language::coreLang()));
    preview_->setSprite(render::ToolSprite(), why);
    return;
  }
  const double ppm = libraryTool ? libraryTool->pixelsPerMm : render::ToolSprite::seedPixelsPerMm;
  render::ToolSprite sprite = render::ToolSprite::fromImage(*image.value, off.tip, ppm);
  const QString info = sprite.cuttingEdgeBox().isEmpty()
                           ? tr("No cutting-edge pixels: every pixel is black (holder) or white (empty).")
                           : tr("%1 × %2 pixels at %3 px/mm = %4 × %5 mm; red cross = controlled point for tip %6")
                                 .arg(image.value->width)
                                 .arg(image.value->height)
                                 .arg(ppm)
                                 .arg(image.value->width / ppm)
                                 .arg(image.value->height / ppm)
                                 .arg(off.tip);
  preview_->setSprite(sprite, info);
}

void ToolSelectDialog::setProgramTools(const core::machine::ToolInference& inference,
                                       const std::vector<core::machine::StationOverride>& overrides) {
  inference_ = inference;
  overrides_ = overrides;
  retranslate();
}

std::vector<core::machine::StationOverride> ToolSelectDialog::jobOverrides() const { return overrides_; }

QString ToolSelectDialog::overrideOf(int tool) const {
  for (const auto& o : overrides_)
    if (o.station == tool) return QString::fromStdString(o.libraryId);
  return {};
}

void ToolSelectDialog::setOverride(int tool, const QString& id) {
  std::erase_if(overrides_, [tool](const core::machine::StationOverride& o) { return o.station == tool; });
  if (!id.isEmpty()) overrides_.push_back({tool, id.toStdString()});
}

QString ToolSelectDialog::shownEntry(int tool) const {
  if (const QString o = overrideOf(tool); !o.isEmpty()) return QString::fromLatin1(io::kLibraryPrefix.data()) + o;
  if (const auto* c = inference_.choiceFor(tool); c && c->reason != core::machine::ToolReason::Override)
    return QString::fromLatin1(io::kLibraryPrefix.data()) + QString::fromStdString(c->libraryId);
  return QString::fromStdString(tools_.bitmap[static_cast<std::size_t>(tool - 1)]);
}

QString ToolSelectDialog::choiceText() const { return choice_->text(); }

void ToolSelectDialog::syncControls() {
  const int row = list_->currentRow();
  if (row < 0) return;
  const int tool = row + 1;
  const QString entry = shownEntry(tool);
  syncing_ = true;
  nameEdit_->setText(QString::fromStdString(tools_.bitmap[static_cast<std::size_t>(row)]));
  const QString id = entry.startsWith(QLatin1String(io::kLibraryPrefix.data()))
                         ? entry.mid(int(io::kLibraryPrefix.size())).trimmed()
                         : QString();
  const int index = libraryCombo_->findData(id);
  libraryCombo_->setCurrentIndex(index < 0 ? 0 : index);
  const int material = materialCombo_->findData(QString::fromStdString(tools_.material[static_cast<std::size_t>(row)]));
  materialCombo_->setCurrentIndex(material < 0 ? 0 : material);
  jobOnly_->setChecked(!overrideOf(tool).isEmpty() || jobOnlyPending_ == tool);
  syncing_ = false;
  const auto* c = inference_.choiceFor(tool);
  if (!overrideOf(tool).isEmpty()) {
    choice_->setText(tr("Set for this program only: %1 (tools.cfg has: %2)")
                         .arg(overrideOf(tool))
                         .arg(nameEdit_->text().isEmpty() ? tr("(none)") : nameEdit_->text()));
  } else if (c) {
    const QString why = QString::fromStdString(core::formatMessage(c->note(), Language::coreLang()));
    choice_->setText(tr("Chosen from the program: %1").arg(why));
  } else {
    choice_->clear();
  }
  choice_->setVisible(!choice_->text().isEmpty());
  updatePreview();
}

void ToolSelectDialog::setLibraryTool(int tool, const QString& id, bool jobOnly) {
  setCurrentTool(tool);
  jobOnly_->setChecked(jobOnly);
  const int index = libraryCombo_->findData(id);
  libraryCombo_->setCurrentIndex(index < 0 ? 0 : index);
  onLibraryChosen(libraryCombo_->currentIndex());
}

void ToolSelectDialog::onLibraryChosen(int index) {
  const int row = list_->currentRow();
  if (row < 0 || index < 0) return;
  const QString id = libraryCombo_->itemData(index).toString();
  jobOnlyPending_ = 0;
  if (jobOnly_->isChecked()) {
    setOverride(row + 1, id);
  } else {
    setOverride(row + 1, {});
    if (!id.isEmpty()) {
      const io::LibraryTool* t = io::shippedToolLibrary().find(id.toStdString());
      if (t) {
        const auto i = static_cast<std::size_t>(row);
        if (!beforeLibrary_[i])
          beforeLibrary_[i] =
              StationLine{tools_.bitmap[i], tools_.libraryPath[i], tools_.pixelsPerMm[i], tools_.bitmapUnreadable[i]};
        tools_.setLibraryTool(row + 1, t->id, io::shippedToolLibrary().bitmapPath(*t), t->pixelsPerMm);
      }
    }
  }
  retranslate();
}

void ToolSelectDialog::onJobOnlyToggled(bool on) {
  if (syncing_) return;
  const int row = list_->currentRow();
  if (row < 0) return;
  const QString id = libraryCombo_->currentData().toString();
  jobOnlyPending_ = on && id.isEmpty() ? row + 1 : 0;
  const auto i = static_cast<std::size_t>(row);
  if (on && !id.isEmpty() && beforeLibrary_[i]) {
    // The tool was put in tools.cfg's line a moment ago: it is this program's now, and
    // the line is what it was (the promise on the box).
    tools_.bitmap[i] = beforeLibrary_[i]->bitmap;
    tools_.libraryPath[i] = beforeLibrary_[i]->libraryPath;
    tools_.pixelsPerMm[i] = beforeLibrary_[i]->pixelsPerMm;
    tools_.bitmapUnreadable[i] = beforeLibrary_[i]->unreadable;
    beforeLibrary_[i].reset();
  } else if (!on && !id.isEmpty() && !overrideOf(row + 1).isEmpty()) {
    // Unticked: the chosen tool goes to tools.cfg after all.
    const io::LibraryTool* t = io::shippedToolLibrary().find(id.toStdString());
    if (t) {
      if (!beforeLibrary_[i])
        beforeLibrary_[i] =
            StationLine{tools_.bitmap[i], tools_.libraryPath[i], tools_.pixelsPerMm[i], tools_.bitmapUnreadable[i]};
      tools_.setLibraryTool(row + 1, t->id, io::shippedToolLibrary().bitmapPath(*t), t->pixelsPerMm);
    }
  }
  setOverride(row + 1, on ? id : QString());
  retranslate();
}

void ToolSelectDialog::accept() {
  // Every named bitmap must load, so the saved table is one the loader accepts.
  QStringList problems;
  for (int t = 1; t <= stationCount(); ++t) {
    const QString name = QString::fromStdString(tools_.bitmap[static_cast<std::size_t>(t - 1)]);
    if (name.isEmpty()) continue;
    const QString path = resolve(name);
    if (path.isEmpty()) {
      problems << tr("Tool %1: %2 is not in the tool library").arg(t, 2, 10, QLatin1Char('0')).arg(name);
      continue;
    }
    const auto image = io::readImage(path.toStdString());
    if (!image.value) {
      problems << tr("Tool %1: %2")
                      .arg(t, 2, 10, QLatin1Char('0'))
                      .arg(image.diagnostics.empty() ? name
                                                     : QString::fromStdString(core::formatMessage(
                                                           image.diagnostics.front(), Language::coreLang())));
      continue;
    }
    // Larger than a tool can be: the setup would refuse it (F139), so the dialog does now.
    const auto i = static_cast<std::size_t>(t - 1);
    const double ppm =
        tools_.bitmap[i].rfind(io::kLibraryPrefix, 0) == 0 ? tools_.pixelsPerMm[i] : io::kSeedPixelsPerMm;
    const int most = io::maxToolBitmapPixels(ppm);
    if (image.value->width > most || image.value->height > most) {
      const core::Diagnostic tooLarge{
          core::Severity::Error,
          core::codes::kToolBitmapTooLarge,
          {},
          {QDir(configDir_).filePath(QStringLiteral("tools.cfg")).toStdString(),
           QStringLiteral("%1").arg(t, 2, 10, QLatin1Char('0')).toStdString(), name.toStdString(),
           std::to_string(image.value->width), std::to_string(image.value->height), std::to_string(most),
           QString::number(ppm).toStdString()}};
      problems << QString::fromStdString(core::formatMessage(tooLarge, Language::coreLang()));
    }
  }
  if (!problems.isEmpty()) {
    QMessageBox::warning(this, windowTitle(), problems.join(QLatin1Char('\n')));
    return;
  }
  // Nothing is written here (issue 30 item 2): the window makes the edited table an undo
  // step on the setup it holds, and File ▸ Save writes tools.cfg. A table the loader would
  // refuse is never accepted.
  if (toolsChanged()) {
    const auto check = io::parseToolTable(io::formatToolTable(tools_), tools_.folder, "tools.cfg", stationCount());
    if (!check.ok()) {
      QMessageBox::warning(
          this, windowTitle(),
          QString::fromStdString(core::formatMessage(check.diagnostics.front(), Language::coreLang())));
      return;
    }
  }
  tools_.bitmapUnreadable.fill(false);  // every named bitmap was read just now
  QDialog::accept();
}

bool ToolSelectDialog::toolsChanged() const {
  return tools_.bitmap != loaded_.bitmap || tools_.material != loaded_.material;
}

void ToolSelectDialog::setToolMaterial(int tool, const QString& id) {
  if (tool < 1 || tool > stationCount()) return;
  tools_.material[static_cast<std::size_t>(tool - 1)] = id.toStdString();
  if (tool == currentTool()) syncControls();
}

void ToolSelectDialog::retranslate() {
  setWindowTitle(tr("Tool Select"));
  nameLabel_->setText(tr("Bitmap file:"));
  browseButton_->setText(tr("Browse..."));
  offsetLabel_->setText(tr("Preview with offset:"));
  nameEdit_->setPlaceholderText(tr("e.g. resources/tools/turning.bmp"));
  libraryLabel_->setText(tr("Library tool:"));
  jobOnly_->setText(tr("Only for this program (tools.cfg is not changed)"));
  libraryCombo_->setItemText(0, tr("(a bitmap file, below)"));
  materialLabel_->setText(tr("Tool material:"));
  materialCombo_->setItemText(0, tr("(the library tool's, else not known)"));
  materialCombo_->setItemText(1, tr("HSS (high-speed steel)"));
  materialCombo_->setItemText(2, tr("Carbide"));
  materialCombo_->setItemText(3, tr("Coated carbide"));
  const bool th = Language::coreLang() == core::Lang::Th;
  for (int i = 1; i < libraryCombo_->count(); ++i) {
    const io::LibraryTool* t = io::shippedToolLibrary().find(libraryCombo_->itemData(i).toString().toStdString());
    if (t)
      libraryCombo_->setItemText(i, QStringLiteral("%1 — %2").arg(QString::fromStdString(t->id),
                                                                  QString::fromStdString(th ? t->nameTh : t->nameEn)));
  }
  for (int t = 1; t <= stationCount(); ++t) {
    const QString entry = shownEntry(t);
    QString name = entry.isEmpty() ? tr("(none)") : QFileInfo(entry).fileName();
    if (entry.startsWith(QLatin1String(io::kLibraryPrefix.data()))) name = entry.mid(int(io::kLibraryPrefix.size()));
    QString text = tr("Tool %1: %2").arg(t, 2, 10, QLatin1Char('0')).arg(name);
    if (!overrideOf(t).isEmpty())
      text += tr(" (this program)");
    else if (inference_.choiceFor(t))
      text += tr(" (from the program)");
    list_->item(t - 1)->setText(text);
  }
  QStringList lines;
  for (const auto& d : loadDiagnostics_)
    if (core::isError(d.severity)) lines << QString::fromStdString(core::formatMessage(d, Language::coreLang()));
  problems_->setText(lines.join(QLatin1Char('\n')));
  problems_->setVisible(!lines.isEmpty());
  if (list_->currentRow() >= 0) syncControls();
}

void ToolSelectDialog::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDialog::changeEvent(event);
}

}  // namespace klueng::gui
