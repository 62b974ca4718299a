#pragma once
// The strip above the editor that stands for the file's six header lines
// (issue 11: "a new program's first line is numbered 7"). The editor shows the
// G-code only and numbers its lines as the file does (SPEC 2: diagnostics, the
// CLI and the program sheet all name file lines); this strip says what lines
// 1-6 are and opens Job Details on a click. Hidden for a plain G-code file.
#include <QLabel>

#include "klueng/core/io/program_file.h"

namespace klueng::gui {

class HeaderStrip : public QLabel {
  Q_OBJECT
 public:
  explicit HeaderStrip(QWidget* parent = nullptr);
  void showHeader(const core::io::JobHeader& header, bool plainGcode);
  void retranslateUi();

 signals:
  void activated();  // edit the header (File > Job Details)

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void changeEvent(QEvent* event) override;

 private:
  core::io::JobHeader header_;
  bool plain_ = true;
};

}  // namespace klueng::gui
