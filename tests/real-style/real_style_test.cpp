// Real-style lathe programs (issue 8, first acceptance item): Haas programs in
// inch and Fanuc 0T/0i programs in mm, written in the habits of shop and
// textbook programs (tests/real-style/README.md says which habit and which
// manual rule each one exercises). Each is run through the built klueng-cli as
// a teacher would run a header-less file:
//   klueng-cli check FILE --dialect haas|fanuc [--units inch] [--stock ...] [--tool ...]
//   klueng-cli simulate FILE ... --profile out.csv
// and the finished part is measured from the profile CSV (z, outer diameter,
// inner diameter, all in mm, one row per 0.01 mm column). Every expected size
// is derived by hand in the comment beside it.
//
// Tool data the derivations use (the shipped offset.cfg, SPEC 9):
//   T01 offset 01: R0.8 mm (0.0315 in), tip 3 - outside turning; with G41/G42
//       the nose follows the contour exactly (cylinders, faces, chamfers,
//       tapers, arcs); with G40 the imaginary tip follows it, so cylinders and
//       faces are exact and tapers/chamfers are left fat (see haas-08).
//   T03 offset 03: R0, tip 8 - the 60 degree thread tool, its apex is the
//       controlled point, so the root of a thread is the last pass's X.
//   T04 offset 04: R0.2 mm, tip 3 - 3 mm grooving tool, left corner controlled.
//   T05 offset 05: R0.4 mm, tip 2 - boring bar.
//   T06 offset 06: R0, tip 7 - Ø10 mm drill, point controlled.
//   T08 offset 08: R0, tip 6 - inside thread tool, apex controlled.
// Stations the shipped tools.cfg has no tool for are given with --tool from
// the tool library: 12=parting-3mm (blade 3 mm = 0.1181 in, left corner
// controlled) and 9=vnmg-35-r02 (35 degree VNMG, R0.2 mm, tip 3; offset row 09
// is 0 0 0 0, so it takes the library tool's nose radius and tip).
#include <unistd.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>
#include "../scratch_folders.h"

namespace {

namespace fs = std::filesystem;

// KLUENG_REAL_STYLE_CLI / KLUENG_REAL_STYLE_CONFIG run the same programs
// against another build or configuration folder.
std::string fromEnv(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : fallback;
}
const std::string kCli = fromEnv("KLUENG_REAL_STYLE_CLI", KLUENG_CLI_PATH);
const std::string kShipped = fromEnv("KLUENG_REAL_STYLE_CONFIG", KLUENG_SOURCE_DIR);
const std::string kPrograms = KLUENG_REAL_STYLE_DIR;

constexpr double kMm = 0.01;    // mm programs: 0.01 mm
constexpr double kIn = 0.0005;  // inch programs: 0.0005 in
constexpr double kMmPerIn = 25.4;

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct Output {
  int exitCode = -1;
  std::string text;  // stdout and stderr
};

Output runCli(const std::string& args) {
  const std::string command = "env LC_ALL= LC_MESSAGES= LANG=C " + quote(kCli) + " " + args + " 2>&1";
  Output out;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[65536];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.text.append(buffer, n);
  const int status = ::pclose(pipe);
  out.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Error lines of `check`/`simulate` output ("FILE:L:C: error E...").
std::string errorLines(const std::string& text) {
  std::istringstream in(text);
  std::string line, errors;
  while (std::getline(in, line))
    if (line.find(": error ") != std::string::npos || line.find(": alarm ") != std::string::npos) errors += line + "\n";
  return errors;
}

// The finished part read from `--profile` (src/core/cut/finished_part.cpp:
// header "z,x_outer,x_inner", then one row per stock column at its centre plus
// the two end faces, diameters in mm, "%.4f"). Lengths in and out are in the
// program's unit: `unit` mm per program unit (1 or 25.4).
class Profile {
 public:
  struct Row {
    double z, outer, inner;  // mm
  };

  Profile() = default;
  Profile(const std::string& csv, double unit) : unit_(unit) {
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
      Row r{};
      if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &r.z, &r.outer, &r.inner) == 3) rows_.push_back(r);
    }
  }
  bool empty() const { return rows_.empty(); }

  // Outer / inner diameter at z, interpolated between the column centres
  // around z (as FinishedPart::outerDiameterAt).
  double d(double z) const { return sample(z, true); }
  double inner(double z) const { return sample(z, false); }
  // Smallest / largest outer diameter over [z0, z1] (a thread's root / crest).
  double minD(double z0, double z1) const { return extreme(z0, z1, true, true); }
  double maxInner(double z0, double z1) const { return extreme(z0, z1, false, false); }
  // Where, going from zFrom towards zTo, the outer (or inner) diameter first
  // crosses `diameter`: a shoulder's or a face's Z, interpolated between the
  // two columns on either side (a vertical face lies on their common edge).
  double edge(double zFrom, double zTo, double diameter, bool outer = true) const {
    const double a = std::min(zFrom, zTo) * unit_, b = std::max(zFrom, zTo) * unit_;
    const double target = diameter * unit_;
    std::vector<Row> span;
    for (const Row& r : rows_)
      if (r.z >= a && r.z <= b) span.push_back(r);
    if (zFrom > zTo) std::reverse(span.begin(), span.end());
    for (std::size_t i = 1; i < span.size(); ++i) {
      const double v0 = (outer ? span[i - 1].outer : span[i - 1].inner) - target;
      const double v1 = (outer ? span[i].outer : span[i].inner) - target;
      if (v0 == 0.0) return span[i - 1].z / unit_;
      if ((v0 < 0) != (v1 < 0)) {
        // A step between two columns sits on their edge; a slope is interpolated.
        // (more than 0.1 mm of diameter from one 0.01 mm column to the next is a step).
        const double z = std::abs(v1 - v0) > 0.1 ? (span[i - 1].z + span[i].z) / 2
                                                 : span[i - 1].z + (span[i].z - span[i - 1].z) * v0 / (v0 - v1);
        return z / unit_;
      }
    }
    return NAN;
  }
  // Z of the part's right face (the last row with material).
  double rightFace() const {
    for (auto it = rows_.rbegin(); it != rows_.rend(); ++it)
      if (it->outer > 0.0) return it->z / unit_;
    return NAN;
  }

 private:
  double sample(double z, bool outer) const {
    const double zm = z * unit_;
    for (std::size_t i = 1; i < rows_.size(); ++i) {
      const Row& a = rows_[i - 1];
      const Row& b = rows_[i];
      if (zm >= a.z && zm <= b.z) {
        const double w = b.z > a.z ? (zm - a.z) / (b.z - a.z) : 0.0;
        const double va = outer ? a.outer : a.inner, vb = outer ? b.outer : b.inner;
        return ((1.0 - w) * va + w * vb) / unit_;
      }
    }
    return NAN;
  }
  double extreme(double z0, double z1, bool outer, bool smallest) const {
    const double a = std::min(z0, z1) * unit_, b = std::max(z0, z1) * unit_;
    double best = NAN;
    for (const Row& r : rows_) {
      if (r.z < a || r.z > b) continue;
      const double v = outer ? r.outer : r.inner;
      if (std::isnan(best) || (smallest ? v < best : v > best)) best = v;
    }
    return best / unit_;
  }

  std::vector<Row> rows_;
  double unit_ = 1.0;
};

// A known disagreement between Klueng and the real control, written down as a
// decision: the job's test checks that the output still shows it (`needle`) and
// is then skipped with `reason`; once Klueng changes and the needle is gone the
// test fails, saying to remove the limit from the job so that it runs.
struct KnownLimit {
  std::string needle;
  std::string reason;
};

struct Job {
  std::string file;     // under tests/real-style/programs
  std::string dialect;  // haas | fanuc
  std::string options;  // --stock ... [--units inch] [--tool N=ID]
  bool inch = false;
  std::optional<KnownLimit> known = {};
};

struct Result {
  Output check, simulate;
  Profile part;
};

// check, then simulate with the profile written; the finished part in the program's unit.
Result cut(const Job& job) {
  const fs::path dir = fs::temp_directory_path() / ("klueng_real_style_test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // One file per test: ctest may run the tests of one program side by side.
  const fs::path csv = dir / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".csv");
  fs::remove(csv);
  const std::string file = quote(kPrograms + "/" + job.file);
  const std::string common = " --dialect " + job.dialect + " " + job.options + " --config " + quote(kShipped);
  Result r;
  r.check = runCli("check " + file + common);
  r.simulate = runCli("simulate " + file + common + " --resolution 0.01 --profile " + quote(csv.string()));
  r.part = Profile(slurp(csv), job.inch ? kMmPerIn : 1.0);
  return r;
}

