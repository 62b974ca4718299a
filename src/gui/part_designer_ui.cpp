// The part designer's widgets and their texts.
#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

#include "gui/design_model.h"
#include "gui/language.h"
#include "klueng/core/gcode/machine_profile.h"
#include "gui/design_preview.h"
#include "gui/part3d_view.h"
#include "gui/part_designer.h"

namespace klueng::gui {

namespace {

QToolButton* toolButton(QWidget* parent, const char* name, const char* icon) {
  auto* b = new QToolButton(parent);
  b->setObjectName(QString::fromLatin1(name));
  if (icon) b->setIcon(QIcon(QStringLiteral(":/icons/%1.svg").arg(QString::fromLatin1(icon))));
  b->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  return b;
}

}  // namespace

void PartDesignerDialog::buildUi() {
  auto* top = new QHBoxLayout;
  addRowButtons(top);
  top->addStretch(1);
  addChoices(top);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addLayout(buildBarLine());
  layout->addWidget(buildTableAndViews(), 1);
  layout->addLayout(buildFindingsAndButtons());
  resize(1180, 640);
  retranslate();
}

// Add, remove, move a row; undo, redo; open and save a design.
void PartDesignerDialog::addRowButtons(QHBoxLayout* top) {
  addButton_ = toolButton(this, "designAdd", "new");
  addButton_->setPopupMode(QToolButton::InstantPopup);
  auto* addMenu = new QMenu(addButton_);
  for (int k = 0; k <= static_cast<int>(DesignRowKind::Thread); ++k) {
    QAction* a = addMenu->addAction(DesignTableModel::kindName(static_cast<DesignRowKind>(k)));
    a->setData(k);
    connect(a, &QAction::triggered, this, [this, k] { addRow(k); });
  }
  addButton_->setMenu(addMenu);
  removeButton_ = toolButton(this, "designRemove", "delete");
  upButton_ = toolButton(this, "designUp", nullptr);
  upButton_->setArrowType(Qt::UpArrow);
  downButton_ = toolButton(this, "designDown", nullptr);
  downButton_->setArrowType(Qt::DownArrow);
  undoButton_ = toolButton(this, "designUndo", "undo");
  redoButton_ = toolButton(this, "designRedo", "redo");
  openButton_ = toolButton(this, "designOpen", "open");
  saveButton_ = toolButton(this, "designSave", "save");
  for (QToolButton* b : {upButton_, downButton_}) b->setToolButtonStyle(Qt::ToolButtonIconOnly);
  for (QToolButton* b : {undoButton_, redoButton_}) b->setToolButtonStyle(Qt::ToolButtonIconOnly);
  connect(removeButton_, &QToolButton::clicked, this, &PartDesignerDialog::removeRow);
  connect(upButton_, &QToolButton::clicked, this, [this] { moveRow(-1); });
  connect(downButton_, &QToolButton::clicked, this, [this] { moveRow(+1); });
  connect(undoButton_, &QToolButton::clicked, undo_, &QUndoStack::undo);
  connect(redoButton_, &QToolButton::clicked, undo_, &QUndoStack::redo);
  connect(undo_, &QUndoStack::canUndoChanged, undoButton_, &QToolButton::setEnabled);
  connect(undo_, &QUndoStack::canRedoChanged, redoButton_, &QToolButton::setEnabled);
  undoButton_->setEnabled(false);
  redoButton_->setEnabled(false);
  undoButton_->setShortcut(QKeySequence::Undo);
  redoButton_->setShortcut(QKeySequence::Redo);
  connect(openButton_, &QToolButton::clicked, this, &PartDesignerDialog::openDialog);
  connect(saveButton_, &QToolButton::clicked, this, &PartDesignerDialog::saveDialog);
  for (QToolButton* b :
       {addButton_, removeButton_, upButton_, downButton_, undoButton_, redoButton_, openButton_, saveButton_})
    top->addWidget(b);
}

// The machine (dialect), the material, the tool material, parting off.
void PartDesignerDialog::addChoices(QHBoxLayout* top) {
  dialectLabel_ = new QLabel(this);
  dialect_ = new QComboBox(this);
  dialect_->setObjectName(QStringLiteral("designDialect"));
  dialect_->addItem(QStringLiteral("Fanuc 0i-TF"), static_cast<int>(core::gcode::Dialect::Fanuc));
  dialect_->addItem(QStringLiteral("Haas ST"), static_cast<int>(core::gcode::Dialect::Haas));
  dialect_->addItem(QString(), static_cast<int>(core::gcode::Dialect::Classic));
  // The machines past the shipped three (romi-gl240m, the user's): the program in their G-code system.
  for (const core::gcode::MachineProfile* p : core::gcode::machineProfiles())
    if (static_cast<int>(p->dialect) > static_cast<int>(core::gcode::Dialect::Classic))
      dialect_->addItem(QString(), static_cast<int>(p->dialect));
  materialLabel_ = new QLabel(this);
  material_ = new QComboBox(this);
  material_->setObjectName(QStringLiteral("designMaterial"));
  for (const auto& row : speeds_) material_->addItem(QString(), QString::fromStdString(row.material));
  toolMaterialLabel_ = new QLabel(this);
  toolMaterial_ = new QComboBox(this);
  toolMaterial_->setObjectName(QStringLiteral("designToolMaterial"));
  toolMaterial_->addItem(QString(), QStringLiteral("carbide"));
  toolMaterial_->addItem(QString(), QStringLiteral("hss"));
  for (QComboBox* c : {dialect_, material_, toolMaterial_})
    connect(c, &QComboBox::currentIndexChanged, this, [this] { scheduleLoop(); });
  partOff_ = new QCheckBox(this);
  partOff_->setObjectName(QStringLiteral("designPartOff"));
  connect(partOff_, &QCheckBox::toggled, this, [this](bool on) {
    if (design().partOff == on) return;
    core::design::PartDesign d = design();
    d.partOff = on;
    setDesign(d, partOff_->text().remove(QLatin1Char('&')));
  });
  for (QWidget* w : std::initializer_list<QWidget*>{dialectLabel_, dialect_, materialLabel_, material_,
                                                    toolMaterialLabel_, toolMaterial_, partOff_})
    top->addWidget(w);
}

// The bar the design is cut from, and the one the open file names (to take over).
QHBoxLayout* PartDesignerDialog::buildBarLine() {
  auto* bar = new QHBoxLayout;
  barLabel_ = new QLabel(this);
  barLabel_->setObjectName(QStringLiteral("designBar"));
  jobButton_ = new QPushButton(this);
  jobButton_->setObjectName(QStringLiteral("designJobDetails"));
  connect(jobButton_, &QPushButton::clicked, this, &PartDesignerDialog::jobDetailsRequested);
  fileBar_ = new QLabel(this);
  fileBar_->setStyleSheet(QStringLiteral("color: #8a5a00"));
  useFileBar_ = new QPushButton(this);
  useFileBar_->setObjectName(QStringLiteral("designUseFileBar"));
  connect(useFileBar_, &QPushButton::clicked, this, [this] {
    emit useStock(fileStock_[0], fileStock_[1], fileStock_[2]);
    fileBar_->hide();
    useFileBar_->hide();
  });
  fileBar_->hide();
  useFileBar_->hide();
  bar->addWidget(barLabel_);
  bar->addWidget(jobButton_);
  bar->addSpacing(12);
  bar->addWidget(fileBar_);
  bar->addWidget(useFileBar_);
  bar->addStretch(1);
  return bar;
}

// The rows beside the drawing and the 3D view.
QSplitter* PartDesignerDialog::buildTableAndViews() {
  table_ = new QTableView(this);
  table_->setObjectName(QStringLiteral("designTable"));
  table_->setModel(model_);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->verticalHeader()->setVisible(false);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                          QAbstractItemView::AnyKeyPressed);
  connect(table_->selectionModel(), &QItemSelectionModel::currentChanged, this, [this] { updateSelection(); });

