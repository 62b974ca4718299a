// One job (job/job.h, issue 30 item 1): what klueng-cli, the editor's check, a
// run, the reports and the design loop see; read and parsed once, the timeline
// and the cut computed on first ask.
#include "klueng/core/job/job.h"
#include "klueng/core/messages.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/machine/setup_files.h"
#include "../machine/test_support.h"

#include <future>

namespace klueng::core::job {
namespace {

using machine::LoadedSetup;
using machine::loadMachineSetup;
using machine::MachineSetup;

namespace fs = std::filesystem;

const LoadedSetup& shipped() {
  static const LoadedSetup setup = loadMachineSetup(KLUENG_SOURCE_DIR);
  return setup;
}

JobInput request(const std::string& path, gcode::Dialect dialect = gcode::Dialect::Fanuc) {
  JobInput r;
  r.path = path;
  r.setup = shipped().setup;
  r.run.dialect = dialect;
  r.stations = shipped().setup.tools.stations;
  return r;
}

TEST(MakeJob, HeaderAndGrammarDiagnosticsComeSortedByLine) {
  const auto made = makeJob(request(KLUENG_SAMPLES_DIR "/04-grammar-errors.txt", gcode::Dialect::Classic));
  const Job& job = *made;
  ASSERT_TRUE(job.file() && job.program());
  EXPECT_FALSE(job.unreadable());
  ASSERT_FALSE(job.diagnostics().empty());
  EXPECT_EQ(job.diagnostics().front().range.line, 11);
  EXPECT_EQ(job.diagnostics().back().range.line, 30);
  for (std::size_t i = 1; i < job.diagnostics().size(); ++i)
    EXPECT_LE(job.diagnostics()[i - 1].range.line, job.diagnostics()[i].range.line);
  EXPECT_TRUE(job.stockNotes().empty());  // the header's stock: nothing to say
  EXPECT_EQ(job.file()->header.stockSource, io::StockSource::Header);
}

TEST(MakeJob, AFileThatCannotBeReadIsUnreadable) {
  const auto made = makeJob(request("/no/such/file.nc"));
  const Job& job = *made;
  EXPECT_TRUE(job.unreadable());
  EXPECT_FALSE(job.file());
  EXPECT_TRUE(job.hasErrors());
}

TEST(MakeJob, APlainProgramWithASubprogramFileIsParsedOnceEach) {
  const machine::testing::ScratchFolder folder{"jobfile"};
  // A plain file as a shop writes it: no header, the stock only in the approach.
  const std::string main = folder.write("MAIN.nc",
                                        "O0100\n"
                                        "G21 G40 G99\n"
                                        "T0909 (BORING BAR)\n"
                                        "G97 S800 M03\n"
                                        "G00 X42. Z2.\n"
                                        "M98 P1000\n"
                                        "G00 X150. Z150.\n"
                                        "M30\n");
  folder.write("O1000.nc",
               "O1000 (FACE)\n"
               "G01 Z0. F0.2\n"
               "X-1.6\n"
               "G00 Z2.\n"
               "M99\n");
  const std::size_t before = gcode::parseCount();
  const auto made = makeJob(request(main));
  const Job& job = *made;
  EXPECT_EQ(gcode::parseCount() - before, 2u);  // MAIN.nc and O1000.nc, nothing twice
  ASSERT_TRUE(job.program());
  EXPECT_EQ(job.program()->files.size(), 2u);
  for (const Diagnostic& d : job.diagnostics())
    ADD_FAILURE() << d.code << " line " << d.range.line << " file " << d.range.file;
  // The stock comes from the approach X42., and a note says so: the feed there only reaches the
  // face (G01 Z0.), so it is above the bar, the largest standard bar not above it (issue 38).
  EXPECT_EQ(job.file()->header.stockSource, io::StockSource::Inferred);
  EXPECT_EQ(job.file()->header.diameter, 40.0);
  ASSERT_FALSE(job.stockNotes().empty());
  // A boring bar for the empty station 9, from its comment.
  ASSERT_FALSE(job.toolNotes().empty());
  EXPECT_NE(job.setup().tools.libraryId(9).find("bor"), std::string::npos) << job.setup().tools.libraryId(9);
}

// Issue 29 item 10: the called program's file name is a folder beside the program:
// the call says so (E416), not "neither in this file nor in its folder" (E404); a
// real file under another of its names is still taken.
TEST(MakeJob, ASubprogramFileThatIsAFolderIsSaidToBeOne) {
  const machine::testing::ScratchFolder folder{"jobfile"};
  const std::string main = folder.write("MAIN.nc", "O0100\nG21\nM98 P1000\nM98 P2000\nM30\n");
  fs::create_directory(fs::path(main).parent_path() / "O1000.nc");
  fs::create_directory(fs::path(main).parent_path() / "O2000.nc");
  folder.write("2000.nc", "O2000\nG00 X10.\nM99\n");
  const auto made = makeJob(request(main));
  const Job& job = *made;
  ASSERT_TRUE(job.program());
  std::vector<const Diagnostic*> errors;
  for (const Diagnostic& d : job.diagnostics())
    if (isError(d.severity)) errors.push_back(&d);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0]->code, "E416");
  EXPECT_EQ(errors[0]->range.line, 3);
  EXPECT_EQ(errors[0]->range.column, 5);
  EXPECT_EQ(
      formatMessage(*errors[0], Lang::En),
      "M98 P1000: program O1000 is not in this file, and 'O1000.nc' in its folder is a folder, not a program file");
  EXPECT_EQ(formatMessage(*errors[0], Lang::Th),
            "M98 P1000: ไม่มีโปรแกรม O1000 ในไฟล์นี้ และ 'O1000.nc' ในโฟลเดอร์เดียวกันเป็นโฟลเดอร์ ไม่ใช่ไฟล์โปรแกรม");
  EXPECT_EQ(job.program()->files.size(), 2u);  // 2000.nc
}