// Both commands must succeed without an error (warnings, such as rounded CAM
// decimals or a machine-specific M code, are allowed), and a part must exist.
// A job with a known limit instead checks that the limit is still there.
#define RUN_CLEAN(job, r)                                                                                \
  const Result r = cut(job);                                                                             \
  if ((job).known) {                                                                                     \
    ASSERT_NE((r.check.text + r.simulate.text).find((job).known->needle), std::string::npos)             \
        << (job).file << ": the known limit is lifted (\"" << (job).known->needle                        \
        << "\" is gone): remove it from the job so that the test runs\n"                                 \
        << r.check.text << r.simulate.text;                                                              \
    GTEST_SKIP() << (job).file << ": known disagreement with the real control: " << (job).known->reason; \
  }                                                                                                      \
  ASSERT_EQ(r.check.exitCode, 0) << "check " << (job).file << ":\n" << r.check.text;                     \
  ASSERT_EQ(errorLines(r.check.text), "") << r.check.text;                                               \
  ASSERT_EQ(r.simulate.exitCode, 0) << "simulate " << (job).file << ":\n" << r.simulate.text;            \
  ASSERT_EQ(errorLines(r.simulate.text), "") << r.simulate.text;                                         \
  ASSERT_FALSE(r.part.empty())

// ============================================================================
// Haas ST programs, inch. The Haas profile powers on in inch (G20 not needed).
// ============================================================================

// O20101: power-on inch (no G20), bare G28, M31/M33, one-block G71 P Q U W D F
// with G42 inside the profile, G70 P Q, G53 G00 X0 / G53 G00 Z0, T1212 cut-off.
TEST(RealStyleHaas, Shaft_Op1_G71G70_CutOff) {
  const Job job{"haas-01-shaft-op1.nc", "haas", "--units inch --stock 2.1x4in --tool 12=parting-3mm", true};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  // N10..N20 finished by G70 under G42: the nose follows the contour, so every
  // element is as programmed; G71 left U0.02 / W0.005 which G70 takes off.
  EXPECT_NEAR(p.d(-0.5), 0.7500, kIn);  // Z-0.0625..-1.0 cylinder X0.75
  EXPECT_NEAR(p.d(-0.03125), 0.6875,
              kIn);  // 1/16 x 45 chamfer X0.625 Z0 -> X0.75 Z-0.0625, half way: 0.625 + 2(0.03125)
  EXPECT_NEAR(p.d(-1.03125), 1.1875, kIn);  // chamfer X1.125 Z-1. -> X1.25 Z-1.0625, half way
  EXPECT_NEAR(p.d(-1.5), 1.2500, kIn);      // X1.25 to Z-2.
  // G02 X1.5 Z-2.125 R0.125 from X1.25 Z-2.: centre Z-2.0 at radius 0.75 (a
  // concave fillet, R0.125 > nose R0.0315). At Z-2.0625:
  // r = 0.75 - sqrt(0.125^2 - 0.0625^2) = 0.75 - 0.108253 = 0.641747 -> Ø1.283494.
  EXPECT_NEAR(p.d(-2.0625), 1.2835, kIn);
  EXPECT_NEAR(p.d(-2.15625), 1.9375, kIn);  // chamfer X1.875 Z-2.125 -> X2. Z-2.1875, half way
  EXPECT_NEAR(p.d(-2.5), 2.0000, kIn);      // X2. to Z-2.75
  // Left of Z-2.75 the bar is untouched: the first G71 level is X2.2 - 2(0.06)
  // = X2.08, which meets the profile (moved by U/W) on its last face at Z-2.745.
  EXPECT_NEAR(p.d(-2.9), 2.1000, kIn);
  EXPECT_NEAR(p.edge(-0.9, -1.1, 0.95), -1.0, kIn);  // shoulder face at Z-1.
  // The shoulder at Z-2.75: N20 G40 X2.2 cancels the compensation on the face
  // move, so the block before it (Z-2.75) ends with the offset perpendicular
  // to itself (the cancel rule of Fanuc/Haas nose compensation): the nose
  // centre stops at Z-2.75, radius 1.0 + R (R = 0.8 mm = 0.0314961 in), and
  // its circle reaches R past the shoulder. At Ø2.05 (radius 1.025, 0.0064961
  // below the centre) the face is at Z-2.75 - sqrt(R^2 - 0.0064961^2) = -2.780819.
  EXPECT_NEAR(p.edge(-2.6, -2.9, 2.05), -2.7808, kIn);
  EXPECT_NEAR(p.rightFace(), 0.0, kIn);  // faced at Z0 (the bar's face)
  // Cut-off: T1212 at Z-3.118 (left corner), blade 3 mm = 0.11811 in wide, fed
  // to past the centre: nothing left in [-3.118, -2.99989]; the part's
  // left face is the blade's right side, Z-3.118 + 0.11811 = -2.99989 (3.000 long).
  EXPECT_NEAR(p.d(-3.06), 0.0, kIn);
  EXPECT_NEAR(p.edge(-2.95, -3.05, 1.0), -2.9999, kIn);
}

// The same program as a teacher first runs it, without --tool: station 12 has
// no tool in tools.cfg, and the comment before T1212 ("CUT OFF AT 3.000 LONG")
// makes Klueng take the library's parting blade (note I401), its empty offset
// row the blade's R0 and tip 3 (I410) - so the cut-off lands where it did above.
TEST(RealStyleHaas, Shaft_Op1_CutOffToolFromComment) {
  const Job job{"haas-01-shaft-op1.nc", "haas", "--stock 2.1x4in", true};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.check.text.find("T12 = parting-3mm"), std::string::npos) << r.check.text;
  EXPECT_NEAR(r.part.d(-3.06), 0.0, kIn);                     // the blade's gap [-3.118, -2.99989]
  EXPECT_NEAR(r.part.edge(-2.95, -3.05, 1.0), -2.9999, kIn);  // the part is 3.000 long
  EXPECT_NEAR(r.part.d(-2.5), 2.0000, kIn);
}

// O20102: the second setup of O20101 (turned around) as its own file, G20,
// M00 between roughing and finishing, tool and spindle restated after M00.
TEST(RealStyleHaas, Shaft_Op2_SecondSetup_M00) {
  const Job job{"haas-02-shaft-op2.nc", "haas", "--units inch --stock 2.1x3in", true};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-0.015), 1.4700, kIn);  // chamfer X1.44 Z0 -> X1.5 Z-0.03 (G42): 1.44 + 2(0.015)
  EXPECT_NEAR(p.d(-0.1), 1.5000, kIn);    // X1.5 to Z-0.15
  EXPECT_NEAR(p.d(-0.165), 1.9700, kIn);  // chamfer X1.94 Z-0.15 -> X2. Z-0.18: 1.94 + 2(0.015)
  EXPECT_NEAR(p.d(-0.25), 2.0000, kIn);   // X2. Z-0.18 .. -0.3, blends into op 1's Ø2.000
  // The bar is modelled plain: left of Z-0.3 it is the Ø2.1 blank (on the real
  // part it is op 1's Ø2.000 there; the program does not cut it).
  EXPECT_NEAR(p.d(-0.6), 2.1000, kIn);
  EXPECT_NEAR(p.edge(-0.1, -0.2, 1.7), -0.15, kIn);  // face between Ø1.5 and the chamfer
  // End of the profile: N200 G40 X2.2 cancels on the face move, so (as in
  // op 1) the nose circle stops centred on Z-0.3 at radius 1.0 + R and reaches
  // past it: at Ø2.05 the face is at Z-0.3 - sqrt(R^2 - 0.0064961^2) = -0.330819.
  EXPECT_NEAR(p.edge(-0.25, -0.4, 2.05), -0.3308, kIn);
}

// O20103: one-block G75 X Z I K F relief groove, one-block G76 X Z K D A F, M24,
// G28 U0 W0 between the tools.
TEST(RealStyleHaas, Stud_3_4_10_G75Relief_G76) {
  const Job job{"haas-03-thread-3-4-10.nc", "haas", "--units inch --stock 1x3in", true};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  // 3/4-10 UNC: major turned to X0.745, thread height K0.0613 (0.6134 x pitch
  // 0.1), so the last G76 pass is at X0.745 - 2(0.0613) = X0.6224, the apex of
  // the R0 tip-8 tool on it: the root of every thread turn is Ø0.6224.
  EXPECT_NEAR(p.minD(-0.7, -0.2), 0.6224, kIn);
  // Front chamfer X0.545 Z0 -> X0.745 Z-0.1 under G42; at Z-0.02 it is
  // 0.545 + 2(0.02) = 0.585, below the thread root, so the thread leaves it.
  EXPECT_NEAR(p.d(-0.02), 0.5850, kIn);
  // G75 from Z-0.918 to Z-1. with K0.08: plunges at Z-0.918, -0.998, -1.0, the
  // 0.11811 in blade's left corner controlled: groove [-1.0, -0.79989], floor X0.6.
  EXPECT_NEAR(p.d(-0.9), 0.6000, kIn);
  // The groove's left wall is the blade's left side at Z-1. Measured at Ø0.7,
  // below the Ø0.745 the OD tool turned: above it the shoulder carries the
  // nose's cancel overcut (N2 G40 X1.1 on the face move, see haas-01).
  EXPECT_NEAR(p.edge(-0.95, -1.05, 0.7), -1.0, kIn);
  EXPECT_NEAR(p.d(-1.5), 1.0000, kIn);  // the bar, left of the shoulder
}

