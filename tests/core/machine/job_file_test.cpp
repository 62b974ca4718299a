// One program file made ready to run (job_file.h): what klueng-cli check and
// simulate see, read and parsed once.
#include "klueng/core/machine/job_file.h"
#include "klueng/core/machine/job_check.h"
#include "klueng/core/messages.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/machine/setup_files.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

namespace fs = std::filesystem;

const LoadedSetup& shipped() {
  static const LoadedSetup setup = loadMachineSetup(KLUENG_SOURCE_DIR);
  return setup;
}

JobFileRequest request(gcode::Dialect dialect = gcode::Dialect::Fanuc) {
  JobFileRequest r;
  r.run.dialect = dialect;
  r.stations = shipped().setup.tools.stations;
  return r;
}

TEST(LoadJobFile, HeaderAndGrammarDiagnosticsComeSortedByLine) {
  const JobFile job = loadJobFile(KLUENG_SAMPLES_DIR "/04-grammar-errors.txt", shipped().setup,
                                  request(gcode::Dialect::Classic), io::shippedToolLibrary());
  ASSERT_TRUE(job.file && job.program);
  EXPECT_FALSE(job.unreadable);
  ASSERT_FALSE(job.diagnostics.empty());
  EXPECT_EQ(job.diagnostics.front().range.line, 11);
  EXPECT_EQ(job.diagnostics.back().range.line, 30);
  for (std::size_t i = 1; i < job.diagnostics.size(); ++i)
    EXPECT_LE(job.diagnostics[i - 1].range.line, job.diagnostics[i].range.line);
  EXPECT_TRUE(job.stockNotes.empty());  // the header's stock: nothing to say
  EXPECT_EQ(job.file->header.stockSource, io::StockSource::Header);
}

TEST(LoadJobFile, AFileThatCannotBeReadIsUnreadable) {
  const JobFile job = loadJobFile("/no/such/file.nc", shipped().setup, request(), io::shippedToolLibrary());
  EXPECT_TRUE(job.unreadable);
  EXPECT_FALSE(job.file);
  EXPECT_TRUE(job.hasErrors());
}

TEST(LoadJobFile, APlainProgramWithASubprogramFileIsParsedOnceEach) {
  const testing::ScratchFolder folder{"jobfile"};
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
  const JobFile job = loadJobFile(main, shipped().setup, request(), io::shippedToolLibrary());
  EXPECT_EQ(gcode::parseCount() - before, 2u);  // MAIN.nc and O1000.nc, nothing twice
  ASSERT_TRUE(job.program);
  EXPECT_EQ(job.program->files.size(), 2u);
  for (const Diagnostic& d : job.diagnostics) ADD_FAILURE() << d.code << " line " << d.range.line << " file " << d.range.file;
  // The stock comes from the approach X42. (the next bar up), and a note says so.
  EXPECT_EQ(job.file->header.stockSource, io::StockSource::Inferred);
  EXPECT_GE(job.file->header.diameter, 42.0);
  ASSERT_FALSE(job.stockNotes.empty());
  // A boring bar for the empty station 9, from its comment.
  ASSERT_FALSE(job.toolNotes.empty());
  EXPECT_NE(job.setup.tools.libraryId(9).find("bor"), std::string::npos) << job.setup.tools.libraryId(9);
}

// Issue 29 item 10: the called program's file name is a folder beside the program:
// the call says so (E416), not "neither in this file nor in its folder" (E404); a
// real file under another of its names is still taken.
TEST(LoadJobFile, ASubprogramFileThatIsAFolderIsSaidToBeOne) {
  const testing::ScratchFolder folder{"jobfile"};
  const std::string main = folder.write("MAIN.nc", "O0100\nG21\nM98 P1000\nM98 P2000\nM30\n");
  fs::create_directory(fs::path(main).parent_path() / "O1000.nc");
  fs::create_directory(fs::path(main).parent_path() / "O2000.nc");
  folder.write("2000.nc", "O2000\nG00 X10.\nM99\n");
  const JobFile job = loadJobFile(main, shipped().setup, request(), io::shippedToolLibrary());
  ASSERT_TRUE(job.program);
  std::vector<const Diagnostic*> errors;
  for (const Diagnostic& d : job.diagnostics)
    if (isError(d.severity)) errors.push_back(&d);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0]->code, "E416");
  EXPECT_EQ(errors[0]->range.line, 3);
  EXPECT_EQ(errors[0]->range.column, 5);
  EXPECT_EQ(formatMessage(*errors[0], Lang::En),
            "M98 P1000: program O1000 is not in this file, and 'O1000.nc' in its folder is a folder, not a program file");
  EXPECT_EQ(formatMessage(*errors[0], Lang::Th),
            "M98 P1000: ไม่มีโปรแกรม O1000 ในไฟล์นี้ และ 'O1000.nc' ในโฟลเดอร์เดียวกันเป็นโฟลเดอร์ ไม่ใช่ไฟล์โปรแกรม");
  EXPECT_EQ(job.program->files.size(), 2u);  // 2000.nc
}

TEST(LoadJobFile, TheStockGivenForTheRunWinsOverTheHeader) {
  JobFileRequest r = request();
  io::JobHeader stock;
  stock.diameter = 30.0;
  stock.length = 60.0;
  stock.stockSource = io::StockSource::CommandLine;
  r.stock = stock;
  const JobFile job = loadJobFile(KLUENG_SAMPLES_DIR "/01-step-shaft.txt", shipped().setup, r, io::shippedToolLibrary());
  ASSERT_TRUE(job.file);
  EXPECT_EQ(job.file->header.diameter, 30.0);
  EXPECT_EQ(job.file->header.length, 60.0);
  EXPECT_EQ(job.file->header.stockSource, io::StockSource::CommandLine);
  ASSERT_FALSE(job.stockNotes.empty());
}

TEST(LoadJobFile, WithoutAToolTableTWordsAreNotChecked) {
  JobFileRequest r = request();
  r.toolTable = false;
  MachineSetup bare;  // no bitmaps at all
  const JobFile job = loadJobFile(KLUENG_SAMPLES_DIR "/01-step-shaft.txt", bare, r, io::shippedToolLibrary());
  EXPECT_FALSE(job.hasErrors());
  EXPECT_TRUE(job.toolNotes.empty());
}

// Where the editor's modal walk stops (the macro statement on line 3), the
// recorded run goes on (issue 26 item 2): it meets G96 with no spindle limit
// (W105 on line 5), then an arc whose R cannot join its ends (W106, the run's
// A114 on line 8), each once, at the word, as the walk would have said it.
std::vector<std::string> modalWarnings(const std::string& text) {
  gcode::CheckOptions options;
  options.modalRules = true;  // as the editor asks
  options.toolsWithBitmap = std::vector<int>{};
  const JobCheck job = checkJob(text, 1, options, shipped().setup, io::shippedToolLibrary(), {},
                                shipped().setup.tools.stations);
  std::vector<std::string> seen;
  for (const Diagnostic& d : job.diagnostics)
    if (d.severity == Severity::Warning)
      seen.push_back(d.code + " " + std::to_string(d.range.line) + ":" + std::to_string(d.range.column) + " " +
                     (d.args.empty() ? "" : d.args.front()) + (d.args.size() > 1 ? " " + d.args[1] : ""));
  return seen;
}

TEST(JobCheck, TheRunWarnsWhereTheModalWalkCannotFollow) {
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

}  // namespace
}  // namespace klueng::core::machine