TEST(MakeJob, TheStockGivenForTheRunWinsOverTheHeader) {
  JobInput r = request(KLUENG_SAMPLES_DIR "/01-step-shaft.txt");
  io::JobHeader stock;
  stock.diameter = 30.0;
  stock.length = 60.0;
  stock.stockSource = io::StockSource::CommandLine;
  r.stock = stock;
  const auto made = makeJob(r);
  const Job& job = *made;
  ASSERT_TRUE(job.file());
  EXPECT_EQ(job.file()->header.diameter, 30.0);
  EXPECT_EQ(job.file()->header.length, 60.0);
  EXPECT_EQ(job.file()->header.stockSource, io::StockSource::CommandLine);
  ASSERT_FALSE(job.stockNotes().empty());
}

TEST(MakeJob, WithoutAToolTableTWordsAreNotChecked) {
  JobInput r = request(KLUENG_SAMPLES_DIR "/01-step-shaft.txt");
  r.toolTable = false;
  r.setup = MachineSetup{};  // no bitmaps at all
  const auto made = makeJob(r);
  const Job& job = *made;
  EXPECT_FALSE(job.hasErrors());
  EXPECT_TRUE(job.toolNotes().empty());
}

// Where the editor's modal walk stops (the macro statement on line 3), the
// recorded run goes on (issue 26 item 2): it meets G96 with no spindle limit
// (W105 on line 5), then an arc whose R cannot join its ends (W106, the run's
// A114 on line 8), each once, at the word, as the walk would have said it.
std::vector<std::string> modalWarnings(const std::string& text) {
  JobInput input = request("");
  input.modalRules = true;  // as the editor asks
  io::ProgramFile file;     // the editor's text: a plain program
  file.plainGcode = true;
  file.gcodeFirstLine = 1;
  file.gcode = text;
  input.file = file;
  const auto job = makeJob(input);
  std::vector<std::string> seen;
  for (const Diagnostic& d : job->programFileDiagnostics())
    if (d.severity == Severity::Warning)
      seen.push_back(d.code + " " + std::to_string(d.range.line) + ":" + std::to_string(d.range.column) + " " +
                     (d.args.empty() ? "" : d.args.front()) + (d.args.size() > 1 ? " " + d.args[1] : ""));
  return seen;
}