// O20104: one-block G72 P Q U W D F (facing passes), G70 with G41 (the tool is
// left of a path that runs down the faces), G53 G00 X0 / Z0.
TEST(RealStyleHaas, Flange_G72_G41) {
  const Job job{"haas-04-flange-g72.nc", "haas", "--units inch --stock 3x2in", true};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-0.025), 1.2000, kIn);                // chamfer X1.25 Z-0.05 -> X1.15 Z0, half way: 1.15 + 2(0.025)
  EXPECT_NEAR(p.d(-0.2), 1.2500, kIn);                  // hub X1.25 from Z-0.4 to Z-0.05
  EXPECT_NEAR(p.d(-0.6), 2.5000, kIn);                  // X2.5 from Z-0.75 to Z-0.4
  EXPECT_NEAR(p.d(-1.2), 3.0000, kIn);                  // the flange: the bar left of Z-0.75
  EXPECT_NEAR(p.edge(-0.3, -0.5, 1.875), -0.4, kIn);    // face Z-0.4 (between Ø1.25 and Ø2.5)
  EXPECT_NEAR(p.edge(-0.65, -0.85, 2.75), -0.75, kIn);  // face Z-0.75 (between Ø2.5 and Ø3.0)
  EXPECT_NEAR(p.rightFace(), 0.0, kIn);                 // the profile faces Z0 to X0
}

// O20105: tube stock, OD G71 + G70 (G42), M00, then an ID G71 with U negative
// and G70 with G41 using the boring bar.
TEST(RealStyleHaas, Bushing_Tube_OdThenBore_M00) {
  const Job job{"haas-05-bushing-tube.nc", "haas", "--units inch --stock 2.5x3x1.25in", true};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-0.025), 2.2000, kIn);  // OD chamfer X2.15 Z0 -> X2.25 Z-0.05, half way
  EXPECT_NEAR(p.d(-0.75), 2.2500, kIn);   // OD X2.25 to Z-1.5
  EXPECT_NEAR(p.d(-2.0), 2.5000, kIn);    // the tube's OD, left of Z-1.5
  // ID under G41, tip 2 R0.4 mm: the nose follows the contour.
  EXPECT_NEAR(p.inner(-0.015), 1.7800, kIn);                 // mouth chamfer X1.81 Z0 -> X1.75 Z-0.03: 1.81 - 2(0.015)
  EXPECT_NEAR(p.inner(-0.4), 1.7500, kIn);                   // bore X1.75 to Z-0.8
  EXPECT_NEAR(p.inner(-1.2), 1.5000, kIn);                   // bore X1.5 from Z-0.8 to Z-1.6
  EXPECT_NEAR(p.inner(-2.0), 1.2500, kIn);                   // the tube's own bore past Z-1.6
  EXPECT_NEAR(p.edge(-0.7, -0.9, 1.625, false), -0.8, kIn);  // step in the bore at Z-0.8
}

// O20106: one-block G73 P Q I K U W D F (D = number of passes), G28 G00 U0 W0;
// a 35 degree VNMG for the neck (an 80 degree CNMG's trailing edge would rub
// the back slope).
TEST(RealStyleHaas, Knob_G73_Vnmg) {
  const Job job{"haas-06-knob-g73.nc", "haas", "--units inch --stock 1.5x3in --tool 9=vnmg-35-r02", true};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  // G03 X1. Z-0.15 R0.15 from X0.7 Z0: centre Z-0.15 at radius 0.35 (convex).
  // At Z-0.05: r = 0.35 + sqrt(0.15^2 - 0.1^2) = 0.35 + 0.111803 -> Ø0.923607.
  EXPECT_NEAR(p.d(-0.05), 0.9236, kIn);
  EXPECT_NEAR(p.d(-0.4), 1.0000, kIn);  // X1. from Z-0.15 to Z-0.6
  // G02 X1. Z-1.2 R0.75 from X1. Z-0.6: chord 0.6, centre 0.687386 above the
  // chord's middle: Z-0.9 at radius 0.5 + 0.687386 = 1.187386 (a shallow neck).
  // Bottom at Z-0.9: r = 1.187386 - 0.75 = 0.437386 -> Ø0.874773.
  EXPECT_NEAR(p.d(-0.9), 0.8748, kIn);
  // At Z-0.75: r = 1.187386 - sqrt(0.75^2 - 0.15^2) = 1.187386 - 0.734847 -> Ø0.905078.
  EXPECT_NEAR(p.d(-0.75), 0.9051, kIn);
  EXPECT_NEAR(p.d(-1.3), 1.0000, kIn);  // X1. from Z-1.2 to Z-1.4
  EXPECT_NEAR(p.d(-1.7), 1.2500, kIn);  // X1.25 from Z-1.4 to Z-2.
  EXPECT_NEAR(p.d(-2.3), 1.5000, kIn);  // the bar
}

// The same knob without --tool: the tool list at the top, "(T9 VNMG 332 -
// 35 DEG ...)", names station 9, so the 35 degree VNMG comes from the library
// and the neck is the same as with --tool.
TEST(RealStyleHaas, Knob_ToolFromTheToolList) {
  const Job job{"haas-06-knob-g73.nc", "haas", "--units inch --stock 1.5x3in", true};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.check.text.find("T09 = vnmg-35-r02 (comment \"T9 VNMG 332"), std::string::npos) << r.check.text;
  EXPECT_NEAR(r.part.d(-0.4), 1.0000, kIn);
  EXPECT_NEAR(r.part.d(-0.9), 0.8748, kIn);
}

// O20107: CAM output (X0.42928932: more decimals than 0.0001, rounded with a
// warning), M88/M89, T1212 cut-off.
TEST(RealStyleHaas, TaperPin_CamDecimals_CutOff) {
  const Job job{"haas-07-taper-pin-cam.nc", "haas", "--units inch --stock 1.25x4in --tool 12=parting-3mm", true};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.check.text.find("W103"), std::string::npos) << "the rounding is said:\n" << r.check.text;
  const Profile& p = r.part;
  // X0.42928932 -> X0.4293, Z-0.03535534 -> Z-0.0354 (0.0001 in increments).
  // Chamfer half way (Z-0.0177): 0.4293 + (0.5 - 0.4293)/2 = 0.46465.
  EXPECT_NEAR(p.d(-0.0177), 0.4647, kIn);
  EXPECT_NEAR(p.d(-0.3), 0.5000, kIn);  // X0.5 to Z-0.5
  // Taper X0.5 Z-0.5 -> X0.75 Z-2. under G42 (exact): Ø = 0.5 + 0.25 (z0 - z)/1.5.
  EXPECT_NEAR(p.d(-0.8), 0.5500, kIn);    // 0.5 + 0.25(0.3/1.5)
  EXPECT_NEAR(p.d(-1.25), 0.6250, kIn);   // half way
  EXPECT_NEAR(p.d(-2.025), 0.9500, kIn);  // chamfer X0.9 Z-2. -> X1. Z-2.05, half way
  EXPECT_NEAR(p.d(-2.3), 1.0000, kIn);    // X1. to Z-2.8
  // Cut-off at Z-2.718 (left corner), blade 0.11811: gap [-2.718, -2.59989];
  // the pin is 2.600 long.
  EXPECT_NEAR(p.d(-2.66), 0.0, kIn);
  EXPECT_NEAR(p.edge(-2.5, -2.65, 0.5), -2.5999, kIn);
  EXPECT_NEAR(p.d(-3.0), 1.2500, kIn);  // the bar left of the profile's end at Z-2.8
}

// O20108: an old shop program without nose compensation (G40 throughout) and
// the Haas park `G00 G53 X0 Z-2.` at the end.
// The park rapided through the part (A301) while G53 was read as work
// coordinates; fixed on main in 2268fb4 (README.md, "What the programs found").
const Job kGuidePin{"haas-08-no-comp-chamfer.nc", "haas", "--units inch --stock 1.5x3in", true};

// The whole program, park included.
TEST(RealStyleHaas, GuidePin_ParkG53G00) {
  const Job& job = kGuidePin;
  RUN_CLEAN(job, r);
  EXPECT_NEAR(r.part.d(-0.5), 1.0000, kIn);
}

