#pragma once
// The open program file: its path, its job header (lines 1-6, edited in the Job
// details dialog) and how it was written (plain G-code or not, encoding). The
// G-code text itself lives in the editor's QTextDocument; this class reads and
// writes the whole file through the core's io::readProgramFile /
// formatProgramFile / writeTextFileAtomic so the GUI and CLI agree byte for byte.
#include <QObject>
#include <QString>
#include <optional>
#include <vector>

#include "klueng/core/design/part_design.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"

namespace klueng::gui {

// What a background load returns (plain value, safe to build off the GUI thread).
struct LoadedProgram {
  QString path;
  bool ok = false;  // a usable program was read
  core::io::ProgramFile file;
  QString gcode;                              // file.gcode as QString, converted off the GUI thread
  std::vector<core::Diagnostic> diagnostics;  // header / file diagnostics (F1xx)
  std::vector<core::Diagnostic> stockNotes;   // where the stock came from (I15x)
};

class Document : public QObject {
  Q_OBJECT
 public:
  explicit Document(QObject* parent = nullptr);

  // The header as it stands, for undo (setup_commands.h): restoreHeader() puts
  // back exactly this, where the stock came from and the modified flag included.
  struct HeaderState {
    core::io::JobHeader header;
    std::vector<core::Diagnostic> stockNotes;
    bool modified = false;
  };
  HeaderState headerState() const { return {file_.header, stockNotes_, headerModified_}; }
  // What setHeader(header) would make of it, without making it (an undo command's "after").
  HeaderState headerStateFor(const core::io::JobHeader& header) const;
  void restoreHeader(const HeaderState& state);

  // Reads and splits a program file; thread-safe (touches no Document).
  // A plain file's stock (SPEC 2 ext): `jobDetails` (set for this very file), else JobHeader's
  // defaults until the first check's Job infers it (takeInferredStock) — never
  // `defaultsForPlain`'s stock, whose text fields (project ...) it keeps.
  static LoadedProgram load(const QString& path, const core::io::JobHeader& defaultsForPlain,
                            const std::optional<core::io::JobHeader>& jobDetails = std::nullopt);

  // A plain file whose stock was inferred (or defaulted) takes the stock a
  // Job resolved (`resolved`, with its notes) — after the dialect or the units
  // changed, the same text may mean another approach. Job details and headers
  // are left alone. Returns true when the stock changed.
  bool takeInferredStock(const core::io::JobHeader& resolved, std::vector<core::Diagnostic> notes);

  // Start an untitled program with the given job details.
  void reset(const core::io::JobHeader& header);
  // What a new or plain program starts with from the remembered Job details:
  // the programmer and the stock size; never another job's project, part or
  // material, which would print on this program's sheets (issue 28 item 3).
  static core::io::JobHeader newProgramHeader(const core::io::JobHeader& remembered);
  // Take over a successfully loaded program.
  void adopt(const LoadedProgram& loaded);

  // Writes header + gcode atomically (UTF-8, LF). On success the path becomes
  // `path` and the header is no longer modified.
  bool save(const QString& path, const QString& gcode, QString* error);
  // The exact text save() would write.
  std::string formatted(const QString& gcode) const;

  QString filePath() const { return path_; }
  bool isUntitled() const { return path_.isEmpty(); }
  // "untitled.txt" or the file's name, for the title bar.
  QString displayName() const;

  const core::io::JobHeader& header() const { return file_.header; }
  // A header file's header is part of the file (modified until saved); a plain
  // file's Job details are not (the caller remembers them per file).
  void setHeader(const core::io::JobHeader& header);
  // Where the stock came from (I15x notes; the first one says it in short).
  const std::vector<core::Diagnostic>& stockNotes() const { return stockNotes_; }
  bool isPlainGcode() const { return file_.plainGcode; }
  // File line of the editor's first line: 7 after a 6-line header, 1 for plain files.
  int gcodeFirstLine() const { return file_.gcodeFirstLine; }
  // Diagnostics of the header and file format from the last load (F1xx, rule 13).
  const std::vector<core::Diagnostic>& fileDiagnostics() const { return fileDiagnostics_; }
  // The first line the reader left out because it is too long to edit (F106),
  // 0 when none: saving over the file would lose it, so the window refuses.
  int firstOmittedLine() const;

  bool isHeaderModified() const { return headerModified_; }

  // The Part Designer's design this program was created from, for the drawing's
  // tolerances and finish marks (issue 28 item 3); none for a program opened or typed.
  const std::optional<core::design::PartDesign>& design() const { return design_; }
  void setDesign(const core::design::PartDesign& design) { design_ = design; }

 signals:
  void headerChanged();
  void pathChanged(const QString& path);

 private:
  QString path_;
  core::io::ProgramFile file_;
  std::vector<core::Diagnostic> fileDiagnostics_;
  std::vector<core::Diagnostic> stockNotes_;
  bool headerModified_ = false;
  std::optional<core::design::PartDesign> design_;
};

}  // namespace klueng::gui