TEST(MakeJob, TheRunWarnsWhereTheModalWalkCannotFollow) {
  EXPECT_EQ(modalWarnings("O0001\nG21 G99\n#1 = 40.\nT0101\nG96 S180 M03\nG00 X#1 Z2.\n"
                          "G01 Z-20. F0.2\nG02 X50. Z-25. R2.\nM30\n"),
            (std::vector<std::string>{"W105 5:1 ", "W106 8:16 R2. 3.536"}));
  // A feed move with no F after a statement: W104 on the G01 the run stops at.
  EXPECT_EQ(modalWarnings("O0002\nG21 G99\n#1 = 40.\nT0101\nG50 S2500\nG97 S800 M03\nG00 X[#1+2] Z2.\n"
                          "G01 Z-20.\nX50.\nM30\n"),
            (std::vector<std::string>{"W104 8:1 G01"}));
  // Before the statement the walk itself warns, and the run adds nothing twice.
  EXPECT_EQ(modalWarnings("O0003\nG21 G99\nT0101\nG96 S180 M03\n#1 = 40.\nG00 X#1 Z2.\nG01 Z-20. F0.2\nM30\n"),
            (std::vector<std::string>{"W105 4:1 "}));
}

// A header file held in memory (the editor's, a generated program): checked,
// then run on first ask. The first step of issue 12's CompiledJob, now a Job.
JobInput inMemory(const std::string& gcode, double diameter,
                  const MachineSetup& setup = machine::testing::testSetup()) {
  JobInput input;
  input.setup = setup;
  input.inferTools = false;  // the test setup as it is
  io::ProgramFile file;
  file.header.diameter = diameter;
  file.header.length = 100;
  file.header.stockSource = io::StockSource::Header;
  file.gcodeFirstLine = 7;
  file.gcode = gcode;
  input.file = file;
  return input;
}

TEST(MakeJob, CheckThenRunOnFirstAsk) {
  const auto job = makeJob(inMemory("G98 G00 X20. Z2.\nM01\nG01 Z-5. F100.\n", 40));
  ASSERT_FALSE(job->hasErrors());
  const ComputeLog before = computeLog();
  const machine::Timeline* timeline = job->timeline();
  ASSERT_TRUE(timeline);
  EXPECT_EQ(computeLog().timelines - before.timelines, 1);
  EXPECT_EQ(job->timeline(), timeline);  // once: the second ask is the same run
  EXPECT_EQ(computeLog().timelines - before.timelines, 1);
  ASSERT_EQ(timeline->snapshots.size(), 3u);
  EXPECT_FALSE(timeline->snapshots[0].optionalStop);
  EXPECT_TRUE(timeline->snapshots[1].optionalStop);  // M01 on line 8, whatever the switch
  EXPECT_EQ(timeline->snapshots[1].line, 8);
  // Errors: no timeline, the diagnostics sorted, the missing stock size on header line 4.
  const auto bad = makeJob(inMemory("G01 X20. Y1.\n", 0));
  EXPECT_FALSE(bad->timeline());
  EXPECT_FALSE(bad->cut());
  ASSERT_EQ(bad->diagnostics().size(), 2u);
  EXPECT_EQ(bad->diagnostics()[0].code, "F115");
  EXPECT_EQ(bad->diagnostics()[0].range.line, 4);
  EXPECT_EQ(bad->diagnostics()[1].code, "E201");
  EXPECT_EQ(bad->diagnostics()[1].range.line, 7);
}