// The part, finished before the park.
TEST(RealStyleHaas, GuidePin_NoNoseComp) {
  const Job& job = kGuidePin;
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  // Tip 3, R = 0.8 mm = 0.0314961 in, G40: the imaginary tip follows the path.
  // Cylinders and faces are touched by the imaginary tip's two tangents: exact.
  EXPECT_NEAR(p.d(-0.5), 1.0000, kIn);
  EXPECT_NEAR(p.d(-1.4), 1.2000, kIn);
  EXPECT_NEAR(p.d(-2.0), 1.5000, kIn);  // the bar
  // A line at angle t to the Z axis rising towards the chuck: the nose centre
  // is R(1,1) from the imaginary tip, so the cut line lies
  // R(sin t + cos t - 1) off the programmed one, i.e. R(1 + tan t - 1/cos t)
  // more radius at a given Z.
  // 45 degree chamfer X0.8 Z0 -> X1. Z-0.1: R(2 - sqrt 2) = 0.0184500 in on the
  // radius; half way (Z-0.05) the program says Ø0.9, the part is
  // 0.9 + 2(0.0184500) = 0.9369.
  EXPECT_NEAR(p.d(-0.05), 0.9369, kIn);
  // Taper X1. Z-0.8 -> X1.2 Z-1.2, tan t = 0.1/0.4 = 0.25, 1/cos t = 1.0307764:
  // R(0.2192236) = 0.0069047 in; half way (Z-1.0) Ø1.1 + 0.0138 = 1.1138.
  EXPECT_NEAR(p.d(-1.0), 1.1138, kIn);
}

// O20109: G76 to a shoulder with M23 (thread chamfer out), a wide G75 groove
// stepped by K, G53 safe lines.
// The thread tool parked by `G53 G00 Z0` started inside the stock (A301) while G53
// was read as work coordinates; fixed on main in 2268fb4.
const Job kPumpShaft{"haas-09-thread-1-8-chamfer.nc", "haas", "--units inch --stock 1.25x3in", true};

// The whole program: the thread is cut after the second G53 park.
TEST(RealStyleHaas, PumpShaft_1_8_M23_Thread) {
  const Job& job = kPumpShaft;
  RUN_CLEAN(job, r);
  // 1-8 UNC: major X0.995, K = 0.6134/8 = 0.0767, last pass X0.995 - 0.1534 = X0.8416.
  EXPECT_NEAR(r.part.minD(-0.8, -0.2), 0.8416, kIn);
}

// The OD and the groove, finished before the park.
TEST(RealStyleHaas, PumpShaft_WideGroove) {
  const Job& job = kPumpShaft;
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-1.4), 1.2000, kIn);  // X1.2 from Z-1.2 to Z-2.3, right of the groove
  // G75 X0.9 Z-2. from Z-1.718, K0.1: plunges at -1.718, -1.818, -1.918, -2.0;
  // groove [-2.0, -1.718 + 0.11811 = -1.59989], floor X0.9.
  EXPECT_NEAR(p.d(-1.8), 0.9000, kIn);
  EXPECT_NEAR(p.edge(-1.9, -2.1, 1.05), -2.0, kIn);
  EXPECT_NEAR(p.edge(-1.7, -1.5, 1.05), -1.5999, kIn);
  EXPECT_NEAR(p.d(-2.2), 1.2000, kIn);  // left of the groove
  EXPECT_NEAR(p.d(-2.6), 1.2500, kIn);  // the bar, left of Z-2.3
}

// O20110: G20, convex and concave R arcs in a G71 profile, a plunge groove with
// G04 P0.5 (Haas: P with a point is seconds), G28 G00 U0 W0.
TEST(RealStyleHaas, SteppedSpindle_Radii_Dwell) {
  const Job job{"haas-10-steps-radii-dwell.nc", "haas", "--units inch --stock 2x4in", true};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  // G03 X0.5 Z-0.06 R0.06 from X0.38 Z0: centre Z-0.06 at radius 0.19. At Z-0.02:
  // r = 0.19 + sqrt(0.06^2 - 0.04^2) = 0.19 + 0.044721 -> Ø0.469443.
  EXPECT_NEAR(p.d(-0.02), 0.4694, kIn);
  EXPECT_NEAR(p.d(-0.3), 0.5000, kIn);      // X0.5 to Z-0.5
  EXPECT_NEAR(p.d(-0.53125), 0.9375, kIn);  // chamfer X0.875 Z-0.5 -> X1. Z-0.5625, half way
  EXPECT_NEAR(p.d(-1.0), 1.0000, kIn);      // X1. to Z-1.25
  // G02 X1.25 Z-1.375 R0.125: centre Z-1.25 at radius 0.625 (concave). At Z-1.3125:
  // r = 0.625 - sqrt(0.125^2 - 0.0625^2) = 0.625 - 0.108253 -> Ø1.033494.
  EXPECT_NEAR(p.d(-1.3125), 1.0335, kIn);
  // G03 X1.875 Z-1.5 R0.125 from X1.625 Z-1.375: centre Z-1.5 at radius 0.8125
  // (convex). At Z-1.4375: r = 0.8125 + 0.108253 -> Ø1.841506.
  EXPECT_NEAR(p.d(-1.4375), 1.8415, kIn);
  EXPECT_NEAR(p.d(-1.7), 1.8750, kIn);  // X1.875 to Z-2.5
  // Groove: T404 left corner at Z-2., plunged to X1.6: [-2.0, -1.88189], floor Ø1.6.
  EXPECT_NEAR(p.d(-1.94), 1.6000, kIn);
  EXPECT_NEAR(p.edge(-1.8, -1.94, 1.7), -1.8819, kIn);
  EXPECT_NEAR(p.d(-2.3), 1.8750, kIn);
  EXPECT_NEAR(p.d(-2.8), 2.0000, kIn);  // the bar
}

// O20111: first setup of a spacer: face, G71/G70 spigot, M00, T1212 cut-off.
TEST(RealStyleHaas, Spacer_Op1_CutOff) {
  const Job job{"haas-11-spacer-op1.nc", "haas", "--units inch --stock 2x3in --tool 12=parting-3mm", true};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-0.015), 1.4700, kIn);  // chamfer X1.44 Z0 -> X1.5 Z-0.03, half way
  EXPECT_NEAR(p.d(-0.4), 1.5000, kIn);    // spigot X1.5 to Z-0.75
  EXPECT_NEAR(p.d(-0.765), 1.9700, kIn);  // chamfer X1.94 Z-0.75 -> X2. Z-0.78, half way
  EXPECT_NEAR(p.d(-1.0), 2.0000, kIn);    // the bar's own Ø2.0
  EXPECT_NEAR(p.edge(-0.7, -0.8, 1.7), -0.75, kIn);
  // Cut-off at Z-1.418 (left corner): gap [-1.418, -1.29989]; 1.300 long blank for op 2.
  EXPECT_NEAR(p.d(-1.36), 0.0, kIn);
  EXPECT_NEAR(p.edge(-1.2, -1.35, 1.0), -1.2999, kIn);
}

// O20112: second setup of the spacer: face, chamfer with a G42 start-up on a
// G01 block, G83 drilling on centre and G80.
TEST(RealStyleHaas, Spacer_Op2_SecondSetup_G83) {
  const Job job{"haas-12-spacer-op2.nc", "haas", "--units inch --stock 2x1.3in", true};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-0.03), 1.9400, kIn);  // chamfer X1.88 Z0 -> X2. Z-0.06 (G42), half way
  EXPECT_NEAR(p.d(-0.5), 2.0000, kIn);
  // T606: the Ø10 mm drill (0.3937 in), point controlled, to Z-0.5 in Q0.125 pecks.
  EXPECT_NEAR(p.inner(-0.2), 10.0 / kMmPerIn, kIn);
  EXPECT_NEAR(p.inner(-0.8), 0.0, kIn);  // solid past the drill point
  EXPECT_NEAR(p.rightFace(), 0.0, kIn);
}

// O20113: one-block G71 with a P block naming X and Z (the manual's type 2): the
// profile dips into a Ø0.8 relief neck between two Ø1.0 lands, which a type 1
// profile cannot; the 35 degree VNMG reaches it; G70 under G42.
TEST(RealStyleHaas, NeckShaft_G71Type2_Pocket) {
  const Job job{"haas-13-neck-type2.nc", "haas", "--units inch --stock 1.5x3in --tool 9=vnmg-35-r02", true};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-0.3), 1.0000, kIn);   // X1. from Z-0.05 to Z-0.6
  EXPECT_NEAR(p.d(-0.95), 0.8000, kIn);  // the neck X0.8 from Z-0.8 to Z-1.1
  EXPECT_NEAR(p.d(-1.4), 1.0000, kIn);   // X1. from Z-1.2 to Z-1.6
  EXPECT_NEAR(p.d(-1.9), 1.4000, kIn);   // X1.4 to Z-2.2
  EXPECT_NEAR(p.d(-2.5), 1.5000, kIn);   // the bar
  // The neck's walls, half way down: X1. Z-0.6 -> X0.8 Z-0.8 reaches Ø0.9 at Z-0.7,
  // X0.8 Z-1.1 -> X1. Z-1.2 at Z-1.15 (G42: exact).
  EXPECT_NEAR(p.edge(-0.6, -0.8, 0.9), -0.7, kIn);
  EXPECT_NEAR(p.edge(-1.1, -1.2, 0.9), -1.15, kIn);
  EXPECT_NEAR(p.edge(-1.5, -1.7, 1.2), -1.6, kIn);  // the Ø1.4 shoulder
}

