#include "klueng/core/job/class_grading.h"

#include "klueng/core/gcode/word_format.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/cutting_data.h"
#include "klueng/core/cut/guess_fit.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/io/folder_files.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/messages.h"
#include "klueng/core/machine/interpreter.h"

namespace klueng::core::job {

using namespace cut;

namespace {

namespace fs = std::filesystem;

std::string place(const Diagnostic& d) {
  return d.range.line > 0 ? d.code + " line " + std::to_string(d.range.line) : d.code;  // a file's own F-code has none
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// Whether the file at `path` says the offsets are unknown (its head); false when it cannot be read.
bool classAsksTouchOff(const std::string& path) {
  if (path.empty()) return false;
  const io::ReadResult<io::ProgramFile> read = io::readProgramFile(path);
  return read.value && read.value->header.offsetsUnknown();
}

// A refused entry's first_error: its code and the English words of the CSV.
std::string refusalText(const Diagnostic& d) {
  if (d.code == codes::kOutsideFolder) return d.code + " refused: points outside the folder";
  if (d.code == codes::kNoSuchFile) return d.code + " unreadable: a link to nothing";
  if (d.code == codes::kNotAnOrdinaryFile) return d.code + " unreadable: not an ordinary file";
  return d.code + " unreadable: a folder";
}

std::string touchOffMm(double v) { return gcode::formatFixed(std::abs(v) < 0.0005 ? 0.0 : v, 3); }

}  // namespace

bool TouchOffGrade::pass() const {
  return !asked || (saved && std::all_of(tools.begin(), tools.end(), [](const ToolTouchOff& t) { return t.within; }));
}

std::string touchOffFilePath(const std::string& programPath) {
  fs::path p(programPath);
  p.replace_extension(".offset.cfg");
  return p.string();
}

std::string touchOffSummary(const TouchOffGrade& g) {
  if (!g.asked) return {};
  if (!g.saved) return "not saved (" + g.file + (g.readError.empty() ? "" : ": " + g.readError) + ")";
  std::string out;
  for (const ToolTouchOff& t : g.tools) {
    if (!out.empty()) out += "; ";
    out += "T" + std::string(t.station < 10 ? "0" : "") + std::to_string(t.station) + " X" + touchOffMm(t.enteredX) +
           "/" + touchOffMm(t.trueX) + " Z" + touchOffMm(t.enteredZ) + "/" + touchOffMm(t.trueZ) +
           (t.within ? " in" : " out");
  }
  return out.empty() ? "no tool used" : out;
}

std::string touchOffText(const TouchOffGrade& g, double tolerance, Lang lang) {
  if (!g.asked) return {};
  auto say = [lang](const char* code, std::vector<std::string> args) {
    Diagnostic d;
    d.severity = Severity::Note;
    d.code = code;
    d.args = std::move(args);
    return formatMessage(d, lang);
  };
  if (!g.saved)
    return say(core::codes::kTouchOffNotSaved, {g.file, g.readError.empty() ? "" : " (" + g.readError + ")"});
  std::string out;
  for (const ToolTouchOff& t : g.tools) {
    if (!out.empty()) out += "; ";
    out += say(t.within ? core::codes::kTouchOffWithin : core::codes::kTouchOffOutside,
               {std::string(t.station < 10 ? "0" : "") + std::to_string(t.station), touchOffMm(t.enteredX),
                touchOffMm(t.enteredZ), touchOffMm(t.trueX), touchOffMm(t.trueZ), gcode::formatFixed(tolerance, 3)});
  }
  return out;
}

GradedProgram gradeProgram(const std::string& path, const JobInput& base) {
  GradedProgram g;
  try {
    JobInput input = base;
    input.path = path;
    input.file.reset();
    input.folder.reset();  // the student's own folder
    input.timelineNext = true;
    const std::shared_ptr<const Job> job = makeJob(std::move(input));
    const gcode::Program* program = job->program();
    if (program)
      g.subprogramFiles.assign(program->files.begin() + std::min<std::ptrdiff_t>(1, std::ssize(program->files)),
                               program->files.end());
    for (const Diagnostic& d : job->diagnostics())
      if (isError(d.severity) && g.errors++ == 0) g.firstError = place(d);
    if (job->unreadable() || !job->file() || !program || job->hasErrors() || !job->timeline()) {
      if (g.errors == 0) g.errors = 1, g.firstError = "unreadable";
      return g;
    }
    const machine::Timeline& timeline = *job->timeline();
    for (const machine::Move& m : timeline.moves)
      if (m.tool > 0 && std::find(g.stations.begin(), g.stations.end(), m.tool) == g.stations.end())
        g.stations.push_back(m.tool);
    g.cycleTime = timeline.cycleTime();
    if (timeline.alarm) {
      g.alarm = place(*timeline.alarm);
      return g;
    }
    CutOptions options;
    options.checkpointBudgetBytes = 0;  // one run forward
    // A guessed tool that touches gives way to another of its kind that fits (issue 26).
    const GuessFit fit =
        fitGuessedTools(timeline, job->file()->header, job->setup(), io::shippedToolLibrary(), options);
    const CutSimulator& sim = *fit.cut;
    if (sim.alarm()) {
      g.alarm = place(*sim.alarm());
      return g;
    }
    g.part = sim.stock();
    // The teacher's view of its cuts, with the tools the cut used (measured on the same run).
    const io::JobHeader& header = job->file()->header;
    CuttingDataOptions cutting =
        cuttingDataOptions(header.material, fit.setup.tools, fit.setup.machine, shippedMaterials());
    cutting.units = job->units();
    g.cuttingWarnings = measureCuts(timeline, CutSetup::from(header, fit.setup), cutting).warnings;
  } catch (const std::exception& ex) {  // one file must never end the batch
    g = GradedProgram{};
    g.errors = 1;
    g.firstError = std::string("internal error: ") + ex.what();
  }
  return g;
}

std::vector<ClassRow> gradeClass(const std::string& folder, const std::string& referencePath, const Stock& reference,
                                 const JobInput& base, double tolerance,
                                 const std::function<void(int, int, const std::string&)>& progress) {
  GradeAgainst against;
  against.referencePath = referencePath;
  against.reference = &reference;
  against.tolerance = tolerance;
  return gradeClass(folder, against, base, progress);
}

std::vector<ClassRow> gradeClass(const std::string& folder, const GradeAgainst& against, const JobInput& base,
                                 const std::function<void(int, int, const std::string&)>& progress) {
  const double tolerance = against.tolerance;
  std::error_code ec;
  // Only what lies in the folder is read; a link out of it, a pipe, a folder or a dangling
  // link is a failed row of its own, never opened (issue 42 item 1).
  std::vector<io::FolderEntry> files;
  for (io::FolderEntry& e : io::programFolderEntries(folder)) {
    std::error_code same;
    if (e.kind == io::FolderEntryKind::Program && !against.referencePath.empty() &&
        fs::equivalent(e.path, against.referencePath, same))
      continue;
    files.push_back(std::move(e));
  }
  std::vector<ClassRow> rows;
  const bool referenceAsks = classAsksTouchOff(against.referencePath);
  for (std::size_t i = 0; i < files.size(); ++i) {
    ClassRow row;
    row.file = files[i].name;
    row.path = files[i].path;
    if (progress) progress(static_cast<int>(i), static_cast<int>(files.size()), row.file);
    if (const std::optional<Diagnostic> refused = io::folderEntryRefusal(files[i])) {
      row.graded.errors = 1;
      row.graded.firstError = refusalText(*refused);
      row.graded.refusal = refused;
      rows.push_back(std::move(row));
      continue;
    }
    TouchOffGrade& touch = row.touchOff;
    touch.asked = referenceAsks || classAsksTouchOff(row.path);
    JobInput input = base;
    input.folderRun = true;
    if (touch.asked) {
      // The student's own offsets: the run uses them, as the lathe would.
      const std::string offsetsPath = touchOffFilePath(row.path);
      touch.file = fs::path(offsetsPath).filename().string();
      std::error_code lec;
      const bool present = fs::exists(fs::symlink_status(offsetsPath, lec));
      if (present && (!io::insideFolder(offsetsPath, folder) || !fs::is_regular_file(offsetsPath, lec))) {
        // Its messages quote its lines: a file from outside the folder is not read.
        touch.readError = "refused: not a file of the folder";
      } else if (present) {
        const io::ReadResult<io::OffsetTable> read = io::readOffsetTable(offsetsPath);
        const auto bad = std::find_if(read.diagnostics.begin(), read.diagnostics.end(),
                                      [](const Diagnostic& d) { return isError(d.severity); });
        if (read.value && bad == read.diagnostics.end()) {
          touch.saved = true;
          input.setup.offsets = *read.value;
        } else {
          touch.readError = bad != read.diagnostics.end() ? formatMessage(*bad, Lang::En) : "unreadable";
        }
      }
    }
    row.graded = gradeProgram(row.path, input);
    if (touch.saved)
      for (int s : row.graded.stations) {
        if (s < 1 || s > io::kOffsetCount) continue;
        ToolTouchOff t;
        t.station = s;
        t.enteredX = input.setup.offsets.at(s).x;
        t.enteredZ = input.setup.offsets.at(s).z;
        t.trueX = base.setup.offsets.at(s).x;
        t.trueZ = base.setup.offsets.at(s).z;
        t.within =
            std::abs(t.enteredX - t.trueX) <= tolerance + 1e-9 && std::abs(t.enteredZ - t.trueZ) <= tolerance + 1e-9;
        touch.tools.push_back(t);
      }
    if (row.graded.part) {
      row.pass = true;
      if (against.reference) {
        row.compared = true;
        row.deviation = compareParts(*row.graded.part, *against.reference, tolerance);
        row.pass = row.deviation.leftover <= tolerance + 1e-9 && row.deviation.gouge <= tolerance + 1e-9;
      }
    }
    if (against.hasDrawing) {
      // A program that did not run to its end has none of the drawing's dimensions.
      row.inspection = inspectPart(row.graded.part ? partFeatures(*row.graded.part) : PartFeatures{}, against.drawing);
      row.pass = row.pass && std::all_of(row.inspection.begin(), row.inspection.end(),
                                         [](const InspectedDimension& d) { return d.in(); });
    }
    row.pass = row.pass && touch.pass();
    row.graded.part.reset();  // thirty parts need not stay in memory
    rows.push_back(std::move(row));
  }
  // A subprogram file the others call (M98 P2000 reading O2000.nc) is part of their programs, not a student's.
  std::vector<fs::path> called;
  for (const ClassRow& r : rows)
    for (const std::string& f : r.graded.subprogramFiles) called.emplace_back(f);
  std::erase_if(rows, [&](const ClassRow& r) {
    return std::any_of(called.begin(), called.end(), [&](const fs::path& c) {
      std::error_code same;
      return fs::equivalent(c, r.path, same);
    });
  });
  return rows;
}

std::string cuttingWarningsText(const GradedProgram& g, Lang lang) {
  std::string out;
  for (const Diagnostic& w : g.cuttingWarnings)
    out +=
        (out.empty() ? "" : ", ") + w.code + (lang == Lang::Th ? " บรรทัด " : " line ") + std::to_string(w.range.line);
  return out;
}

std::string classCsv(const std::vector<ClassRow>& rows, bool drawing) {
  const bool touchOff = std::any_of(rows.begin(), rows.end(), [](const ClassRow& r) { return r.touchOff.asked; });
  std::string out =
      "file,result,errors,first_error,alarm,cycle_time_s,leftover_mm,leftover_z,gouge_mm,gouge_z,cutting_data";
  if (touchOff) out += ",touch_off";
  out += drawing ? ",feature,nominal_mm,tolerance,lower_mm,upper_mm,measured_mm,verdict\n" : "\n";
  for (const ClassRow& r : rows) {
    std::string line =
        csvField(r.file) + "," + (r.pass ? "pass" : "fail") + "," + std::to_string(r.graded.errors) + "," +
        csvField(r.graded.firstError) + "," + csvField(r.graded.alarm) + "," +
        (r.graded.errors == 0 ? gcode::formatFixed(r.graded.cycleTime, 1) : "") + "," +
        (r.compared
             ? gcode::formatFixed(r.deviation.leftover, 3) + "," + gcode::formatFixed(r.deviation.leftoverZ, 2) + "," +
                   gcode::formatFixed(r.deviation.gouge, 3) + "," + gcode::formatFixed(r.deviation.gougeZ, 2)
             : ",,,") +
        "," + csvField(cuttingWarningsText(r.graded, Lang::En));
    if (touchOff) line += "," + csvField(touchOffSummary(r.touchOff));
    if (!drawing) {
      out += line + "\n";
      continue;
    }
    for (const InspectedDimension& d : r.inspection)
      out += line + "," + csvField(dimensionLabel(d.drawn, Lang::En)) + "," + gcode::formatFixed(d.drawn.nominal, 3) +
             "," + csvField(toleranceLabel(d.drawn.tolerance)) + "," + gcode::formatFixed(d.lowerLimit(), 3) + "," +
             gcode::formatFixed(d.upperLimit(), 3) + "," + (d.measured ? gcode::formatFixed(*d.measured, 3) : "") +
             "," + verdictName(d.verdict, Lang::En) + "\n";
    if (r.inspection.empty()) out += line + ",,,,,,,\n";
  }
  return out;
}

}  // namespace klueng::core::job