// The cut is computed once, whichever thread asks first; every thread sees the same bar.
TEST(MakeJob, TheCutIsComputedOnceWhicheverThreadAsks) {
  const auto job = makeJob(
      inMemory("T0101\nG97 S1000 M03\nG98 G00 X38. Z2.\nG01 Z-30. F100.\nG00 X50.\nZ2.\n", 40, shipped().setup));
  ASSERT_FALSE(job->hasErrors());
  const ComputeLog before = computeLog();
  std::vector<std::future<const cut::CutSimulator*>> asks;
  for (int i = 0; i < 4; ++i) asks.push_back(std::async(std::launch::async, [job] { return job->cut(); }));
  const cut::CutSimulator* first = asks[0].get();
  ASSERT_TRUE(first);
  for (std::size_t i = 1; i < asks.size(); ++i) EXPECT_EQ(asks[i].get(), first);
  EXPECT_EQ(computeLog().cuts - before.cuts, 1);
  EXPECT_EQ(computeLog().timelines - before.timelines, 1);
  EXPECT_TRUE(first->finished());
  EXPECT_FALSE(first->alarm());
  // The same bar as a cut of the same run made here, alone.
  cut::CutSimulator alone(*job->timeline(), cut::CutSetup::from(job->file()->header, job->setup()));
  alone.runToEnd();
  EXPECT_GT(first->removedVolume(), 0.0);
  EXPECT_DOUBLE_EQ(first->removedVolume(), alone.removedVolume());
}

// The editor shows one file: an error inside a subprogram file is one E412 on
// the call that reaches it; a CLI job keeps it in its own file.
TEST(MakeJob, AnErrorInASubprogramFileIsOneE412OnItsCallForTheEditor) {
  const machine::testing::ScratchFolder folder{"jobfold"};
  const std::string main = folder.write("MAIN.nc", "O0100\nG21 G99\nT0101\nG00 X42. Z2.\nM98 P1000\nM30\n");
  folder.write("O1000.nc", "O1000\nG01 X20. Y1. F0.2\nM99\n");
  const auto job = makeJob(request(main));
  bool inSubprogram = false;
  for (const Diagnostic& d : job->diagnostics())
    if (d.range.file == 1 && d.code == "E201") inSubprogram = true;
  EXPECT_TRUE(inSubprogram);
  std::vector<Diagnostic> errors;
  for (const Diagnostic& d : job->programFileDiagnostics())
    if (isError(d.severity)) errors.push_back(d);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].code, "E412");
  EXPECT_EQ(errors[0].range.line, 5);
  EXPECT_EQ(errors[0].range.column, 5);
  EXPECT_EQ(errors[0].args, (std::vector<std::string>{"O1000.nc", "2", "10", "E201"}));
}

// The GUI's run lends the editor's check its parsed program (issue 42 item 3): a job of the same
// text, read alike, shares the check's blocks, subprogram files and readings, and runs as a job
// that parsed the text itself; another text, folder or dialect is parsed anew.
TEST(MakeJob, TheRunSharesTheChecksProgramWhenItReadsTheSameText) {
  const machine::testing::ScratchFolder folder{"sametext"};
  folder.write("O2000.nc", "O2000\nG01 U-4 F0.2\nG00 U4\nW-6\nM99\n");
  const auto editorJob = [&](const std::string& text, gcode::Dialect dialect, std::shared_ptr<const Job> same) {
    JobInput input = request("", dialect);
    io::ProgramFile file;  // a plain program in the editor: lengths without a point, a subprogram file
    file.plainGcode = true;
    file.gcodeFirstLine = 1;
    file.gcode = text;
    input.file = file;
    input.folder = folder.path();
    input.inferTools = same == nullptr;  // the run takes the check's tools as they are
    if (same) input.setup = same->setup();
    input.sameText = std::move(same);
    return makeJob(std::move(input));
  };
  const std::string text = "O0001\nG21 G99\nT0101\nG97 S800 M03\nG00 X42 Z2\nM98 P32000\nG00 X100 Z100\nM30\n";
  const auto check = editorJob(text, gcode::Dialect::Fanuc, nullptr);
  ASSERT_FALSE(check->hasErrors());
  ASSERT_EQ(check->program()->files.size(), 2u);  // O2000.nc attached
  const auto run = editorJob(text, gcode::Dialect::Fanuc, check);
  EXPECT_EQ(run->program(), check->program());  // the same blocks, not a copy
  const auto parsed = makeJob([&] {
    JobInput input = request("", gcode::Dialect::Fanuc);
    input.file = *check->file();
    input.folder = folder.path();
    input.inferTools = false;
    input.setup = check->setup();
    return input;
  }());
  ASSERT_NE(parsed->program(), check->program());
  // The subprogram three times (M98 P32000), as a job that parsed the text itself runs it, to the move.
  ASSERT_TRUE(run->timeline() && parsed->timeline());
  ASSERT_EQ(run->timeline()->moves.size(), parsed->timeline()->moves.size());
  for (std::size_t i = 0; i < run->timeline()->moves.size(); ++i) {
    EXPECT_EQ(run->timeline()->moves[i].path.end, parsed->timeline()->moves[i].path.end) << i;
    EXPECT_EQ(run->timeline()->moves[i].line, parsed->timeline()->moves[i].line) << i;
  }
  EXPECT_EQ(run->diagnostics().size(), parsed->diagnostics().size());
  // X42 without a point reads as 42 mm in both: the shared reading of the lengths.
  const auto approach = std::find_if(run->timeline()->moves.rbegin(), run->timeline()->moves.rend(),
                                     [](const machine::Move& m) { return m.line == 5; });
  ASSERT_NE(approach, run->timeline()->moves.rend());
  EXPECT_DOUBLE_EQ(approach->path.end.y(), 21.0);
  EXPECT_DOUBLE_EQ(approach->path.end.x(), 2.0);
  // Another text, another dialect: parsed anew, read as that job reads it.
  const auto edited = editorJob(text + "G00 X50 Z5\n", gcode::Dialect::Fanuc, check);
  EXPECT_NE(edited->program(), check->program());
  EXPECT_EQ(edited->program()->blocks.size(), check->program()->blocks.size() + 1);
  const auto haas = editorJob(text, gcode::Dialect::Haas, check);
  EXPECT_NE(haas->program(), check->program());
}