  preview_ = new DesignPreview(this);
  view3d_ = new Part3DWidget(this);
  tabs_ = new QTabWidget(this);
  tabs_->setObjectName(QStringLiteral("designTabs"));
  tabs_->addTab(preview_, QString());
  tabs_->addTab(view3d_, QString());
  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(table_);
  split->addWidget(tabs_);
  split->setStretchFactor(0, 1);
  split->setStretchFactor(1, 1);
  split->setSizes({500, 640});
  return split;
}

// What the design loop found, and the buttons to take its program or close.
QHBoxLayout* PartDesignerDialog::buildFindingsAndButtons() {
  findings_ = new QListWidget(this);
  findings_->setObjectName(QStringLiteral("designFindings"));
  findings_->setWordWrap(true);
  findings_->setMaximumHeight(130);
  createButton_ = new QPushButton(this);
  createButton_->setObjectName(QStringLiteral("designCreateProgram"));
  createButton_->setEnabled(false);
  connect(createButton_, &QPushButton::clicked, this, [this] {
    if (lastLoop() && lastLoop()->program) emit programReady(QString::fromStdString(lastLoop()->program->text));
  });
  auto* closeButton = new QPushButton(this);
  closeButton->setObjectName(QStringLiteral("designClose"));
  connect(closeButton, &QPushButton::clicked, this, &QDialog::close);
  auto* bottom = new QHBoxLayout;
  bottom->addWidget(findings_, 1);
  auto* buttons = new QVBoxLayout;
  buttons->addWidget(createButton_);
  buttons->addStretch(1);
  buttons->addWidget(closeButton);
  bottom->addLayout(buttons);
  return bottom;
}

