// The core's C API for the web page (issue 41): text in, JSON out. It calls the core
// entry points klueng-cli's check and simulate call (src/cli/check_command.cpp,
// simulate_command.cpp), in the same order, so the page and the CLI say the same of a
// program: the setup read from the shipped files (embedded under /klueng), the machine
// the program names unless one is chosen, job::makeJob, the run's timeline, the cut with
// guessed tools fitted (cut::fitGuessedTools) and the finished part's features.
//
// Every function returns a NUL-terminated UTF-8 JSON text owned here, valid until the next
// call. Languages: 0 = English, 1 = Thai. Units (the power-on units before any G20/G21):
// 0 = the machine's, 1 = mm, 2 = inch. machine: a loaded machine's id, "" = the one the
// program names at its head, else Fanuc 0i-TF (klueng-cli without --machine).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/guess_fit.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/help/explain.h"
#include "klueng/core/io/macro_variables.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/machine_files.h"
#include "klueng/core/machine/program_units.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/messages.h"
#include "klueng/core/units.h"

namespace {

using namespace klueng::core;

// The name the page's program goes by in messages (the CLI names its file).
constexpr const char* kProgramName = "program.nc";

struct Session {
  std::optional<machine::LoadedSetup> config;  // the shipped setup, read once
  // The last run: its job (owning the timeline), the cut that plays it and what it was asked.
  std::shared_ptr<const job::Job> run;
  std::unique_ptr<cut::CutSimulator> player;
  std::string runKey;
  std::vector<float> profile;    // per stock column: outer radius, inner radius (after klueng_advance)
  io::MacroVariables variables;  // #500-#999 of this page's runs (kept while the page is open)
  std::string out;
};

Session& session() {
  static Session s;
  return s;
}

const machine::LoadedSetup& shippedSetup() {
  Session& s = session();
  // As klueng-cli's loadConfig: findConfigDir's folder, the bitmaps decoded.
  if (!s.config) s.config = machine::loadMachineSetup({}, true);
  return *s.config;
}

Lang langOf(int lang) { return lang == 1 ? Lang::Th : Lang::En; }

std::optional<gcode::InputUnits> unitsOf(int units) {
  if (units == 1) return gcode::InputUnits::Millimetre;
  if (units == 2) return gcode::InputUnits::Inch;
  return std::nullopt;
}

// ---------------------------------------------------------------- JSON

std::string esc(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out += '"';
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (u < 0x20 || u == 0x7F) {
      out += fmt::format("\\u{:04x}", u);
    } else {
      out += c;
    }
  }
  out += '"';
  return out;
}

std::string num(double v) { return std::isfinite(v) ? fmt::format("{}", v + 0.0) : std::string("null"); }

std::string diagnosticJson(const Diagnostic& d, const std::string& file, Lang lang) {
  return fmt::format(R"({{"code":{},"severity":{},"line":{},"column":{},"length":{},"file":{},"message":{}}})",
                     esc(d.code), esc(severityName(d.severity, Lang::En)), d.range.line, d.range.column, d.range.length,
                     esc(file), esc(formatMessage(d, lang)));
}

// A located text in the CLI's form: "line 12: note I401: ...".
std::string noteText(const Diagnostic& d, Lang lang) {
  return fmt::format("{} {}: {}", severityName(d.severity, lang), d.code, formatMessage(d, lang));
}

const char* done(std::string text) {
  Session& s = session();
  s.out = std::move(text);
  return s.out.c_str();
}

// ---------------------------------------------------------------- one request

struct Request {
  std::optional<job::JobInput> input;
  gcode::Dialect dialect = gcode::Dialect::Fanuc;
  std::vector<Diagnostic> programWarnings;        // the machine a program names and does not exist (F205)
  std::vector<machine::SetupDiagnostic> refused;  // a machine chosen that is not loaded
};