// O20114: the shop habit of ending the G71 profile where it reached the start's
// X (X1.3) and retracting along Z over the bar with the G40 block
// (`N20 G00 G40 Z0.1`); the P block `G00 G42 X-0.0625 Z0.1` names X and Z. The
// retract lies at the start's level, outside the stock: the control runs it.
TEST(RealStyleHaas, LocatingPin_G71ProfileEndsWithARetract) {
  const Job job{"haas-17-pin-g71-retract.nc", "haas", "--units inch --stock 1.25x3in", true};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  // G70 under G42 (T01 R0.8 tip 3): the nose follows the contour exactly.
  EXPECT_NEAR(p.d(-0.01875), 0.5875, kIn);  // chamfer X0.55 Z0 -> X0.625 Z-0.0375, half way
  EXPECT_NEAR(p.d(-0.5), 0.6250, kIn);      // X0.625 to Z-0.9
  EXPECT_NEAR(p.d(-1.05), 0.7875, kIn);     // taper X0.625 Z-0.9 -> X0.95 Z-1.2, half way
  EXPECT_NEAR(p.d(-1.5), 0.9500, kIn);      // X0.95 from Z-1.2 to Z-1.75
  EXPECT_NEAR(p.d(-2.0), 1.2500, kIn);      // the bar, left of the Z-1.75 face
  // The face X0.95 -> X1.3 at Z-1.75: the compensated face is exact below the
  // cancel (N20 G40 leaves the offset perpendicular to the face, along Z).
  EXPECT_NEAR(p.edge(-1.6, -1.9, 1.1), -1.75, kIn);
  EXPECT_NEAR(p.rightFace(), 0.0, kIn);  // G01 Z0. then across the centre (X-0.0625)
}

// O20115: the same habit in a metric Haas program (G21), with a concave R4
// fillet in the profile; the retract `N200 G00 G40 Z2.` is at the start's X42.
TEST(RealStyleHaas, MetricSpigot_G71ProfileEndsWithARetract) {
  const Job job{"haas-18-metric-g71-retract.nc", "haas", "--stock 40x80", false};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-1.0), 22.000, kMm);   // chamfer X20. Z0 -> X24. Z-2., half way
  EXPECT_NEAR(p.d(-10.0), 24.000, kMm);  // X24. to Z-25.
  // G02 X32. Z-29. R4. from X24. Z-25.: a concave fillet, centre Z-25. at
  // radius 16; at Z-27.: r = 16 - sqrt(4^2 - 2^2) = 12.535898 -> Ø25.0718.
  EXPECT_NEAR(p.d(-27.0), 25.0718, kMm);
  EXPECT_NEAR(p.d(-35.0), 36.000, kMm);                 // X36. from Z-29. to Z-45.
  EXPECT_NEAR(p.d(-50.0), 40.000, kMm);                 // the bar, left of Z-45.
  EXPECT_NEAR(p.edge(-40.0, -50.0, 38.0), -45.0, kMm);  // the Z-45. face
  EXPECT_NEAR(p.rightFace(), 0.0, kMm);
}

// ============================================================================
// Fanuc 0T / 0i-TF programs, mm.
// ============================================================================

// :0100 packed words, G28 U0 W0, tool change at X380. Z300. with M16 (a
// machine-specific M code: a warning), two-block G71 U R / G71 P Q U W F,
// G42 on the approach before G70.
TEST(RealStyleFanuc, Shaft_Packed_G71G70) {
  const Job job{"fanuc-01-shaft-packed.nc", "fanuc", "--stock 50x100", false};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-1.0), 22.0, kMm);   // chamfer X20. Z0 -> X24. Z-2., half way
  EXPECT_NEAR(p.d(-10.0), 24.0, kMm);  // X24. to Z-20.
  EXPECT_NEAR(p.d(-27.5), 33.0, kMm);  // taper X30. Z-20. -> X36. Z-35., half way (G42: exact)
  EXPECT_NEAR(p.d(-42.0), 36.0, kMm);  // X36. to Z-50.
  // G2 X44. Z-54. R4. from X36. Z-50.: centre Z-50. at radius 22 (concave). At Z-52.:
  // r = 22 - sqrt(16 - 4) = 22 - 3.464102 -> Ø37.071797.
  EXPECT_NEAR(p.d(-52.0), 37.0718, kMm);
  EXPECT_NEAR(p.d(-60.0), 50.0, kMm);  // the bar (X52. is above it)
  EXPECT_NEAR(p.edge(-19.0, -21.0, 27.0), -20.0, kMm);
  EXPECT_NEAR(p.edge(-53.0, -55.0, 48.0), -54.0, kMm);
}

// :0200 all lowercase, two-block G72 W R / G72 P Q U W F, G41 before G70.
TEST(RealStyleFanuc, Flange_Lowercase_G72) {
  const Job job{"fanuc-02-flange-g72-lower.nc", "fanuc", "--stock 100x50", false};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-1.0), 48.0, kMm);    // chamfer x50. z-2. -> x46. z0., half way
  EXPECT_NEAR(p.d(-6.0), 50.0, kMm);    // hub x50. from z-12. to z-2.
  EXPECT_NEAR(p.d(-16.0), 80.0, kMm);   // x80. from z-20. to z-12.
  EXPECT_NEAR(p.d(-30.0), 100.0, kMm);  // the bar
  EXPECT_NEAR(p.edge(-11.0, -13.0, 65.0), -12.0, kMm);
  EXPECT_NEAR(p.edge(-19.0, -21.0, 90.0), -20.0, kMm);
  EXPECT_NEAR(p.rightFace(), 0.0, kMm);
}

// O0300 two-block G73 U W R / G73 P Q U W F (R = divisions), G42 before G70;
// the 35 degree VNMG for the neck.
TEST(RealStyleFanuc, Knob_G73_Vnmg) {
  const Job job{"fanuc-03-knob-g73.nc", "fanuc", "--stock 40x90 --tool 9=vnmg-35-r02", false};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  // G03 X24. Z-5. R5. from X14. Z0.: centre Z-5. at radius 7. At Z-2.:
  // r = 7 + sqrt(25 - 9) = 11 -> Ø22.
  EXPECT_NEAR(p.d(-2.0), 22.0, kMm);
  EXPECT_NEAR(p.d(-12.0), 24.0, kMm);  // X24. from Z-5. to Z-20.
  // G02 X24. Z-40. R25. from X24. Z-20.: chord 20, centre sqrt(625 - 100) =
  // 22.912878 above its middle: Z-30. at radius 34.912878.
  EXPECT_NEAR(p.d(-30.0), 19.8258, kMm);  // 2(34.912878 - 25)
  EXPECT_NEAR(p.d(-25.0), 20.8360, kMm);  // 2(34.912878 - sqrt(625 - 25)) = 2(34.912878 - 24.494897)
  EXPECT_NEAR(p.d(-45.0), 24.0, kMm);     // X24. from Z-40. to Z-50.
  EXPECT_NEAR(p.d(-55.0), 36.0, kMm);     // X36. from Z-50. to Z-60.
  EXPECT_NEAR(p.d(-70.0), 40.0, kMm);     // the bar
}

// O0400 G90 box cycles (modal X), finishing with G42, two-block G75 R / G75 X Z P Q F
// relief groove, two-block G76 P(m r a) Q R / G76 X Z P Q F thread M24x2.
TEST(RealStyleFanuc, BoltM24_G90_G75_G76) {
  const Job job{"fanuc-04-m24-groove-thread.nc", "fanuc", "--stock 30x80", false};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  // M24x2: h = 0.6134 x 2 = 1.227 (P1227), root X24 - 2(1.227) = X21.546: the
  // last pass puts the tip-8 tool's apex on it along the whole thread.
  EXPECT_NEAR(p.minD(-24.0, -4.0), 21.546, kMm);
  // G75 from Z-29. to Z-30. (Q1000 = 1 mm shift): blade [-30, -26], floor X20.
  EXPECT_NEAR(p.d(-28.0), 20.0, kMm);
  EXPECT_NEAR(p.edge(-29.0, -31.0, 24.0), -30.0, kMm);  // left wall = the Ø28 shoulder
  EXPECT_NEAR(p.edge(-27.0, -25.0, 20.8), -26.0, kMm);  // right wall, where the thread ends (G76 Z-26.)
  EXPECT_NEAR(p.d(-38.0), 28.0, kMm);                   // X28. from Z-30. to Z-45.
  EXPECT_NEAR(p.d(-55.0), 30.0, kMm);                   // the bar
}

