// klueng-cli class (issue 11): a class of 30 variants of sample 01 graded
// against sample 01 — exact copies, parts within and beyond the tolerance,
// grammar errors, a run-time alarm, a binary and an empty file.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include "../scratch_folders.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_class_test {

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

int run(const std::string& args, std::string* err = nullptr) {
  const std::string command = "env LC_ALL= LC_MESSAGES= LANG=C '" + std::string(KLUENG_CLI_PATH) + "' class " + args +
                              " --config '" + KLUENG_SOURCE_DIR + "' 2>&1 >/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return -1;
  char buf[4096];
  std::string out;
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  if (err) *err = out;
  const int status = ::pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(CliClass, ThirtyStudentsGetTheRightPassOrFail) {
  const fs::path dir = fs::temp_directory_path() / ("klueng_cli_class_test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "class");
  const std::string reference = slurp(fs::path(KLUENG_SAMPLES_DIR) / "01-step-shaft.txt");
  ASSERT_FALSE(reference.empty());
  std::map<std::string, std::string> expected;  // file -> pass / fail
  auto student = [&](const std::string& name, const std::string& text, const char* result) {
    std::ofstream(dir / "class" / name, std::ios::binary) << text;
    expected[name] = result;
  };
  for (int i = 1; i <= 9; ++i) student("copy" + std::to_string(i) + ".txt", reference, "pass");
  // Within 0.05 mm: a shoulder 0.02 further along Z, a finishing diameter 0.02 over.
  for (int i = 1; i <= 3; ++i)
    student("close" + std::to_string(i) + ".nc", replaced(reference, "N420 Z-60.", "N420 Z-60.02"), "pass");
  for (int i = 1; i <= 3; ++i)
    student("over" + std::to_string(i) + ".nc", replaced(reference, "N420 Z-60.", "N420 X46.02 Z-60."), "pass");
  // Beyond it: Ø46 left 0.3 big, Ø40 cut 0.2 small, a shoulder 0.3 too deep.
  for (int i = 1; i <= 3; ++i)
    student("big" + std::to_string(i) + ".nc",
            replaced(reference, "N410 X46. Z-41.\nN420 Z-60.", "N410 X46.3 Z-41.\nN420 Z-60."), "fail");
  for (int i = 1; i <= 3; ++i)
    student("taper" + std::to_string(i) + ".nc", replaced(reference, "N390 G01 Z-40.", "N390 G01 X39.8 Z-40."), "fail");
  student("deep.nc", replaced(reference, "N360 Z-20.", "N360 Z-20.3"), "fail");
  student("deeper-a-bit.nc", replaced(reference, "N360 Z-20.", "N360 Z-20.1"), "fail");
  student("deep-within.nc", replaced(reference, "N360 Z-20.", "N360 Z-20.02"), "pass");
  // Programs that do not run to their end.
  student("typo1.nc", replaced(reference, "N100 G01 Z-59.8", "N100 G01 Y-59.8"), "fail");
  // (A letter twice, "Z-39.8 Z-39.8", is a warning on a Fanuc: no manual makes it a stop. A number
  // with two decimal points is: PS0007, docs/dialects.md §10.)
  student("typo2.nc", replaced(reference, "N140 G01 Z-39.8", "N140 G01 Z-39.8.8"), "fail");
  student("unknown-code.nc", replaced(reference, "N15 G99", "N15 G99 G07"), "fail");
  student("nospindle.nc", replaced(reference, "N40 G96 S180 M03", "N40 G96 S180"), "fail");
  student("binary.nc",
          std::string("\x7f"
                      "ELF\x02\x01\x01\x00\x00\x00",
                      10),
          "fail");
  student("empty.nc", "", "fail");
  ASSERT_EQ(expected.size(), 30u);

  const fs::path csvPath = dir / "grades.csv";
  std::string err;
  ASSERT_EQ(run("'" + (dir / "class").string() + "' --reference '" + KLUENG_SAMPLES_DIR +
                    "/01-step-shaft.txt' --tolerance 0.05 --csv '" + csvPath.string() + "'",
                &err),
            0)
      << err;
  // Progress lines ("[30/30] name") only when stderr is a terminal: a pipe gets none (issue 42 item 4).
  EXPECT_EQ(err.find("[30/30]"), std::string::npos) << err;
  EXPECT_NE(err.find("30 programs: 16 pass, 14 fail"), std::string::npos) << err;

  std::istringstream csv(slurp(csvPath));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line,
            "file,result,errors,first_error,alarm,cycle_time_s,leftover_mm,leftover_z,gouge_mm,gouge_z,cutting_data");
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    const std::string name = line.substr(0, line.find(','));
    ASSERT_TRUE(expected.count(name)) << line;
    const std::string result = line.substr(name.size() + 1, 4);
    EXPECT_EQ(result, expected[name]) << line;
    if (name == "nospindle.nc") {
      EXPECT_NE(line.find("A104 line 15"), std::string::npos) << line;
    }
    if (name == "typo1.nc") {
      EXPECT_NE(line.find(",1,E"), std::string::npos) << line;
    }
    if (name == "deep.nc") {
      EXPECT_NE(line.find(",6.7"), std::string::npos) << line;  // the Ø30->Ø36 step, cut 0.3 deeper
    }
    if (name.starts_with("copy")) {
      EXPECT_NE(line.find(",77.8,0.000,0.00,0.000,0.00"), std::string::npos) << line;
    }
  }
  EXPECT_EQ(rows, 30);
}