// What klueng-cli check/simulate do before makeJob (chooseMachine, programMachine, jobRequest).
Request makeRequest(const char* text, const char* machineId, int units) {
  Request r;
  machine::LoadedSetup config = shippedSetup();
  const std::string chosen = machineId ? machineId : "";
  if (!chosen.empty()) {
    const std::optional<gcode::Dialect> d = machine::resolveMachine(chosen, r.refused);
    if (!d) return r;
    r.dialect = *d;
  }
  io::ReadResult<io::ProgramFile> read = io::parseProgramFile(text ? text : "", {}, kProgramName);
  if (chosen.empty() && read.value)
    r.dialect = machine::machineOfProgram(*read.value, r.programWarnings).value_or(r.dialect);
  config.setup.machine = machine::withMachineKeys(config.setup.machine, gcode::machineProfile(r.dialect));
  job::JobInput input;
  input.path = kProgramName;
  input.folder = std::string();  // no folder of subprogram files beside a page's text
  input.setup = config.setup;
  input.run.dialect = r.dialect;
  input.run.powerOnUnits = unitsOf(units);
  const int profileLimit = gcode::machineProfile(r.dialect).maxToolStation;
  input.stations = profileLimit > 0 ? std::min(profileLimit, config.setup.tools.stations) : config.setup.tools.stations;
  input.toolTable = !config.unreadable;
  if (read.value) input.file = std::move(read.value);
  input.readDiagnostics = std::move(read.diagnostics);
  r.input = std::move(input);
  return r;
}

std::string diagnosticsJson(const Request& r, const job::Job* job, Lang lang, int* errors = nullptr) {
  std::string out = "[";
  int errorCount = 0;
  const auto add = [&](const Diagnostic& d, const std::string& file) {
    if (isError(d.severity)) ++errorCount;
    out += (out.size() > 1 ? "," : "") + diagnosticJson(d, file, lang);
  };
  for (const machine::SetupDiagnostic& d : r.refused) add(d.diagnostic, d.file);
  for (const Diagnostic& d : r.programWarnings) add(d, kProgramName);
  if (job)
    for (const Diagnostic& d : job->diagnostics()) add(d, job->fileOf(d));
  if (errors) *errors = errorCount;
  return out + "]";
}

std::string notesJson(const job::Job& job, Lang lang) {
  std::string out = "[";
  for (const std::vector<Diagnostic>& list : {job.toolNotes(), job.stockNotes()})
    for (const Diagnostic& n : list) out += (out.size() > 1 ? "," : "") + esc(noteText(n, lang));
  return out + "]";
}

// The first snapshot of file line `line` in the main program.
const machine::StateSnapshot* snapshotOfLine(const machine::Timeline& t, int line) {
  for (const machine::StateSnapshot& s : t.snapshots)
    if (s.file == 0 && s.line == line) return &s;
  return nullptr;
}

std::string runKeyOf(const char* text, const char* machineId, int units) {
  return fmt::format("{}\x1f{}\x1f{}", machineId ? machineId : "", units, text ? text : "");
}

const char* kindName(machine::MoveKind k) {
  switch (k) {
    case machine::MoveKind::Rapid: return "rapid";
    case machine::MoveKind::Line: return "line";
    case machine::MoveKind::Arc: return "arc";
    case machine::MoveKind::Thread: return "thread";
    case machine::MoveKind::Dwell: return "dwell";
  }
  return "line";
}

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned v =
        bytes[i] << 16 | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) | (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += table[v >> 18 & 63];
    out += table[v >> 12 & 63];
    out += i + 1 < bytes.size() ? table[v >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? table[v & 63] : '=';
  }
  return out;
}

}  // namespace

