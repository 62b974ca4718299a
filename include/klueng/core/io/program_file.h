#pragma once
// The program file (SPEC 2): six header lines then G-code, or a plain G-code file.
#include <optional>
#include <string>
#include <string_view>

#include "klueng/core/io/result.h"

namespace klueng::core::io {

enum class LengthUnit { Inch = 0, Millimetre = 1 };

// Where a job's stock size came from (SPEC 2 ext); the user is always told.
enum class StockSource {
  Header,       // the file's own 6-line header
  CommandLine,  // klueng-cli --stock
  JobDetails,   // Job details the user set for this (plain) file, remembered per file
  Inferred,     // from the program itself (machine/stock_inference.h)
  Default,      // nothing to go by: JobHeader's defaults
};

struct JobHeader {
  std::string project;
  std::string part;
  std::string material;
  double diameter = 50.0;  // as written, in `diameterUnit`
  LengthUnit diameterUnit = LengthUnit::Millimetre;
  double length = 100.0;
  LengthUnit lengthUnit = LengthUnit::Millimetre;
  std::string programmer;
  // Tube stock: the bore diameter in `diameterUnit`; 0 = solid bar. Written on
  // line 4 after the diameter: `1118x90` = 118 mm tube with a 90 mm bore.
  double bore = 0.0;
  StockSource stockSource = StockSource::Default;
  // How this file's lengths without a decimal point are read, when the user
  // chose it for the file (Job details; true = whole units, false = least
  // input increments); unset: the program's numbers or the machine decide
  // (machine/point_reading.h). Not part of the 6-line header.
  std::optional<bool> calculatorInput;
  // Where this file's tools work, when the user chose it (Job details): true =
  // beyond the centre line (a rear tool post, X < 0), false = in front; unset:
  // what a plain program's run shows, else the machine (machine.cfg).
  std::optional<bool> toolsBeyondCentre;
  // The machine this program is written for (issue 27): the id a comment at the
  // program's head names, `(MACHINE: romi-gl240m)` (machineNamedIn); empty: none.
  // File line of that comment, 0 when none. Job details writes it (withMachineNamed).
  std::string machine;
  int machineLine = 0;
  // The setup exercise (issue 31 item 5): `(OFFSETS: UNKNOWN)` at the program's
  // head (offsetsUnknownIn); the file line of that comment, 0 when none.
  int offsetsUnknownLine = 0;
  bool offsetsUnknown() const { return offsetsUnknownLine > 0; }
  double diameterMm() const { return diameterUnit == LengthUnit::Inch ? diameter * 25.4 : diameter; }
  double lengthMm() const { return lengthUnit == LengthUnit::Inch ? length * 25.4 : length; }
  double boreMm() const { return diameterUnit == LengthUnit::Inch ? bore * 25.4 : bore; }
  // Takes the stock (sizes, units, bore and where it came from) of `from`,
  // keeping this header's text fields.
  void takeStockFrom(const JobHeader& from) {
    diameter = from.diameter;
    diameterUnit = from.diameterUnit;
    length = from.length;
    lengthUnit = from.lengthUnit;
    bore = from.bore;
    stockSource = from.stockSource;
  }
};

// "Ø50 x 100 mm", "Ø118/Ø90 x 80 mm" (tube), "Ø2.125 x 4 in": the stock in
// words that need no translation, for notes (I15x) and status texts.
std::string stockSizeText(const JobHeader& header);

enum class SourceEncoding { Utf8, Tis620 };

struct ProgramFile {
  JobHeader header;
  bool plainGcode = false;  // no 6-line header (SPEC 2 ext)
  std::string gcode;        // the G-code lines, UTF-8, original line ends normalised to '\n'
  int gcodeFirstLine = 7;   // file line number of gcode's first line (1 for plain files)
  SourceEncoding encoding = SourceEncoding::Utf8;
};

// SPEC 2 (ext): a file is a 6-line Klueng file only when its lines 4 and 5 are
// unit-digit sizes (`150`, `02.5`, `1-5`, line 4 also `1118x90`) and none of
// lines 1-3 and 6 is G-code (`%`, `(`, `;`, O/N/G/M/T + number). Anything
// else is plain G-code: leading blank lines, `%`, comments and O numbers never
// make a header, and no G-code line is ever read as one. A plain file that
// looks like a header with a broken size line gets warning F117.
//
// Decodes bytes (UTF-8, or TIS-620/Windows-874 when not valid UTF-8) and splits
// header from code. `fileName` is only used in diagnostics' args.
// Never throws; binary or huge input gives F1xx diagnostics. A stock diameter or
// length <= 0 gives E213 (SPEC 5 rule 13); a bore that is not in (0, diameter)
// gives F118. A plain file's header is `defaultsForPlain` as given (its
// stockSource included); a header file's stockSource is Header. Lines longer than 4096 characters
// are reported (F106) and read as empty lines, so line numbers stay right.
ReadResult<ProgramFile> parseProgramFile(std::string_view bytes, const JobHeader& defaultsForPlain = {},
                                         const std::string& fileName = {});
ReadResult<ProgramFile> readProgramFile(const std::string& path, const JobHeader& defaultsForPlain = {});

// A file a folder of programs holds as a program (`check DIR`, `class DIR`):
// .txt .nc .cnc .tap .ngc .gcode, any case; never a CSV, PDF or PNG beside them.
bool isProgramFileName(std::string_view path);

// The machine a program names for itself (issue 27, docs/program-file.md §8):
// a comment `(MACHINE: id)` (also `(MACHINE id)`, `;MACHINE: id`, any case) on one
// of the lines of the program's head (blank lines, `%`, comment lines and an O
// line); a comment further down is the program's own business. `line` counts
// from 1 at the first line of `gcode`, `column` is the id's (1-based, in characters).
struct NamedMachine {
  std::string id;
  int line = 0;
  int column = 0;
};
std::optional<NamedMachine> machineNamedIn(std::string_view gcode);
// The teacher's setup exercise (issue 31 item 5, docs/program-file.md §9): a
// comment `(OFFSETS: UNKNOWN)` (also `(OFFSETS UNKNOWN)`, `;OFFSETS: UNKNOWN`,
// any case) among the lines of the program's head, as `(MACHINE: id)` is found.
// The line (1 at the first line of `gcode`) of that comment, 0 when none.
int offsetsUnknownIn(std::string_view gcode);
// `gcode` naming machine `id`: the head's `(MACHINE: ...)` line rewritten, or a
// new one put after the head's `%` and O line (before the first other line);
// empty `id` takes the line out. Every other line stays as it was.
std::string withMachineNamed(std::string_view gcode, std::string_view id);

// Text in Klueng's format (UTF-8, LF). A plain file is written back plain.
// Sizes are written as unit digit + shortest number (50 mm -> "150"), a bore
// after an `x` on line 4 ("1118x90"); a file without a bore is written as before.
std::string formatProgramFile(const ProgramFile& file);
// A text line of the header (project, part, material, programmer) as written:
// on one line, and marked with a leading no-break space when it would read as
// G-code ("M10 bolt"), which the reader drops again.
std::string headerText(std::string_view text);
// writeFileAtomic (io/file_write.h) for callers that only log: false and
// `error` (the diagnostic's English text) on failure. Read-only files are refused.
bool writeTextFileAtomic(const std::string& path, std::string_view text, std::string* error = nullptr);

}  // namespace klueng::core::io