// Issue 29 item 7: a class folder as a teacher keeps it — the grades' own CSV
// from the last run, a PDF, a picture, and a subprogram file the students'
// programs call (O2000.nc, M98 P2000). Only the students' programs get a row,
// the subprogram counts as theirs, and the CSV can be written again beside them.
TEST(CliClass, OnlyTheStudentsProgramsAreGradedAndTheGradesCanBeWrittenAgain) {
  const fs::path dir = fs::temp_directory_path() / ("klueng_cli_class_folder_test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string reference = slurp(fs::path(KLUENG_SAMPLES_DIR) / "01-step-shaft.txt");
  ASSERT_FALSE(reference.empty());
  std::ofstream(dir / "anan.txt", std::ios::binary) << reference;
  // The same part, its finishing pass moved into a subprogram file.
  std::ofstream(dir / "O2000.nc", std::ios::binary) << "O2000\nG00 X0. Z2.\nM99\n";
  std::ofstream(dir / "boon.txt", std::ios::binary) << replaced(reference, "N15 G99", "N15 G99\nM98 P2000");
  std::ofstream(dir / "notes.pdf", std::ios::binary) << "%PDF-1.4\n";
  std::ofstream(dir / "lathe.png", std::ios::binary) << "\x89PNG";
  const fs::path csvPath = dir / "grades.csv";
  const std::string args = "'" + dir.string() + "' --reference '" + KLUENG_SAMPLES_DIR +
                           "/01-step-shaft.txt' --tolerance 0.05 --csv '" + csvPath.string() + "'";
  for (int runs = 0; runs < 2; ++runs) {  // the second run finds last run's grades.csv in the folder
    std::string err;
    ASSERT_EQ(run(args, &err), 0) << "run " << runs + 1 << ":\n" << err;
    EXPECT_NE(err.find("2 programs: 2 pass, 0 fail"), std::string::npos) << err;
    const std::string csv = slurp(csvPath);
    EXPECT_NE(csv.find("\nanan.txt,pass,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\nboon.txt,pass,"), std::string::npos) << csv;
    EXPECT_EQ(csv.find("O2000.nc"), std::string::npos) << csv;
    EXPECT_EQ(csv.find("grades.csv"), std::string::npos) << csv;
    EXPECT_EQ(csv.find("notes.pdf"), std::string::npos) << csv;
  }
  fs::remove_all(dir);
}

// Issue 27: a student's program that names its machine at its head is graded on
// it: sample 01 written for a ROMI in system B (G95, G92 S) passes against the
// system-A reference; with --dialect fanuc forced it is read as system A and fails.
TEST(CliClass, EachProgramIsGradedOnTheMachineItNames) {
  const fs::path dir = fs::temp_directory_path() / ("klueng_cli_class_machine_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string reference = slurp(fs::path(KLUENG_SAMPLES_DIR) / "01-step-shaft.txt");
  std::string romi = replaced(reference, "O0001\n", "O0001\n(MACHINE: romi-gl240m)\n");
  romi = replaced(romi, "N15 G99", "N15 G95");
  romi = replaced(romi, "N30 G50 S2500", "N30 G92 S2500");
  std::ofstream(dir / "romi.txt", std::ios::binary) << romi;
  const std::string args = "'" + dir.string() + "' --reference '" + KLUENG_SAMPLES_DIR + "/01-step-shaft.txt'";
  const fs::path named = dir / "named.csv", forced = dir / "forced.csv";
  std::string err;
  ASSERT_EQ(run(args + " --csv '" + named.string() + "'", &err), 0) << err;
  EXPECT_NE(slurp(named).find("\nromi.txt,pass,0,"), std::string::npos) << slurp(named);
  ASSERT_EQ(run(args + " --dialect fanuc --csv '" + forced.string() + "'", &err), 0) << err;
  EXPECT_NE(slurp(forced).find("\nromi.txt,fail,"), std::string::npos) << slurp(forced);
  fs::remove_all(dir);
}

// Issue 31 item 5: the setup exercise. Sample 01 with (OFFSETS: UNKNOWN) at its head: each student's
// program runs on the touch-off saved beside it and gets a graded line per tool, English or Thai.
TEST(CliClass, TheSetupExerciseIsGradedOnEachStudentsTouchOff) {
  const fs::path dir = fs::temp_directory_path() / ("klueng_cli_class_touchoff_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string reference = slurp(fs::path(KLUENG_SAMPLES_DIR) / "01-step-shaft.txt");
  const std::string exercise = replaced(reference, "O0001\n", "O0001\n(OFFSETS: UNKNOWN)\n");
  for (const char* name : {"dao.txt", "ekk.txt", "fon.txt"}) std::ofstream(dir / name, std::ios::binary) << exercise;
  // dao touched off right: offset.cfg's own rows; ekk's T01 is 0.3 mm out on the diameter; fon saved nothing.
  const std::string shipped = slurp(fs::path(KLUENG_SOURCE_DIR) / "offset.cfg");
  std::ofstream(dir / "dao.offset.cfg", std::ios::binary) << shipped;
  std::ofstream(dir / "ekk.offset.cfg", std::ios::binary) << replaced(shipped, "0 0 0.8 3\n", "0.3 0 0.8 3\n");
  const std::string args =
      "'" + dir.string() + "' --reference '" + KLUENG_SAMPLES_DIR + "/01-step-shaft.txt' --tolerance 0.05";
  const fs::path csvPath = dir / "grades.csv";
  std::string err;
  ASSERT_EQ(run(args + " --csv '" + csvPath.string() + "'", &err), 0) << err;
  EXPECT_NE(err.find("3 programs: 1 pass, 2 fail"), std::string::npos) << err;
  EXPECT_NE(err.find("dao.txt: T01 touched off at X0.000 Z0.000, true X0.000 Z0.000: within 0.050 mm\n"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("ekk.txt: T01 touched off at X0.300 Z0.000, true X0.000 Z0.000: outside 0.050 mm\n"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("fon.txt: the offsets are unknown but fon.offset.cfg was not found"), std::string::npos) << err;
  const std::string csv = slurp(csvPath);
  EXPECT_NE(csv.find("gouge_z,cutting_data,touch_off\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\ndao.txt,pass,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",T01 X0.000/0.000 Z0.000/0.000 in\n"), std::string::npos) << csv;
  // ekk's part comes out 0.3 mm large on the diameter: the part check sees the touch-off too.
  const auto ekk = csv.find("\nekk.txt,fail,0,,,");
  ASSERT_NE(ekk, std::string::npos) << csv;
  const std::string ekkLine = csv.substr(ekk + 1, csv.find('\n', ekk + 1) - ekk - 1);
  EXPECT_NE(ekkLine.find(",0.300,"), std::string::npos) << ekkLine;
  EXPECT_NE(ekkLine.find(",T01 X0.300/0.000 Z0.000/0.000 out"), std::string::npos) << ekkLine;
  EXPECT_NE(csv.find("\nfon.txt,fail,0,,,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",not saved (fon.offset.cfg)\n"), std::string::npos) << csv;
  // In Thai.
  ASSERT_EQ(run(args + " --lang th --csv '" + csvPath.string() + "'", &err), 0) << err;
  EXPECT_NE(err.find("ekk.txt: T01 ตั้งศูนย์ได้ X0.300 Z0.000 ค่าจริง X0.000 Z0.000: เกินพิกัด 0.050 มม."), std::string::npos)
      << err;
  fs::remove_all(dir);
}

std::string pdfText(const fs::path& pdf, const std::string& options = "") {
  std::string text;
  FILE* pipe = ::popen(("pdftotext " + options + " '" + pdf.string() + "' - 2>/dev/null").c_str(), "r");
  if (!pipe) return text;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) text.append(buf, n);
  ::pclose(pipe);
  return text;
}

// Issue 39 item 4: each student's cutting-data warnings, code and line, in the CSV's cutting_data
// column and the PDF's "Cutting data" column. Sample 01 with its finishing feed F0.1 made F0.35 on
// line 44 alone (the Ø30 from Z-3 to Z-20): Ra = 0.35^2 / (32 * 0.8) * 1000 = 4.8 um > 3.2.
TEST(CliClass, TheCuttingDataWarningsAreAColumn) {
  const fs::path dir = fs::temp_directory_path() / ("klueng_cli_class_cutting_test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "class");
  const std::string reference = slurp(fs::path(KLUENG_SAMPLES_DIR) / "01-step-shaft.txt");
  std::ofstream(dir / "class" / "anna.nc", std::ios::binary) << reference;
  std::ofstream(dir / "class" / "boon.nc", std::ios::binary)
      << replaced(replaced(reference, "N360 Z-20.", "N360 Z-20. F0.35"), "N370 X36.", "N370 X36. F0.1");
  const std::string ref = std::string(KLUENG_SAMPLES_DIR) + "/01-step-shaft.txt";
  std::string err;
  ASSERT_EQ(run("'" + (dir / "class").string() + "' --reference '" + ref + "' --csv '" + (dir / "g.csv").string() +
                    "' --pdf '" + (dir / "g.pdf").string() + "'",
                &err),
            0)
      << err;
  const std::string csv = slurp(dir / "g.csv");
  EXPECT_NE(csv.find(",gouge_z,cutting_data\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nanna.nc,pass,0,,,77.8,0.000,0.00,0.000,0.00,\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",W332 line 44\n"), std::string::npos) << csv;
  const std::string table = pdfText(dir / "g.pdf", "-layout");
  for (const char* s : {"Cutting data", "W332 line 44"}) EXPECT_NE(table.find(s), std::string::npos) << s << table;
  ASSERT_EQ(run("'" + (dir / "class").string() + "' --reference '" + ref + "' --pdf '" + (dir / "g.pdf").string() +
                    "' --lang th",
                &err),
            0)
      << err;
  const std::string thai = pdfText(dir / "g.pdf", "-layout");
  EXPECT_NE(thai.find("W332 บรรทัด 44"), std::string::npos) << thai;
  fs::remove_all(dir);
}

TEST(CliClass, ThePdfHasTheTableAndWithSheetsEveryStudentsSheets) {
  const fs::path dir = fs::temp_directory_path() / ("klueng_cli_class_pdf_test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "class");
  const std::string reference = slurp(fs::path(KLUENG_SAMPLES_DIR) / "01-step-shaft.txt");
  std::ofstream(dir / "class" / "anna.nc", std::ios::binary) << reference;
  std::ofstream(dir / "class" / "boon.nc", std::ios::binary)
      << replaced(reference, "N390 G01 Z-40.", "N390 G01 X39.8 Z-40.");
  const std::string ref = std::string(KLUENG_SAMPLES_DIR) + "/01-step-shaft.txt";
  std::string err;
  ASSERT_EQ(run("'" + (dir / "class").string() + "' --reference '" + ref + "' --csv '" + (dir / "g.csv").string() +
                    "' --pdf '" + (dir / "grades.pdf").string() + "'",
                &err),
            0)
      << err;
  const std::string table = pdfText(dir / "grades.pdf");
  for (const char* s :
       {"Class grades", "01-step-shaft.txt", "2 programs: 1 pass, 1 fail", "anna.nc", "boon.nc", "0.191"})
    EXPECT_NE(table.find(s), std::string::npos) << s << "\n" << table;
  EXPECT_FALSE(fs::exists(dir / "grades.pdf.partial"));
  // In Thai, with each student's program sheet and drawing: 1 + 2 x 2 pages.
  ASSERT_EQ(run("'" + (dir / "class").string() + "' --reference '" + ref + "' --csv '" + (dir / "g.csv").string() +
                    "' --pdf '" + (dir / "sheets.pdf").string() + "' --sheets --lang th",
                &err),
            0)
      << err;
  const std::string all = pdfText(dir / "sheets.pdf");
  // (pdftotext splits some Thai marks from their letters: words without them.)
  for (const char* s : {"ผลการตรวจงาน", "ชุดรหัส", "เอกสารแสดงภาพชิ้นงาน", "N390 G01 X39.8 Z-40."})
    EXPECT_NE(all.find(s), std::string::npos) << s;
  EXPECT_EQ(std::count(all.begin(), all.end(), '\f'), 5);  // pdftotext ends each page with a form feed
}

// Issue 28 item 2: graded against the teacher's drawing with tolerances instead
// of a reference program — one in, one out, one exactly at a limit.
TEST(CliClass, GradedAgainstTheDrawingFeatureByFeature) {
  const fs::path dir = fs::temp_directory_path() / ("klueng_cli_class_drawing_test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "class");
  const std::string sample = slurp(fs::path(KLUENG_SAMPLES_DIR) / "01-step-shaft.txt");
  std::ofstream(dir / "class" / "anna.nc", std::ios::binary) << sample;
  std::ofstream(dir / "class" / "boon.nc", std::ios::binary)
      << replaced(sample, "N380 G03 X40. Z-22.", "N380 G03 X39.98 Z-22.");  // Ø40 0.02 small: out of js6
  std::ofstream(dir / "class" / "chai.nc", std::ios::binary)
      << replaced(sample, "N410 X46. Z-41.\nN420 Z-60.", "N410 X45.95 Z-41.\nN420 Z-60.");  // at the lower limit: in
  const fs::path drawing = dir / "shaft.json";
  std::ofstream(drawing, std::ios::binary) << R"({
    "stock": { "diameter": 50, "length": 100 },
    "outside": [
      { "cylinder": 30, "length": 20, "chamfer": 3, "tolerance": "h7", "length_tolerance": 0.1 },
      { "cylinder": 40, "length": 20, "round": 2, "tolerance": "js6" },
      { "cylinder": 46, "length": 20, "chamfer": 1, "tolerance": [0, -0.05] }
    ]
  })";
  const std::string folder = "'" + (dir / "class").string() + "'";
  const fs::path csvPath = dir / "grades.csv";
  std::string err;
  ASSERT_EQ(run(folder + " --drawing '" + drawing.string() + "' --csv '" + csvPath.string() + "'", &err), 0) << err;
  EXPECT_NE(err.find("3 programs: 2 pass, 1 fail"), std::string::npos) << err;
  const std::string csv = slurp(csvPath);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "file,result,errors,first_error,alarm,cycle_time_s,leftover_mm,leftover_z,gouge_mm,gouge_z,cutting_data,"
            "feature,nominal_mm,tolerance,lower_mm,upper_mm,measured_mm,verdict");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 3 * 4) << csv;
  EXPECT_NE(csv.find("\nanna.nc,pass,0,,,77.8,,,,,,Ø30,30.000,h7 (0/-0.021),29.979,30.000,30.000,in\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\nboon.nc,fail,0,,,77.8,,,,,,Ø40,40.000,js6 (±0.008),39.992,40.008,39.980,out\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\nchai.nc,pass,0,,,77.8,,,,,,Ø46,46.000,0/-0.05,45.950,46.000,45.950,in\n"), std::string::npos)
      << csv;

  // Besides the reference, and as a PDF in Thai: the drawing's page lists every student's dimensions.
  const std::string ref = std::string(KLUENG_SAMPLES_DIR) + "/01-step-shaft.txt";
  ASSERT_EQ(run(folder + " --drawing '" + drawing.string() + "' --reference '" + ref + "' --csv '" + csvPath.string() +
                    "' --pdf '" + (dir / "grades.pdf").string() + "' --lang th",
                &err),
            0)
      << err;
  EXPECT_NE(slurp(csvPath).find("\nboon.nc,fail,0,,,77.8,0.000,0.00,0.020,"), std::string::npos) << slurp(csvPath);
  const std::string th = pdfText(dir / "grades.pdf");
  for (const char* s : {"shaft.json", "01-step-shaft.txt", "anna.nc", "boon.nc", "chai.nc", "h7 (0/-0.021)",
                        "js6 (±0.008)", "39.992 – 40.008", "39.980", "45.950", "0.001"})
    EXPECT_NE(th.find(s), std::string::npos) << s << "\n" << th;
  EXPECT_EQ(std::count(th.begin(), th.end(), '\f'), 2) << th;  // the table, then the inspection
  // In English, the same PDF says it in English words.
  ASSERT_EQ(run(folder + " --drawing '" + drawing.string() + "' --csv '" + csvPath.string() + "' --pdf '" +
                    (dir / "en.pdf").string() + "'",
                &err),
            0)
      << err;
  const std::string en = pdfText(dir / "en.pdf", "-layout");
  for (const char* s : {"Against the drawing shaft.json (4 toleranced dimensions)", "Inspection against shaft.json",
                        "a value exactly at a limit is in", "3 of 4 in", "out", "Measured (mm)"})
    EXPECT_NE(en.find(s), std::string::npos) << s << "\n" << en;

  // A drawing without tolerances grades nothing: said, exit 2; with a general tolerance it grades.
  std::ofstream(drawing, std::ios::binary) << R"({ "stock": { "diameter": 50, "length": 100 },
    "outside": [ { "cylinder": 30, "length": 20, "chamfer": 3 } ] })";
  EXPECT_EQ(run(folder + " --drawing '" + drawing.string() + "'", &err), 2);
  EXPECT_NE(err.find("has no toleranced dimension"), std::string::npos) << err;
  EXPECT_EQ(run(folder + " --drawing '" + drawing.string() + "' --general-tolerance x", &err), 2);
  EXPECT_NE(err.find("f, m, c or v"), std::string::npos) << err;
  // A DXF drawing: its layer named when it has several.
  const std::string pin = std::string(KLUENG_SOURCE_DIR) + "/fuzz/corpus/design/pin.dxf";
  EXPECT_EQ(run(folder + " --drawing '" + pin + "' --general-tolerance m", &err), 2);
  EXPECT_NE(err.find("F187"), std::string::npos) << err;
  // With the layer named it is read on that layer (this corpus pin's outline is open there: F189, located).
  EXPECT_EQ(run(folder + " --drawing '" + pin + "' --layer PART --general-tolerance m", &err), 2);
  EXPECT_NE(err.find("F189"), std::string::npos) << err;
  EXPECT_NE(err.find("X45.000 Y17.000"), std::string::npos) << err;
  ASSERT_EQ(run(folder + " --drawing '" + drawing.string() + "' --general-tolerance m --csv '" + csvPath.string() + "'",
                &err),
            0)
      << err;
  EXPECT_NE(slurp(csvPath).find("\nanna.nc,pass,0,,,77.8,,,,,,Ø30,30.000,ISO 2768-m (±0.2),29.800,30.200,30.000,in\n"),
            std::string::npos)
      << slurp(csvPath);
  fs::remove_all(dir);
}

TEST(CliClass, ABadReferenceOrBadOptionsExitTwo) {
  EXPECT_EQ(run("/tmp --reference /no/such/file.nc"), 2);
  EXPECT_EQ(run("--reference x.nc"), 2);
  EXPECT_EQ(run("/tmp --reference x.nc --tolerance -1"), 2);
}

}  // namespace

}  // namespace cli_class_test

// Its scratch folders go with the process: nothing left in /tmp after a run.
[[maybe_unused]] ::testing::Environment* const kCliClassScratchCleanup = klueng::test::removeScratchFoldersAtExit(
    {"klueng_cli_class_test-", "klueng_cli_class_pdf_test-", "klueng_cli_class_cutting_test-"});