extern "C" {

// The machines (id and name in `lang`), the samples and what reading the shipped setup said.
const char* klueng_info(int lang) {
  const Lang l = langOf(lang);
  const machine::LoadedSetup& config = shippedSetup();
  std::string machines;
  for (const gcode::MachineProfile* p : gcode::machineProfiles())
    machines += fmt::format("{}{{\"id\":{},\"name\":{}}}", machines.empty() ? "" : ",", esc(p->id),
                            esc(l == Lang::Th ? p->nameTh : p->nameEn));
  std::vector<std::string> samples;
  namespace fs = std::filesystem;
  std::error_code ec;
  const std::string dir = io::samplesDir();
  if (!dir.empty())
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
      if (e.is_regular_file() && io::isProgramFileName(e.path().filename().string()))
        samples.push_back(e.path().filename().string());
  std::sort(samples.begin(), samples.end());
  std::string sampleList;
  for (const std::string& s : samples) sampleList += (sampleList.empty() ? "" : ",") + esc(s);
  std::string setup;
  for (const machine::SetupDiagnostic& d : config.diagnostics)
    setup += (setup.empty() ? "" : ",") + diagnosticJson(d.diagnostic, d.file, l);
  return done(fmt::format(R"({{"machines":[{}],"samples":[{}],"setup":[{}]}})", machines, sampleList, setup));
}

// A shipped sample's text ("" when there is none of that name).
const char* klueng_sample(const char* name) {
  const std::string n = name ? name : "";
  if (n.empty() || n.find('/') != std::string::npos) return done("");
  std::ifstream in(std::filesystem::path(io::samplesDir()) / n, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return done(text.str());
}

// The check the editor makes while typing: every diagnostic, the tool and stock notes.
const char* klueng_check(const char* text, const char* machineId, int units, int lang) {
  const Lang l = langOf(lang);
  Request r = makeRequest(text, machineId, units);
  if (!r.input) return done(fmt::format(R"({{"diagnostics":{},"notes":[]}})", diagnosticsJson(r, nullptr, l)));
  r.input->modalRules = true;  // the editor's check also follows the modal state (W104-W106)
  const std::shared_ptr<const job::Job> job = job::makeJob(std::move(*r.input));
  return done(fmt::format(R"({{"diagnostics":{},"notes":{},"machine":{},"units":{}}})",
                          diagnosticsJson(r, job.get(), l), notesJson(*job, l),
                          esc(gcode::machineProfile(r.dialect).id),
                          esc(job->units() == DisplayUnits::Inch ? "inch" : "mm")));
}

// What the block on file line `line` does: with the state it left in the last run of this
// very text, else from its words alone.
const char* klueng_explain(const char* text, int line, const char* machineId, int units, int lang) {
  const std::string_view all = text ? text : "";
  std::size_t start = 0;
  for (int k = 1; k < line && start != std::string_view::npos; ++k) {
    start = all.find('\n', start);
    if (start != std::string_view::npos) ++start;
  }
  if (line < 1 || start == std::string_view::npos) return done("{\"text\":\"\"}");
  const std::size_t end = std::min(all.find('\n', start), all.size());
  const std::string_view lineText = all.substr(start, end - start);
  Session& s = session();
  const machine::StateSnapshot* after = nullptr;
  gcode::Dialect dialect = gcode::Dialect::Fanuc;
  bool increments = false;
  if (s.run && s.runKey == runKeyOf(text, machineId, units) && s.run->timeline()) {
    after = snapshotOfLine(*s.run->timeline(), line);
    dialect = s.run->input().run.dialect;
    increments = !s.run->setup().machine.calculatorInput;
  } else {
    const Request r = makeRequest(text, machineId, units);
    if (r.input) {
      dialect = r.input->run.dialect;
      increments = !r.input->setup.machine.calculatorInput;
    }
  }
  // The program's own lines: a 6-line header shifts them (io::ProgramFile::gcodeFirstLine).
  return done(fmt::format(R"({{"text":{}}})",
                          esc(machine::explainLineText(lineText, line, after, dialect, langOf(lang), increments))));
}

// Runs the program as klueng-cli simulate does and keeps the run for klueng_advance: the
// diagnostics (errors: no run), the timeline's moves and blocks, the cycle time, the alarm,
// the stock and chuck, and the finished part's features cut to the end.
const char* klueng_run(const char* text, const char* machineId, int units, int lang) {
  const Lang l = langOf(lang);
  Session& s = session();
  s.run.reset();
  s.player.reset();
  s.runKey.clear();
  Request r = makeRequest(text, machineId, units);
  if (!r.input) return done(fmt::format(R"({{"ok":false,"diagnostics":{}}})", diagnosticsJson(r, nullptr, l)));
  r.input->run.persistentVariables = &s.variables;
  r.input->run.optionalStop = false;
  r.input->timelineNext = true;
  const std::shared_ptr<const job::Job> job = job::makeJob(std::move(*r.input));
  int errors = 0;
  const std::string diagnostics = diagnosticsJson(r, job.get(), l, &errors);
  if (!job->file() || !job->program() || job->hasErrors() || !job->timeline() || errors > 0)
    return done(fmt::format(R"({{"ok":false,"diagnostics":{},"notes":{}}})", diagnostics, notesJson(*job, l)));
  const machine::Timeline& timeline = *job->timeline();
  const io::JobHeader& header = job->file()->header;
  // As simulate's cut: a guessed tool that touches gives way to one of its kind that fits.
  cut::CutOptions once;
  once.checkpointBudgetBytes = 0;
  const cut::GuessFit fit = cut::fitGuessedTools(timeline, header, job->setup(), io::shippedToolLibrary(), once);
  const cut::CutSimulator& finished = *fit.cut;
  const UnitFormat shown(
      machine::programUnits(timeline, gcode::powerOnUnitsOf(job->input().run.dialect, job->input().run.powerOnUnits)));
  std::string features;
  const cut::PartFeatures part = cut::partFeatures(finished.stock());
  for (const auto* list : {&part.outside, &part.inside})
    for (const cut::PartFeature& f : *list)
      features +=
          fmt::format(R"({}{{"kind":{},"side":{},"diameter":{},"zLeft":{},"zRight":{},"label":{},"text":{}}})",
                      features.empty() ? "" : ",", esc(cut::featureKindName(f.kind, Lang::En)),
                      esc(f.side == cut::FeatureSide::Outside ? "outside" : "inside"), num(f.diameter), num(f.zLeft),
                      num(f.zRight), esc(cut::featureLabel(f, l, shown)), esc(cut::describeFeature(f, l, shown)));
  std::string moves;
  moves.reserve(timeline.moves.size() * 80);
  for (const machine::Move& m : timeline.moves) {
    moves += fmt::format("{}[{},{},{},{},{},{},{},{},{},{}", moves.empty() ? "" : ",", esc(kindName(m.kind)), m.line,
                         num(m.tStart), num(m.tEnd), num(m.path.start.x()), num(m.path.start.y()), num(m.path.end.x()),
                         num(m.path.end.y()), m.tool, m.file);
    if (m.path.isArc())
      moves += fmt::format(",{},{},{}", num(m.path.centre.x()), num(m.path.centre.y()), m.path.ccw ? 1 : 0);
    moves += "]";
  }
  std::string blocks;
  for (const machine::StateSnapshot& b : timeline.snapshots)
    blocks += fmt::format("{}[{},{},{},{}]", blocks.empty() ? "" : ",", b.line, num(b.time), b.moveEnd, b.file);
  const std::optional<Diagnostic> alarm = finished.alarm() ? finished.alarm() : timeline.alarm;
  std::string guessNotes;
  for (const Diagnostic& n : fit.notes) guessNotes += (guessNotes.empty() ? "" : ",") + esc(noteText(n, l));
  std::string warnings;
  for (const Diagnostic& w : finished.warnings())
    warnings += (warnings.empty() ? "" : ",") + diagnosticJson(w, job->fileOf(w), l);
  const cut::Stock& stock = finished.stock();
  const cut::Chuck& chuck = finished.chuck();
  const std::string json = fmt::format(
      R"({{"ok":true,"diagnostics":{},"notes":{},"guessNotes":[{}],"warnings":[{}],"cycleTime":{},"endTime":{},)"
      R"("alarm":{},"units":{},"features":[{}],"moves":[{}],"blocks":[{}],)"
      R"("stock":{{"diameter":{},"length":{},"bore":{},"columns":{},"resolution":{}}},)"
      R"("chuck":{{"grip":{},"jawHeight":{},"bodyWidth":{},"spindleBoreRadius":{}}}}})",
      diagnostics, notesJson(*job, l), guessNotes, warnings, num(timeline.cycleTime()), num(finished.endTime()),
      alarm ? diagnosticJson(*alarm, job->fileOf(*alarm), l) : std::string("null"), esc(shown.inch() ? "inch" : "mm"),
      features, moves, blocks, num(stock.diameter()), num(stock.length()), num(stock.bore()), stock.columnCount(),
      num(stock.resolution()), num(chuck.grip), num(chuck.jawHeight), num(chuck.bodyWidth),
      num(chuck.spindleBoreRadius));
  // The player: the same cut with the tools the run used, from the bar, for the animation.
  s.run = job;
  s.player = std::make_unique<cut::CutSimulator>(timeline, cut::CutSetup::from(header, fit.setup));
  s.runKey = runKeyOf(text, machineId, units);
  return done(json);
}

// Cuts the kept run to time t (going back restores a checkpoint) and says where the tool
// is; the stock's profile is then at klueng_profile() (klueng_profile_size() floats).
const char* klueng_advance(double t, int lang) {
  Session& s = session();
  if (!s.player || !s.run || !s.run->timeline()) return done("{\"ok\":false}");
  cut::CutSimulator& sim = *s.player;
  const machine::Timeline& timeline = *s.run->timeline();
  sim.advanceTo(t);
  const cut::Stock& stock = sim.stock();
  s.profile.resize(static_cast<std::size_t>(stock.columnCount()) * 2);
  for (int i = 0; i < stock.columnCount(); ++i) {
    s.profile[2 * static_cast<std::size_t>(i)] = static_cast<float>(stock.outerRadius(i));
    s.profile[2 * static_cast<std::size_t>(i) + 1] = static_cast<float>(stock.innerRadius(i));
  }
  const Vec2 p = sim.toolPosition();
  const int index = sim.currentMove();
  const machine::Move* m = index >= 0 ? &timeline.moves[static_cast<std::size_t>(index)] : nullptr;
  const cut::ToolShape* tool = sim.currentTool();
  const std::optional<Diagnostic> alarm = sim.finished() ? sim.stoppingAlarm() : std::nullopt;
  const Lang l = langOf(lang);
  return done(fmt::format(
      R"({{"ok":true,"time":{},"finished":{},"move":{},"line":{},"z":{},"x":{},"tool":{},"offset":{},"feed":{},)"
      R"("rpm":{},"kind":{},"toolKey":{},"noseRadius":{},"noseZ":{},"noseX":{},"alarm":{}}})",
      num(sim.time()), sim.finished() ? "true" : "false", index, m ? m->line : 0, num(p.x()), num(p.y()),
      m ? m->tool : 0, m ? m->offset : 0, num(m ? m->feed : 0.0), num(m ? m->rpm : 0.0),
      esc(m ? kindName(m->kind) : ""),
      esc(tool ? fmt::format("{}|{}|{}", tool->fileName, tool->noseRadius, tool->tip) : std::string()),
      num(tool ? tool->noseRadius : 0.0), num(tool ? tool->noseCentre.x() : 0.0),
      num(tool ? tool->noseCentre.y() : 0.0), alarm ? diagnosticJson(*alarm, s.run->fileOf(*alarm), l) : "null"));
}

const float* klueng_profile() { return session().profile.data(); }
int klueng_profile_size() { return static_cast<int>(session().profile.size()); }

// The current tool's bitmap for drawing: RGB bytes (base64), its resolution and the
// controlled point in pixels, the exact nose.
const char* klueng_tool_image() {
  Session& s = session();
  const cut::ToolShape* tool = s.player ? s.player->currentTool() : nullptr;
  if (!tool) return done("{\"ok\":false}");
  std::vector<unsigned char> rgb;
  rgb.reserve(tool->image.pixels.size() * 3);
  for (const std::uint32_t p : tool->image.pixels) {
    rgb.push_back(static_cast<unsigned char>(p >> 16));
    rgb.push_back(static_cast<unsigned char>(p >> 8));
    rgb.push_back(static_cast<unsigned char>(p));
  }
  return done(fmt::format(
      R"({{"ok":true,"width":{},"height":{},"controlX":{},"controlY":{},"pixelsPerMm":{},"noseRadius":{},)"
      R"("noseZ":{},"noseX":{},"rgb":"{}"}})",
      tool->image.width, tool->image.height, num(tool->controlPixelX), num(tool->controlPixelY), num(tool->pixelsPerMm),
      num(tool->noseRadius), num(tool->noseCentre.x()), num(tool->noseCentre.y()), base64(rgb)));
}

}  // extern "C"