// :0500 ID work on tube stock Ø118/Ø90 x 80 (--stock 118x80x90): two-block G71
// with U negative, G41 on the approach, boring bar tip 2.
TEST(RealStyleFanuc, BearingHousing_Tube_BoreG71) {
  const Job job{"fanuc-05-bore-tube-g71.nc", "fanuc", "--stock 118x80x90", false};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.inner(-0.5), 101.0, kMm);   // mouth chamfer X102. Z0. -> X100. Z-1., half way
  EXPECT_NEAR(p.inner(-12.0), 100.0, kMm);  // X100. to Z-25.
  EXPECT_NEAR(p.inner(-40.0), 95.0, kMm);   // X95. from Z-25. to Z-50.
  EXPECT_NEAR(p.inner(-60.0), 90.0, kMm);   // the tube's bore
  EXPECT_NEAR(p.d(-40.0), 118.0, kMm);      // OD untouched
  EXPECT_NEAR(p.edge(-24.0, -26.0, 97.5, false), -25.0, kMm);
  EXPECT_NEAR(p.edge(-49.0, -51.0, 92.5, false), -50.0, kMm);
}

// O0600 a CAM post: separated words, G28 U0. / G28 W0. on their own lines,
// 8-decimal coordinates (rounded to 0.001 mm with a warning), G71/G70.
TEST(RealStyleFanuc, TaperShaft_CamDecimals) {
  const Job job{"fanuc-06-cam-g71.nc", "fanuc", "--stock 40x90", false};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.check.text.find("W103"), std::string::npos) << "the rounding is said:\n" << r.check.text;
  const Profile& p = r.part;
  // X24.34314575 -> X24.343, Z-1.82842712 -> Z-1.828: chamfer of slope 1 on the
  // radius, at Z-0.9: 24.343 + 2(0.9) = 26.143.
  EXPECT_NEAR(p.d(-0.9), 26.143, kMm);
  EXPECT_NEAR(p.d(-10.0), 28.0, kMm);  // X28. to Z-20.
  // 30 degree taper X28. Z-20. -> X34.92820323 (34.928) Z-26.: 6 tan 30 = 3.4641
  // on the radius; at Z-23.: 28 + 2(3 tan 30) = 31.4641.
  EXPECT_NEAR(p.d(-23.0), 31.4641, kMm);
  EXPECT_NEAR(p.d(-33.0), 34.928, kMm);
  EXPECT_NEAR(p.d(-50.0), 40.0, kMm);  // the bar
}

// O0700 packed: G94 facing in two passes (the blank's face comes off 2 mm),
// G83 peck drilling on centre with R incremental (Fanuc), G80.
TEST(RealStyleFanuc, Blank_G94Face_G83Drill) {
  const Job job{"fanuc-07-face-drill-packed.nc", "fanuc", "--stock 50x100", false};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  // G94 Z-1. then Z-2.: the face is at Z-2. (the imaginary tip of the
  // R0.8 tip-3 tool on Z-2.; takes the nose centre to the axis).
  EXPECT_NEAR(p.rightFace(), -2.0, kMm);
  EXPECT_NEAR(p.d(-20.0), 50.0, kMm);
  // G83 Z-27. R-2. Q5000 from Z3.: R point Z1., 5 mm pecks to Z-27.; Ø10 drill.
  EXPECT_NEAR(p.inner(-12.0), 10.0, kMm);
  EXPECT_NEAR(p.inner(-35.0), 0.0, kMm);  // solid past the point
}

// :0800 nut on tube stock Ø60/Ø30 x 40: G71 ID, G70 with G41, internal
// two-block G76 (X increases towards the root).
TEST(RealStyleFanuc, NutM36x1_5_Tube_InternalG76) {
  const Job job{"fanuc-08-nut-internal-thread.nc", "fanuc", "--stock 60x40x30", false};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  // Bore X34.376 (M36x1.5 minor = 36 - 2(0.812)); G76 X36. P812: the last pass
  // puts the tip-6 tool's apex on Ø36, the root of the internal thread.
  EXPECT_NEAR(p.maxInner(-24.0, -4.0), 36.0, kMm);
  EXPECT_NEAR(p.inner(-0.3), 36.776, kMm);   // mouth chamfer X37.376 Z0. -> X34.376 Z-1.5: 37.376 - 2(0.3)
  EXPECT_NEAR(p.inner(-28.0), 34.376, kMm);  // bore past the thread's end (Z-26.)
  EXPECT_NEAR(p.inner(-35.0), 30.0, kMm);    // the tube's bore past Z-30.
  EXPECT_NEAR(p.edge(-29.0, -31.0, 32.0, false), -30.0, kMm);
  EXPECT_NEAR(p.d(-20.0), 60.0, kMm);
}

// O0900 two-block G71 type II (the first profile block names X and W0): a
// round-bottomed pocket G02 X24. Z-30. R15. between Ø24 lands, roughed level by
// level and finished by G70 under G42 with the 35 degree VNMG.
TEST(RealStyleFanuc, Handle_G71TypeII_ArcPocket) {
  const Job job{"fanuc-09-handle-type2.nc", "fanuc", "--stock 40x90 --tool 9=vnmg-35-r02", false};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-1.0), 22.0, kMm);  // chamfer X20. Z0 -> X24. Z-2., half way
  EXPECT_NEAR(p.d(-5.0), 24.0, kMm);  // X24. to Z-10.
  // The arc: chord 20, R15, centre sqrt(225 - 100) = 11.180340 above its middle:
  // Z-20. at radius 12 + 11.180340. At Z-20.: 2(23.180340 - 15) = 16.360680;
  // at Z-15.: 2(23.180340 - sqrt(225 - 25)) = 2(23.180340 - 14.142136) = 18.076409.
  EXPECT_NEAR(p.d(-20.0), 16.3607, kMm);
  EXPECT_NEAR(p.d(-15.0), 18.0764, kMm);
  EXPECT_NEAR(p.d(-25.0), 18.0764, kMm);
  EXPECT_NEAR(p.d(-33.0), 24.0, kMm);  // X24. from Z-30. to Z-36.
  EXPECT_NEAR(p.edge(-35.0, -37.0, 30.0), -36.0, kMm);
  EXPECT_NEAR(p.d(-45.0), 36.0, kMm);  // X36. to Z-50.
  EXPECT_NEAR(p.d(-70.0), 40.0, kMm);  // the bar
}

// ============================================================================
// Issue 26: the shop's tools, not the classroom turret. These files have no job
// header, so every station's tool comes from the program's evidence and the
// shipped tools.cfg only breaks ties; no --tool is given.
// ============================================================================

// O30414: T202 with no comment, a Haas G75 groove. The shipped station 2 is the
// left-hand turning tool; the G75 makes it the library's 3 mm grooving blade
// (I404) with its own R0 and tip 3 (I411, not row 02's R0.8 tip 4).
TEST(RealStyleShopTools, Haas_T202Groove_G75) {
  const Job job{"haas-14-pin-grooves-t202.nc", "haas", "--stock 1x3in", true};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.check.text.find(":20:1: note I404: T02 = grooving-3mm (grooving cycle G75 on line 20)"),
            std::string::npos)
      << r.check.text;
  EXPECT_NE(r.check.text.find("note I411: offset 02 held R0.8 tip 4"), std::string::npos) << r.check.text;
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-0.2), 0.875, kIn);  // G71 U0 W0: the profile X0.875 to Z-1.5
  EXPECT_NEAR(p.d(-1.0), 0.875, kIn);
  EXPECT_NEAR(p.d(-2.0), 1.000, kIn);  // the bar
  // The blade's left corner goes from Z-0.5 to Z-0.6 (K0.08 shifts, then the
  // last at Z-0.6), 3 mm = 0.11811 in wide: the groove is Ø0.7 over
  // [-0.6, -0.5 + 0.11811 = -0.38189].
  EXPECT_NEAR(p.d(-0.55), 0.700, kIn);
  EXPECT_NEAR(p.d(-0.39), 0.700, kIn);
  EXPECT_NEAR(p.edge(-0.3, -0.45, 0.8), -0.3819, kIn);
  EXPECT_NEAR(p.edge(-0.7, -0.55, 0.8), -0.6, kIn);
}

// O30415: T2 finishes a long pin along -Z to 0.6 in from the jaws. The shipped
// left-hand tool's body would reach into the chuck (A304); a G70 toward the
// chuck wants a right-hand finishing tool: cnmg-80-r04 (I408).
TEST(RealStyleShopTools, Haas_T2FinishesTowardTheChuck) {
  const Job job{"haas-15-long-pin-t2-finish.nc", "haas", "--stock 1.25x6in", true};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.check.text.find(":18:1: note I408: T02 = cnmg-80-r04 (outside turning, G70 on line 18)"),
            std::string::npos)
      << r.check.text;
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-0.5), 0.900, kIn);  // G70 with G40: the imaginary tip on X0.9 from Z0 to Z-5.
  EXPECT_NEAR(p.d(-4.9), 0.900, kIn);
  EXPECT_NEAR(p.edge(-4.8, -5.2, 1.0), -5.0, kIn);
  EXPECT_NEAR(p.d(-5.5), 1.250, kIn);  // the bar up to the jaws
}

