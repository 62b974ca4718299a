#pragma once
// Tool Select (SPEC 11-12): tools 01-08 -> bitmap files, with a live preview
// of the selected bitmap and its controlled point for the tip of the chosen
// offset; Browse... for .bmp/.png.
//
// Public API
//   ToolSelectDialog dlg(configDir, parent);   reads configDir/tools.cfg and offset.cfg
//   dlg.exec() == Accepted  -> the dialog has written tools.cfg (see savedConfigDir())
//   toolTable()            the edited table (names as written, folder = savedConfigDir())
//   savedConfigDir()       where tools.cfg went: configDir, or the per-user copy
//                          (userConfigDir()) when configDir is read-only
//   setCurrentTool(n) / currentTool()   1..8
//   setBitmapName(tool, name)           as if typed (tests)
//   previewSprite()        the sprite shown (tests)
//   loadDiagnostics()      problems found reading the files (shown in the dialog)
// Helpers shared by the dialogs:
//   writableConfigDir(dir, &error)   dir when tools.cfg/offset.cfg there can be written,
//                          else the per-user copy (core::io::ensureUserConfigDir())
#include <QDialog>
#include <QList>
#include <QString>

#include "klueng/core/diagnostic.h"
#include "klueng/core/io/tool_config.h"
#include "render/tool_sprite.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QSpinBox;
class QDialogButtonBox;
class QPlainTextEdit;

namespace klueng::gui {

QString writableConfigDir(const QString& dir, QString* error);

class ToolPreview;

class ToolSelectDialog : public QDialog {
  Q_OBJECT
 public:
  explicit ToolSelectDialog(const QString& configDir, QWidget* parent = nullptr);

  core::io::ToolTable toolTable() const;
  QString savedConfigDir() const { return savedDir_; }
  int currentTool() const;
  void setCurrentTool(int tool);
  void setBitmapName(int tool, const QString& name);
  const render::ToolSprite& previewSprite() const;
  QList<core::Diagnostic> loadDiagnostics() const { return loadDiagnostics_; }

 public slots:
  void accept() override;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void updatePreview();
  void browse();
  void onToolRowChanged(int row);
  void onNameEdited(const QString& text);
  QString resolve(const QString& name) const;

  QString configDir_;
  QString savedDir_;
  core::io::ToolTable tools_;
  core::io::OffsetTable offsets_;
  QList<core::Diagnostic> loadDiagnostics_;

  QListWidget* list_ = nullptr;
  QLabel* nameLabel_ = nullptr;
  QLineEdit* nameEdit_ = nullptr;
  QLabel* browseHint_ = nullptr;
  class QPushButton* browseButton_ = nullptr;
  QLabel* offsetLabel_ = nullptr;
  QSpinBox* offsetSpin_ = nullptr;
  QLabel* tipInfo_ = nullptr;
  ToolPreview* preview_ = nullptr;
  QLabel* problems_ = nullptr;
  QDialogButtonBox* buttons_ = nullptr;
};

}  // namespace klueng::gui
