#pragma once
// Tool Select (SPEC 11-12): every station of the turret -> a bitmap file or a
// tool of the library (docs/tools.md), with a live preview at the tool's true
// scale and its controlled point for the tip of the chosen offset; Browse...
// for .bmp/.png. The tools the program got from the library (tool_inference.h)
// are marked with their reason; a station can be set for this program only.
//
// Public API
//   ToolSelectDialog dlg(tools, offsets, configDir, parent)   the tables the document holds
//   ToolSelectDialog dlg(configDir, parent)   reads configDir/tools.cfg and offset.cfg
//   dlg.exec() == Accepted  -> toolTable() is the edited table, checked; the dialog writes
//                          no file (issue 30 item 2: the window makes it an undo step and
//                          File > Save writes tools.cfg). Stations set "only for this
//                          program" never change the table (they are jobOverrides())
//   toolTable()            the edited table (names as written, folder = configDir)
//   toolsChanged()         a line of the table differs from the one given
//   setCurrentTool(n) / currentTool()   1..stations
//   stationCount()         list rows (the turret)
//   setProgramTools(inference, overrides)  the program's choices and this file's overrides
//   jobOverrides()         the stations set for this program only (after exec)
//   setLibraryTool(tool, id, jobOnly)      as if chosen in the Library box (tests)
//   choiceText()           the "chosen from the program" line shown (tests)
//   setBitmapName(tool, name)           as if typed (tests)
//   previewSprite()        the sprite shown (tests)
//   loadDiagnostics()      problems found reading the files (shown in the dialog)
//   setToolMaterial(tool, id)  as if chosen in the Tool material box ("hss", "carbide",
//                          "coated-carbide"; "" = the library's): the cutting data judges by it
#include <QDialog>
#include <array>
#include <optional>
#include <string>
#include <QList>
#include <QString>

#include "klueng/core/diagnostic.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/infer/tool_inference.h"
#include "render/tool_sprite.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QSpinBox;
class QDialogButtonBox;
class QPlainTextEdit;

namespace klueng::gui {

class ToolPreview;

class ToolSelectDialog : public QDialog {
  Q_OBJECT
 public:
  explicit ToolSelectDialog(const QString& configDir, QWidget* parent = nullptr);
  ToolSelectDialog(const core::io::ToolTable& tools, const core::io::OffsetTable& offsets, const QString& configDir,
                   QWidget* parent = nullptr);

  core::io::ToolTable toolTable() const;
  bool toolsChanged() const;
  void setToolMaterial(int tool, const QString& id);
  int currentTool() const;
  void setCurrentTool(int tool);
  void setBitmapName(int tool, const QString& name);
  const render::ToolSprite& previewSprite() const;
  QList<core::Diagnostic> loadDiagnostics() const { return loadDiagnostics_; }
  int stationCount() const;
  void setProgramTools(const core::machine::ToolInference& inference,
                       const std::vector<core::machine::StationOverride>& overrides);
  std::vector<core::machine::StationOverride> jobOverrides() const;
  void setLibraryTool(int tool, const QString& id, bool jobOnly);
  QString choiceText() const;

 public slots:
  void accept() override;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void build(const core::io::ToolTable& tools, const core::io::OffsetTable& offsets);
  void retranslate();
  void updatePreview();
  void browse();
  void onToolRowChanged(int row);
  void onNameEdited(const QString& text);
  QString resolve(const QString& name) const;
  void onLibraryChosen(int index);
  void onJobOnlyToggled(bool on);
  // What the station uses for this program: an override, the program's choice, or tools.cfg.
  QString shownEntry(int tool) const;
  QString overrideOf(int tool) const;
  void setOverride(int tool, const QString& id);
  void syncControls();

  QString configDir_;
  core::io::ToolTable tools_;
  core::io::ToolTable loaded_;  // the table as given: toolsChanged() compares with it
  // A station's tools.cfg line from before a library tool was chosen into it, so ticking
  // "only for this program" afterwards gives tools.cfg its own line back.
  struct StationLine {
    std::string bitmap, libraryPath;
    double pixelsPerMm = core::io::kSeedPixelsPerMm;
    bool unreadable = false;
  };
  std::array<std::optional<StationLine>, core::io::kMaxStations> beforeLibrary_;
  core::io::OffsetTable offsets_;
  QList<core::Diagnostic> loadDiagnostics_;
  core::machine::ToolInference inference_;
  std::vector<core::machine::StationOverride> overrides_;
  bool syncing_ = false;
  int jobOnlyPending_ = 0;  // station ticked "only for this program" before a library tool was chosen

  QListWidget* list_ = nullptr;
  QLabel* libraryLabel_ = nullptr;
  QComboBox* libraryCombo_ = nullptr;
  QLabel* materialLabel_ = nullptr;  // the tool's cutting material (issue 39): tools.cfg `| material=`
  QComboBox* materialCombo_ = nullptr;
  QCheckBox* jobOnly_ = nullptr;
  QLabel* choice_ = nullptr;
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