// O2010: a ring bored with hand-written G01 passes by T0202, each pass left by
// a small move inward (X43. after Z-20. at X44.): a boring bar (I406).
TEST(RealStyleShopTools, Fanuc_T0202BoresByHand) {
  const Job job{"fanuc-10-ring-hand-bored.nc", "fanuc", "--stock 80x50x40", false};
  RUN_CLEAN(job, r);
  EXPECT_NE(
      r.check.text.find(":8:1: note I406: T02 = boring-bar-16 (cutting inside a bore, N6 G01 Z-20. F0.15 on line 8)"),
      std::string::npos)
      << r.check.text;
  const Profile& p = r.part;
  EXPECT_NEAR(p.inner(-10.0), 50.0, kMm);  // last pass X50. to Z-20. (tip 2 with G40: exact)
  EXPECT_NEAR(p.inner(-19.0), 50.0, kMm);
  EXPECT_NEAR(p.inner(-20.5), 40.0, kMm);  // nothing cut past the passes' Z-20.
  EXPECT_NEAR(p.inner(-30.0), 40.0, kMm);  // the tube's own bore
  EXPECT_NEAR(p.d(-10.0), 80.0, kMm);
}

// A hobby-lathe file: lowercase words, no % or O, the tool beyond the centre
// (x-30.5), facing twice toward X0 at G98 60 mm/min. The tools work at X < 0
// (I412) and are mirrored there, so the holder never crosses the part.
TEST(RealStyleShopTools, Fanuc_FacingBeyondTheCentre) {
  const Job job{"fanuc-11-face-beyond-centre.nc", "fanuc", "--stock 30x50", false};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.check.text.find(":4:1: note I412: the program cuts at X < 0 (from line 4)"), std::string::npos)
      << r.check.text;
  EXPECT_EQ(r.simulate.text.find("W324"), std::string::npos) << r.simulate.text;
  const Profile& p = r.part;
  EXPECT_NEAR(p.edge(-1.5, -2.5, 20.0), -2.0, kMm);  // faced at z-2 (tip 3, G40: the face is the programmed Z)
  EXPECT_NEAR(p.d(-10.0), 30.0, kMm);
}

// O30416: the Haas habit of ending a G71 profile with a retract above the bar
// (X1.35 = the start's X, then N20 G00 G40 Z0.1): it cuts nothing and the
// control runs it (no A121). T02's "(FINISHING)" line says finishing, the tool
// list says "35*": the 35 degree VNMG (I401).
TEST(RealStyleShopTools, Haas_G71ProfileEndsWithARetract) {
  const Job job{"haas-16-pin-g71-retract.nc", "haas", "--stock 1.25x3in", true};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.check.text.find(":24:1: note I401: T02 = vnmg-35-r02 (comment \"FINISHING\" on line 24)"),
            std::string::npos)
      << r.check.text;
  const Profile& p = r.part;
  // G70 under G42: every element as programmed.
  EXPECT_NEAR(p.d(-0.25), 0.600, kIn);
  EXPECT_NEAR(p.d(-0.575), 0.750, kIn);  // chamfer X0.6 Z-0.5 -> X0.9 Z-0.65, half way
  EXPECT_NEAR(p.d(-1.0), 0.900, kIn);
  EXPECT_NEAR(p.edge(-1.1, -1.3, 1.1), -1.2, kIn);
  EXPECT_NEAR(p.d(-2.0), 1.250, kIn);  // the bar
  EXPECT_NEAR(p.rightFace(), 0.0, kIn);
}

}  // namespace

namespace {

// Issue 26 item 6, decimal point input. A production habit: the cycle words
// without a decimal point (G71 U1250 R50, G76 P021060 Q40 R10 / P0427 Q120),
// every position with one. Read whole, U1250 is a 1250 in depth of cut; a
// standard Fanuc reads it in least input increments: 0.1250 in depth, 0.0050
// in retract, 0.0010 in thread finishing allowance (Fanuc 0i-TF parameter
// 3401#0 DPI = 0). The program's numbers decide it (note I103).
TEST(RealStyleDecimalPoint, Fanuc_InchCycleWordsInIncrements) {
  const Job job{"fanuc-12-inch-bushing-pointless.nc", "fanuc", "--stock 1.75x3.5in", true};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.check.text.find(":11:5: note I103: lengths without a decimal point are read in least input increments "
                              "(0.001 mm, 0.0001 in), as a standard Fanuc or Haas reads them: U1250 on line 11 is "
                              "0.1250 in"),
            std::string::npos)
      << r.check.text;
  EXPECT_EQ(r.check.text.find("W11"), std::string::npos) << r.check.text;
  const Profile& p = r.part;
  // The thread: G76 X1.1647 with the 60 degree tool's apex controlled, so the root is X1.1647,
  // from Z.25 to Z-1.25 less the R10 pull-out (1.0 lead = 0.0769 in).
  EXPECT_NEAR(p.minD(-0.9, -0.3), 1.1647, kIn);
  EXPECT_NEAR(p.d(-1.4), 1.250, kIn);  // Z-1.25 to Z-1.5: G70's Ø1.25, past the thread
  EXPECT_NEAR(p.d(-2.0), 1.600, kIn);  // X1.6 to Z-2.25
  EXPECT_NEAR(p.d(-2.5), 1.750, kIn);  // the bar
  EXPECT_NEAR(p.edge(-2.0, -2.5, 1.7), -2.25, kIn);
}

// The same file read whole (--decimal-point whole, a calculator-type control):
// the depth of cut is 1250 in, out of the Fanuc range (E110 at the word), and
// each word the other reading explains gets W111 with that reading.
TEST(RealStyleDecimalPoint, Fanuc_ReadWholeTheCycleWordsAreRefused) {
  const Output out = runCli("check " + quote(kPrograms + "/fanuc-12-inch-bushing-pointless.nc") +
                            " --dialect fanuc --decimal-point whole --config " + quote(kShipped));
  EXPECT_EQ(out.exitCode, 1) << out.text;
  EXPECT_NE(out.text.find(":11:5: error E110: U1250 is out of range"), std::string::npos) << out.text;
  EXPECT_NE(out.text.find(":11:11: warning W111: R50 has no decimal point and is read as 50 in (calculator-type "
                          "input); a control with standard decimal point input reads it as 0.0050 in: if that is "
                          "meant, write R0.0050"),
            std::string::npos)
      << out.text;
  EXPECT_NE(out.text.find(":25:17: warning W111: R10 "), std::string::npos) << out.text;
  EXPECT_EQ(out.text.find("I103"), std::string::npos) << out.text;
  const Output bad = runCli("check " + quote(kPrograms + "/fanuc-12-inch-bushing-pointless.nc") +
                            " --decimal-point 3401 --config " + quote(kShipped));
  EXPECT_EQ(bad.exitCode, 2) << bad.text;
  EXPECT_NE(bad.text.find("bad value '3401' for --decimal-point; allowed: whole or increments"), std::string::npos)
      << bad.text;
}

// A Haas CAM post that writes the G71 allowances without a point (U400 W100 =
// 0.4 and 0.1 mm, Haas setting 162 off) and a hand-edited retract `X60` meant
// as 60 mm: read in increments it is X0.060, so W110 says to write X60.; the
// rapid to X0.06 Z5. stays in front of the face and the part is as programmed.
TEST(RealStyleDecimalPoint, Haas_MetricAllowancesInIncrementsAndAStrayWholeWord) {
  const Job job{"haas-19-metric-pointless-allowance.nc", "haas", "--stock 36x70", false};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.check.text.find(":12:15: note I103: "), std::string::npos) << r.check.text;
  EXPECT_NE(r.check.text.find("U400 on line 12 is 0.400 mm"), std::string::npos) << r.check.text;
  EXPECT_NE(r.check.text.find(":24:5: warning W110: X60 has no decimal point: this machine reads a length without "
                              "one in least input increments, so it is 0.060 mm; write X60. for 60 mm"),
            std::string::npos)
      << r.check.text;
  const Profile& p = r.part;
  // G70 under G42: every element as programmed; a 0.4 mm allowance read whole
  // would have been 400 mm and left the bar uncut.
  EXPECT_NEAR(p.d(-10.0), 20.0, kMm);
  EXPECT_NEAR(p.d(-27.0), 30.0, kMm);
  EXPECT_NEAR(p.d(-50.0), 36.0, kMm);
  EXPECT_NEAR(p.d(-1.0), 18.0, kMm);  // chamfer X16. Z0 -> X20. Z-2., half way
  EXPECT_NEAR(p.edge(-25.0, -36.0, 33.0), -35.0, kMm);
  EXPECT_NEAR(p.rightFace(), 0.0, kMm);
}

// ============================================================================
// What the control stops on, and what it reads on (issue 38): programs in the
// habits of production shops and labs whose lathes ran them.
// ============================================================================