void PartDesignerDialog::retranslate() {
  setWindowTitle(tr("Part designer"));
  addButton_->setText(tr("Add"));
  addButton_->setToolTip(tr("Add a feature: a cylinder, taper or arc outside, a bore step, a groove or a thread"));
  const QList<QAction*> kinds = addButton_->menu()->actions();
  for (QAction* a : kinds) a->setText(DesignTableModel::kindName(static_cast<DesignRowKind>(a->data().toInt())));
  removeButton_->setText(tr("Remove"));
  upButton_->setToolTip(tr("Move the feature toward the face"));
  downButton_->setToolTip(tr("Move the feature toward the chuck"));
  undoButton_->setToolTip(tr("Undo the last change to the part"));
  redoButton_->setToolTip(tr("Redo"));
  openButton_->setText(tr("Open..."));
  openButton_->setToolTip(tr("Open a part file (JSON) or import a DXF drawing of the half section"));
  saveButton_->setText(tr("Save..."));
  saveButton_->setToolTip(tr("Save the part as a part file (JSON)"));
  dialectLabel_->setText(tr("Dialect:"));
  dialect_->setItemText(2, tr("Classic (1999)"));
  const bool thai = Language::coreLang() == core::Lang::Th;
  for (int k = 3; k < dialect_->count(); ++k) {
    const core::gcode::MachineProfile& p =
        core::gcode::machineProfile(static_cast<core::gcode::Dialect>(dialect_->itemData(k).toInt()));
    const std::string_view name = thai ? p.nameTh : p.nameEn;
    dialect_->setItemText(k, QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())));
  }
  materialLabel_->setText(tr("Material:"));
  for (int k = 0; k < material_->count(); ++k) {
    const QString row = material_->itemData(k).toString();
    material_->setItemText(k, row == QStringLiteral("aluminium")   ? tr("Aluminium")
                              : row == QStringLiteral("brass")     ? tr("Brass")
                              : row == QStringLiteral("cast-iron") ? tr("Cast iron")
                              : row == QStringLiteral("steel")     ? tr("Steel")
                                                                   : row);
  }
  toolMaterialLabel_->setText(tr("Tool:"));
  toolMaterial_->setItemText(0, tr("Carbide"));
  toolMaterial_->setItemText(1, tr("HSS"));
  jobButton_->setText(tr("Job details..."));
  partOff_->setText(tr("Part off"));
  partOff_->setToolTip(tr("Cut the part off the bar at its left end with the parting tool (T07)"));
  useFileBar_->setText(tr("Use this bar"));
  tabs_->setTabText(0, tr("Drawing"));
  tabs_->setTabText(1, tr("3D"));
  createButton_->setText(tr("Create program"));
  createButton_->setToolTip(tr("Open the generated program in the editor as a new file"));
  findChild<QPushButton*>(QStringLiteral("designClose"))->setText(tr("Close"));
  view3d_->setToolTip(tr("Drag to turn, right-drag to move, wheel to zoom, double-click for the first view"));
  model_->retranslate();
  if (loop_) showLoop();
}

}  // namespace klueng::gui
