#pragma once
// The program file (SPEC 2): six header lines then G-code, or a plain G-code file.
#include <string>
#include <string_view>

#include "klueng/core/io/result.h"

namespace klueng::core::io {

enum class LengthUnit { Inch = 0, Millimetre = 1 };

struct JobHeader {
  std::string project;
  std::string part;
  std::string material;
  double diameter = 50.0;     // as written, in `diameterUnit`
  LengthUnit diameterUnit = LengthUnit::Millimetre;
  double length = 100.0;
  LengthUnit lengthUnit = LengthUnit::Millimetre;
  std::string programmer;
  double diameterMm() const { return diameterUnit == LengthUnit::Inch ? diameter * 25.4 : diameter; }
  double lengthMm() const { return lengthUnit == LengthUnit::Inch ? length * 25.4 : length; }
};

enum class SourceEncoding { Utf8, Tis620 };

struct ProgramFile {
  JobHeader header;
  bool plainGcode = false;      // no 6-line header (SPEC 2 ext)
  std::string gcode;            // the G-code lines, UTF-8, original line ends normalised to '\n'
  int gcodeFirstLine = 7;       // file line number of gcode's first line (1 for plain files)
  SourceEncoding encoding = SourceEncoding::Utf8;
};

// Decodes bytes (UTF-8, or TIS-620/Windows-874 when not valid UTF-8) and splits
// header from code. `fileName` is only used in diagnostics' args.
// Never throws; binary or huge input gives F1xx diagnostics. A stock diameter or
// length <= 0 gives E213 (SPEC 5 rule 13). Lines longer than 4096 characters
// are reported (F106) and read as empty lines, so line numbers stay right.
ReadResult<ProgramFile> parseProgramFile(std::string_view bytes, const JobHeader& defaultsForPlain = {},
                                         const std::string& fileName = {});
ReadResult<ProgramFile> readProgramFile(const std::string& path, const JobHeader& defaultsForPlain = {});

// Text in Klueng's format (UTF-8, LF). A plain file is written back plain.
// Sizes are written as unit digit + shortest number (50 mm -> "150").
std::string formatProgramFile(const ProgramFile& file);
// Atomic write (temporary file in the same folder + fsync + rename).
// Returns false and fills error (English, for logs) on failure.
bool writeTextFileAtomic(const std::string& path, std::string_view text, std::string* error = nullptr);

}  // namespace klueng::core::io