// O4410: an inch production op with the safety line G18G20G40G80G90G99 before
// each tool (G90 alone selects the turning cycle and moves nothing: W112, not
// the E140 it was), T0101G54, G50S2500, and a G92 thread cycle with its end point.
TEST(RealStyleControlReading, Fanuc_InchSafetyLinesRunAsOnTheLathe) {
  const Job job{"fanuc-13-inch-safety-lines.nc", "fanuc", "--units inch --stock 2x3in", true};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.check.text.find(":7:13: warning W112: G90 is a single cycle"), std::string::npos) << r.check.text;
  EXPECT_NE(r.check.text.find(":26:13: warning W112: "), std::string::npos) << r.check.text;
  EXPECT_EQ(r.check.text.find("I102"), std::string::npos) << "no other machine is offered:\n" << r.check.text;
  const Profile& p = r.part;
  // T01 under G40 (tip 3): cylinders and faces exact.
  EXPECT_NEAR(p.d(-0.80), 1.85, kIn);          // X1.85 to Z-.9, left by the X1.5 pass that stops at Z-.7
  EXPECT_NEAR(p.d(-0.65), 1.50, kIn);          // X1.5 from the thread's end (Z-.6) to Z-.7
  EXPECT_NEAR(p.d(-1.20), 2.00, kIn);          // the bar behind Z-.9
  EXPECT_NEAR(p.minD(-0.5, -0.1), 1.42, kIn);  // G92's last pass X1.42 (T03, apex controlled)
  EXPECT_NEAR(p.rightFace(), 0.0, kIn);        // faced at Z0.
}

// O0314: a mill habit in the safety line (G21G40G49G54G80G90: G49 is read and
// does nothing) and a bar puller at the end, G1 into the bar at X0 with the
// spindle stopped (M5): not a cut, no A302, no hole in the part.
TEST(RealStyleControlReading, Fanuc_G49SafetyLineAndABarPuller) {
  const Job job{"fanuc-14-safety-g49-bar-puller.nc", "fanuc", "--stock 36x80", false};
  RUN_CLEAN(job, r);
  EXPECT_EQ(r.check.text.find("I102"), std::string::npos) << r.check.text;
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-10.0), 30.0, kMm);    // X30. to Z-25.
  EXPECT_NEAR(p.d(-30.0), 36.0, kMm);    // the bar
  EXPECT_NEAR(p.inner(-5.0), 0.0, kMm);  // the puller went in to Z-12. at X0 and drilled nothing
  EXPECT_NEAR(p.edge(-24.0, -26.0, 33.0), -25.0, kMm);
  EXPECT_NEAR(p.rightFace(), 0.0, kMm);  // faced X34. -> X-1. at Z0.
}

// O0815: a label line (the part's name in Chinese) before the first '%', which
// the control skips (note I105, not E138), and `G53 G00 X100 Z150 T00` homing
// lines whose T00 cancels the offset (not E118).
TEST(RealStyleControlReading, Fanuc_LeaderLineAndT00HomingLines) {
  const Job job{"fanuc-15-leader-homing-t00.nc", "fanuc", "--stock 45x60", false};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.check.text.find(":1:1: note I105: lines 1-1 stand before the first '%'"), std::string::npos)
      << r.check.text;
  const Profile& p = r.part;
  // G70 under G40 with T01 (R0.8, tip 3): cylinders exact.
  EXPECT_NEAR(p.d(-10.0), 24.0, kMm);  // X24 from Z-2 to Z-20
  EXPECT_NEAR(p.d(-30.0), 40.0, kMm);  // X40 from Z-20 to Z-35
  EXPECT_NEAR(p.d(-45.0), 45.0, kMm);  // the bar behind the shape
  EXPECT_NEAR(p.edge(-19.0, -21.0, 32.0), -20.0, kMm);
}

// O0216, a Brazilian course's habits: ';' ends every block, a comment in ( )
// after it is fine, but "T0404 ;bedame de 3mm" puts text in the next block
// (E141) and "(USA MAX(#100,#112) COMO PISO)" ends at its first ')' (E142):
// a Fanuc stops on both. Haas reads both lines as comments.
TEST(RealStyleControlReading, Fanuc_TextAfterSemicolonAndAfterAnInnerParenthesisStop) {
  const std::string file = quote(kPrograms + "/fanuc-16-eob-text-nested-comment.nc");
  const Output fanuc = runCli("check " + file + " --dialect fanuc --stock 46x60 --config " + quote(kShipped));
  EXPECT_EQ(fanuc.exitCode, 1) << fanuc.text;
  EXPECT_NE(fanuc.text.find(":3:20: error E142: "), std::string::npos) << fanuc.text;
  EXPECT_NE(fanuc.text.find(":19:8: error E141: this control ends the block at ';' and reads \"bedame de 3mm\""),
            std::string::npos)
      << fanuc.text;
  EXPECT_EQ(errorLines(fanuc.text).find(":6:"), std::string::npos) << "'; (desbaste) ;' is fine:\n" << fanuc.text;
  EXPECT_EQ(fanuc.text.find("I102"), std::string::npos) << "text is no other machine's form:\n" << fanuc.text;
  const Output haas = runCli("check " + file + " --dialect haas --units mm --stock 46x60 --config " + quote(kShipped));
  EXPECT_EQ(errorLines(haas.text), "") << haas.text;
}

// O20020: a Haas program with "; comment" after its blocks, as Haas reads them.
TEST(RealStyleControlReading, Haas_SemicolonCommentsAreComments) {
  const Job job{"haas-20-eob-comments.nc", "haas", "--units inch --stock 1x3in", true};
  RUN_CLEAN(job, r);
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-0.25), 0.6, kIn);  // X0.6 to Z-0.5
  EXPECT_NEAR(p.d(-0.75), 0.8, kIn);  // X0.8 from Z-0.5 to Z-1.0
  EXPECT_NEAR(p.d(-1.5), 1.0, kIn);   // the bar
  EXPECT_NEAR(p.rightFace(), 0.0, kIn);
}

// O2417: the same groove twice, the second 20 mm further in through a local coordinate system
// (G52 Z-20. ... G52 Z0), G61/G64 and G09 around the cuts and the 0i-TF's G23 G25 G69 in the safety
// line: codes the control has that Klueng read as E114 before; none changes the path but G52.
TEST(RealStyleControlReading, Fanuc_LocalCoordinatesForTheSecondGroove) {
  const Job job{"fanuc-17-g52-second-step.nc", "fanuc", "--stock 56x80", false};
  RUN_CLEAN(job, r);
  EXPECT_EQ(r.check.text.find("warning"), std::string::npos) << r.check.text;
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-5.0), 46.0, kMm);  // X46. from Z0 to Z-50.
  EXPECT_NEAR(p.d(-8.5), 40.0, kMm);  // the groove, left corner at Z-10., 3 mm wide
  EXPECT_NEAR(p.d(-20.0), 46.0, kMm);
  EXPECT_NEAR(p.d(-28.5), 40.0, kMm);  // the same groove from the local zero: Z-30. to Z-27.
  EXPECT_NEAR(p.d(-40.0), 46.0, kMm);
  EXPECT_NEAR(p.d(-60.0), 56.0, kMm);  // the bar behind Z-50.
  EXPECT_NEAR(p.edge(-29.0, -31.0, 43.0), -30.0, kMm);
  EXPECT_NEAR(p.edge(-26.0, -28.0, 43.0), -27.0, kMm);
  EXPECT_NEAR(p.rightFace(), 0.0, kMm);
}

// O1809: G42 on the approach to the cycle's start, G71 and G70 under it, G40 on the way home: a
// shop habit the 0i-TF runs (A123 had stopped it at the G71). The roughing passes run on the
// programmed shape (W134), the G70 pass is compensated, so the taper and the chamfer come out as
// drawn, not fat by the nose radius.
TEST(RealStyleControlReading, Fanuc_G42BeforeTheRoughingCycle) {
  const Job job{"fanuc-18-g42-before-g71.nc", "fanuc", "--stock 52x80", false};
  RUN_CLEAN(job, r);
  EXPECT_NE(r.simulate.text.find("W134"), std::string::npos) << r.simulate.text;
  const Profile& p = r.part;
  EXPECT_NEAR(p.d(-1.0), 22.0, kMm);   // the chamfer X20. Z0 -> X24. Z-2., half way
  EXPECT_NEAR(p.d(-8.0), 24.0, kMm);   // X24. to Z-15.
  EXPECT_NEAR(p.d(-20.0), 27.0, kMm);  // the taper X24. Z-15. -> X30. Z-25., half way
  EXPECT_NEAR(p.d(-30.0), 30.0, kMm);  // X30. to Z-35.
  EXPECT_NEAR(p.d(-45.0), 40.0, kMm);  // after the R5 to X40., to Z-50.
  EXPECT_NEAR(p.d(-60.0), 52.0, kMm);  // the bar behind Z-50.
  EXPECT_NEAR(p.edge(-49.0, -51.0, 46.0), -50.0, kMm);
}

}  // namespace

// Its scratch folders go with the process: nothing left in /tmp after a run.
[[maybe_unused]] ::testing::Environment* const kRealStyleScratchCleanup =
    klueng::test::removeScratchFoldersAtExit({"klueng_real_style_test-"});