// A guessed nose radius never stops a run the shop's insert would not (issue 38 item 7): a
// finishing pass under G42 steps up a 1.5 mm shoulder and retracts along +Z, as a Brazilian
// course program's G70 does. The shipped offset 01 (R0.8, a guess for a plain program) cannot
// follow the 1.5 mm face between two concave corners (A202); R0.4 can.
TEST(MakeJob, AGuessedNoseThatDoesNotFitRunsWithTheLargestRadiusThatDoes) {
  const machine::testing::ScratchFolder folder{"guessednose"};
  const std::string text =
      "O0002\n"               // 1
      "G21 G40 G99\n"         // 2
      "T0101\n"               // 3
      "G97 S1000 M3\n"        // 4
      "G00 X90. Z5.\n"        // 5
      "G42 G00 X76. Z2.\n"    // 6
      "G01 Z-20. F0.1\n"      // 7
      "X79.\n"                // 8
      "G00 Z2.\n"             // 9
      "G40 G00 X100. Z50.\n"  // 10
      "M30\n";                // 11
  const std::string path = folder.write("shoulder.nc", text);
  JobInput in = request(path);
  io::JobHeader bar;
  bar.diameter = 80.0;
  bar.length = 60.0;
  bar.stockSource = io::StockSource::CommandLine;
  in.stock = bar;
  const auto made = makeJob(in);
  ASSERT_TRUE(made->setup().tools.isGuess(1));
  const machine::Timeline* t = made->timeline();
  ASSERT_NE(t, nullptr);
  EXPECT_FALSE(t->alarm.has_value()) << t->alarm->code << " line " << t->alarm->range.line;
  ASSERT_FALSE(t->flow.notices.empty());
  const Diagnostic& w = t->flow.notices.front();
  EXPECT_EQ(w.code, "W205");
  EXPECT_EQ(w.severity, Severity::Warning);
  EXPECT_EQ(w.args, (std::vector<std::string>{"01", "0.8", std::to_string(w.range.line), "0.4", "A202"}));
  EXPECT_GE(w.range.line, 8);

  // The user's own tools (not guessed): the alarm is the program's, as on the lathe.
  JobInput chosen = in;
  chosen.inferTools = false;
  const auto own = makeJob(chosen);
  ASSERT_FALSE(own->setup().tools.isGuess(1));
  ASSERT_NE(own->timeline(), nullptr);
  ASSERT_TRUE(own->timeline()->alarm.has_value());
  EXPECT_EQ(own->timeline()->alarm->code, "A202");
}

}  // namespace
}  // namespace klueng::core::job
