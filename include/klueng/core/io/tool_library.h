#pragma once
// The tool library (docs/tools.md): the tools a school lathe has, each a
// bitmap drawn at its own resolution plus its nose radius and tip number.
// Shipped in resources/tools/library/library.cfg. tools.cfg names one with a
// line `library:ID`.
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/io/result.h"

namespace klueng::core::io {

// What a tool is for. Order and ids are part of the library format.
enum class ToolKind {
  Unknown,      // a user's own bitmap we cannot tell
  Turning,      // outside turning (roughing, finishing, profiling)
  ThreadingOd,  // outside threading
  ThreadingId,  // inside threading
  Grooving,
  Parting,
  CentreDrill,
  Drill,
  Boring,
};

// "turning", "threading-od", ... ("unknown" for Unknown).
std::string_view toolKindId(ToolKind kind);
bool parseToolKindId(std::string_view id, ToolKind& out);

struct LibraryTool {
  std::string id;  // "cnmg-80-r08"
  ToolKind kind = ToolKind::Unknown;
  double pixelsPerMm = 10.0;
  double noseRadius = 0.0;  // mm
  int tip = 0;              // imaginary tip 0..9 (SPEC 9)
  double size = 0.0;        // drill diameter / blade width, mm; 0 = not applicable
  std::string bitmap;       // file name, relative to the library's folder
  std::string nameEn;
  std::string nameTh;
  // Optional 10th field, `key=value` words (issue 39): material=hss|carbide|coated-carbide
  // (the cutting-speed range the cutting data judges by; empty = not known) and edge=MM (the
  // insert's cutting-edge length; 0 = not known).
  std::string material;
  double edge = 0.0;
  int line = 0;  // its line in library.cfg, for diagnostics
};

struct ToolLibrary {
  std::vector<LibraryTool> tools;  // in file order
  std::string folder;              // folder of library.cfg

  const LibraryTool* find(std::string_view id) const;  // nullptr when unknown
  std::string bitmapPath(const LibraryTool& tool) const;
  // "cnmg-80-r08, cnmg-80-r04, ..." for messages that list what is allowed.
  std::string idList() const;
};

// Lines: `id | kind | px_per_mm | nose_r | tip | size | bitmap | English name | Thai name`;
// blank lines and lines starting with '#' are skipped. Errors (F160..F166)
// carry file:line:column; a bad line is left out, the rest is kept.
ReadResult<ToolLibrary> parseToolLibrary(std::string_view text, const std::string& folder, const std::string& fileName);
// Also reports bitmaps that do not exist (F167).
ReadResult<ToolLibrary> readToolLibrary(const std::string& path);
// The shipped library (resources/tools/library/library.cfg under
// shippedConfigDir()), read once; empty when it cannot be read.
const ToolLibrary& shippedToolLibrary();
std::string shippedToolLibraryPath();

// What a plain bitmap file name says about its tool ("07-parting-3mm.bmp" ->
// Parting), by words in the name; Unknown when it says nothing.
ToolKind guessToolKind(std::string_view fileName);

// Whether a tool of kind `have` can do the work `want` needs. Unknown fits
// everything (a user's own bitmap is never called wrong); grooving and parting
// blades fit each other, as do centre drills and drills.
bool toolKindFits(ToolKind have, ToolKind want);

}  // namespace klueng::core::io
