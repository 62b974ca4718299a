// A guess never stops a run the real tool would not (issue 26 item 4; cut/guess_fit.h):
// plain programs written the way shops write them, read as klueng-cli simulate reads them.
#include "klueng/core/cut/guess_fit.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "klueng/core/cut/finished_part.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/messages.h"

namespace klueng::core::cut {
namespace {

namespace fs = std::filesystem;

const machine::LoadedSetup& shipped() {
  static const machine::LoadedSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR);
  return setup;
}

// The 1-based line of the first line of `text` that starts with `start`.
int lineOf(const std::string& text, const std::string& start) {
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.rfind(start, 0) == 0) return n;
  return 0;
}

// One plain program, loaded, interpreted and cut with its guessed tools fitted.
struct Run {
  std::shared_ptr<const job::Job> job;
  machine::Timeline timeline;
  GuessFit fit;
};

std::unique_ptr<Run> run(const std::string& name, const std::string& text, gcode::Dialect dialect,
                         const io::JobHeader& stock, const std::vector<machine::StationOverride>& overrides = {}) {
  const fs::path folder = fs::temp_directory_path() / ("klueng-guessfit-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const fs::path path = folder / name;
  std::ofstream(path, std::ios::binary) << text;
  job::JobInput request;
  request.path = path.string();
  request.setup = shipped().setup;
  request.run.dialect = dialect;
  request.stations = shipped().setup.tools.stations;
  request.stock = stock;
  request.overrides = overrides;
  auto r = std::make_unique<Run>();
  r->job = job::makeJob(request);
  fs::remove_all(folder);
  EXPECT_TRUE(r->job->program() && r->job->file() && !r->job->hasErrors());
  if (!r->job->program() || !r->job->file()) return r;
  r->timeline = *r->job->timeline();
  EXPECT_FALSE(r->timeline.alarm.has_value());
  CutOptions options;
  options.checkpointBudgetBytes = 0;
  r->fit = fitGuessedTools(r->timeline, r->job->file()->header, r->job->setup(), io::shippedToolLibrary(), options);
  return r;
}

io::JobHeader bar(double diameter, double length, io::LengthUnit unit = io::LengthUnit::Millimetre) {
  io::JobHeader h;
  h.diameter = diameter;
  h.diameterUnit = unit;
  h.length = length;
  h.lengthUnit = unit;
  h.stockSource = io::StockSource::CommandLine;
  return h;
}

double diameterAt(const Stock& stock, double z) { return 2.0 * stock.outerRadius(stock.columnAt(z)); }

// Fanuc, mm: a spool turned to Ø48, then a 3 mm groove 10 mm deep with G75. The
// comment makes T02 the library's grooving blade, whose gusset sits 8 mm above its
// tip; the parting blade (a long blade of the same width) reaches the bottom.
const std::string kSpool =
    "%\n"
    "O1234 (SPOOL 48 - GROOVE 3 X 10)\n"
    "(==================================)\n"
    "(  OP10 : ROUGH + FINISH OD 48     )\n"
    "(  OP20 : GROOVE 3MM TO DIA 28     )\n"
    "(==================================)\n"
    "G21 G40 G99\n"
    "G28 U0. W0.\n"
    "\n"
    "T0101 (OD ROUGH CNMG 80)\n"
    "G96 S180 M03\n"
    "G50 S2500\n"
    "G00 X52. Z2. M08\n"
    "G71 U1.5 R0.5\n"
    "G71 P10 Q20 U0.4 W0.1 F0.25\n"
    "N10 G00 X40.\n"
    "G01 Z0. F0.15\n"
    "X48. Z-4.\n"
    "Z-60.\n"
    "N20 X52.\n"
    "G70 P10 Q20 F0.1\n"
    "G28 U0. W0. M09\n"
    "\n"
    "(----- OP20 GROOVE -----)\n"
    "T0202 (GROOVING 3MM)\n"
    "G97 S600 M03\n"
    "G00 X52. Z-30. M08\n"
    "G75 R0.5\n"
    "G75 X28. Z-30. P2000 F0.06\n"
    "G00 X52.\n"
    "G28 U0. W0. M09\n"
    "M30\n"
    "%\n";

TEST(GuessFit, AGuessedBladeWhoseHolderTouchesGivesWayToALongerBladeOfTheSameWidth) {
  const auto r = run("spool.nc", kSpool, gcode::Dialect::Fanuc, bar(50, 80));
  ASSERT_TRUE(r->fit.cut);
  const io::ToolTable& first = r->job->setup().tools;
  ASSERT_EQ(first.libraryId(2), "grooving-3mm");
  ASSERT_TRUE(first.isGuess(2));
  const int grooveLine = lineOf(kSpool, "G75 X28.");

  // The first guess alone touches: the holder of the grooving blade, on the G75 block.
  CutOptions options;
  options.checkpointBudgetBytes = 0;
  CutSimulator alone(r->timeline, CutSetup::from(r->job->file()->header, r->job->setup()), options);
  alone.runToEnd();
  ASSERT_EQ(alone.warnings().size(), 1u);
  EXPECT_EQ(alone.warnings()[0].code, "W324");
  EXPECT_EQ(alone.warnings()[0].range.line, grooveLine);
  // 10 mm deep against a gusset 8 mm up: about 2 mm short.
  EXPECT_NEAR(std::stod(alone.warnings()[0].args.at(4)), 2.0, 0.3);

  // Fitted: the parting blade, a note on the G75 block, and a clean run.
  EXPECT_EQ(r->fit.setup.tools.libraryId(2), "parting-3mm");
  EXPECT_TRUE(r->fit.setup.tools.isGuess(2));                      // still Klueng's guess
  EXPECT_EQ(r->fit.setup.tools.libraryId(1), first.libraryId(1));  // the turning tool never touched
  ASSERT_EQ(r->fit.notes.size(), 1u);
  const Diagnostic& note = r->fit.notes[0];
  EXPECT_EQ(note.code, "I413");
  EXPECT_EQ(note.severity, Severity::Note);
  EXPECT_EQ(note.range.line, grooveLine);
  EXPECT_EQ(note.args, (std::vector<std::string>{"02", "parting-3mm", "grooving-3mm", std::to_string(grooveLine)}));
  EXPECT_EQ(formatMessage(note, Lang::En),
            "T02: parting-3mm instead of grooving-3mm: the first guess touched the stock at line " +
                std::to_string(grooveLine));
  EXPECT_NE(formatMessage(note, Lang::Th).find("ใช้ parting-3mm แทน grooving-3mm"), std::string::npos);
  EXPECT_EQ(r->fit.runs, 2);
  EXPECT_FALSE(r->fit.cut->alarm().has_value());
  EXPECT_TRUE(r->fit.cut->warnings().empty());

  // The part: Ø48 turned, the groove Z-30..Z-27 down to Ø28.
  const Stock& s = r->fit.cut->stock();
  EXPECT_NEAR(diameterAt(s, -15.0), 48.0, 0.01);
  EXPECT_NEAR(diameterAt(s, -45.0), 48.0, 0.01);
  EXPECT_NEAR(diameterAt(s, -28.5), 28.0, 0.01);
  EXPECT_NEAR(diameterAt(s, -31.0), 48.0, 0.01);
}

// Tools the user chose are never replaced: the same groove with T02 set for the job is a crash.
TEST(GuessFit, AToolTheUserChoseThatTouchesIsStillTheAlarm) {
  const auto r = run("spool.nc", kSpool, gcode::Dialect::Fanuc, bar(50, 80), {{2, "grooving-3mm"}});
  ASSERT_TRUE(r->fit.cut);
  EXPECT_FALSE(r->fit.setup.tools.isGuess(2));
  EXPECT_EQ(r->fit.setup.tools.libraryId(2), "grooving-3mm");
  EXPECT_TRUE(r->fit.notes.empty());
  EXPECT_EQ(r->fit.runs, 1);
  ASSERT_TRUE(r->fit.cut->alarm().has_value());
  EXPECT_EQ(r->fit.cut->alarm()->code, "A303");
  EXPECT_EQ(r->fit.cut->alarm()->range.line, lineOf(kSpool, "G75 X28."));
}

// Haas, inch: a pulley blank grooved 1.45" deep (36.8 mm), deeper than any blade of the
// library reaches. Nothing fits: the first guess stays, the run finishes with W324.
const std::string kPulley =
    "%\n"
    "O00210 (PULLEY BLANK - DEEP GROOVE)\n"
    "(T1 = OD TURN CNMG, T2 = GROOVE .118 WIDE)\n"
    "G20\n"
    "G28\n"
    "T101 (OD TURN)\n"
    "G97 S600 M03\n"
    "G00 X4.1 Z.1 M08\n"
    "G01 X3.9 F.01\n"
    "Z-3. F.008\n"
    "X4.1\n"
    "G00 Z.1\n"
    "G28\n"
    "\n"
    "T202 (GROOVE .118 WIDE)\n"
    "G97 S300 M03\n"
    "G00 X4.1 Z-1.5\n"
    "G01 X1. F.002\n"
    "G00 X4.1\n"
    "G28\n"
    "M30\n"
    "%\n";

TEST(GuessFit, WhenNoBladeReachesTheRunFinishesWithTheWarningAndWhatTheToolNeeds) {
  const auto r = run("pulley.nc", kPulley, gcode::Dialect::Haas, bar(4, 4, io::LengthUnit::Inch));
  ASSERT_TRUE(r->fit.cut);
  ASSERT_TRUE(r->job->setup().tools.isGuess(2));
  const std::string guess = r->job->setup().tools.libraryId(2);
  ASSERT_TRUE(guess == "grooving-3mm" || guess == "parting-3mm") << guess;
  EXPECT_EQ(r->fit.setup.tools.libraryId(2), guess);  // the first guess stays
  EXPECT_TRUE(r->fit.notes.empty());
  EXPECT_EQ(r->fit.runs, 2);  // the other blade was tried
  EXPECT_FALSE(r->fit.cut->alarm().has_value());
  ASSERT_EQ(r->fit.cut->warnings().size(), 1u);
  const Diagnostic& w = r->fit.cut->warnings()[0];
  EXPECT_EQ(w.code, "W324");
  EXPECT_EQ(w.range.line, lineOf(kPulley, "G01 X1."));
  EXPECT_EQ(w.args.at(0), "02");
  EXPECT_EQ(w.args.at(1), guess);
  EXPECT_GT(std::stod(w.args.at(4)), 1.0);
  EXPECT_NE(formatMessage(w, Lang::En).find("mm more reach here"), std::string::npos);
  // The run went on to the bottom of the groove: Ø1" at Z-1.5".."-1.5+3 mm, Ø3.9" beside it.
  const Stock& s = r->fit.cut->stock();
  EXPECT_NEAR(diameterAt(s, -1.5 * 25.4 + 1.5), 25.4, 0.01);
  EXPECT_NEAR(diameterAt(s, -1.0 * 25.4), 3.9 * 25.4, 0.01);
}

// The candidates: the same kind and width, the nose of the rows the station uses; a
// slimmer bar before a thicker one.
TEST(GuessFit, CandidatesKeepTheKindTheWidthAndTheNose) {
  const io::ToolLibrary& library = io::shippedToolLibrary();
  machine::MachineSetup setup = shipped().setup;
  machine::Timeline tl;
  machine::Move m;
  m.tool = 4;
  m.offset = 4;
  tl.moves.push_back(m);
  const io::LibraryTool* bar16 = library.find("boring-bar-16");
  ASSERT_TRUE(bar16);
  setup.tools.setLibraryTool(4, bar16->id, library.bitmapPath(*bar16), bar16->pixelsPerMm);
  setup.offsets.at(4) = io::Offset{0, 0, bar16->noseRadius, bar16->tip};
  auto ids = [&] {
    std::vector<std::string> out;
    for (const io::LibraryTool* t : guessCandidates(tl, setup, 4, library)) out.push_back(t->id);
    return out;
  };
  EXPECT_EQ(ids(), (std::vector<std::string>{"boring-bar-10"}));
  // A row with another nose: the recorded path would not be the new tool's.
  setup.offsets.at(4).r = 0.8;
  EXPECT_TRUE(ids().empty());
  // A drill: nothing else of its size.
  const io::LibraryTool* drill = library.find("drill-22mm");
  ASSERT_TRUE(drill);
  setup.tools.setLibraryTool(4, drill->id, library.bitmapPath(*drill), drill->pixelsPerMm);
  setup.offsets.at(4) = io::Offset{0, 0, drill->noseRadius, drill->tip};
  EXPECT_TRUE(ids().empty());
}

}  // namespace
}  // namespace klueng::core::cut
