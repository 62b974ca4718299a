// The program generator (issue 14): the outside contour of a part design, then
// a complete program in the dialect's habit around it.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "contour.h"
#include "klueng/core/design/part_design.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/io/program_file.h"

namespace klueng::core::design {

namespace {

using namespace detail;

constexpr double kRoughDepth = 2.0;  // mm a side per roughing pass
constexpr double kAllowanceX = 0.4;  // mm on the diameter left for the finishing pass
constexpr double kAllowanceZ = 0.1;  // mm along Z
constexpr double kRoughFeed = 0.25;  // mm/rev
constexpr double kFaceFeed = 0.2;
constexpr double kClear = 2.0;  // mm in front of the face
constexpr double kBlade = 3.0;  // mm: the grooving tool T04's blade (tip 3: its left corner leads)
constexpr double kGrooveFeed = 0.05;
constexpr double kBoreDepth = 1.0;  // mm a side per boring pass
constexpr double kBoreFeed = 0.15;
constexpr double kDrill = 10.0;     // mm: the drill T06 (tools.cfg 06-drill-10mm)
constexpr double kDrillFeed = 0.1;  // mm/rev
constexpr double kPeck = 5.0;       // mm a peck
constexpr int kThreadPasses = 6;    // classic G32 passes, equal chip area

// The table's material in the comments' language (the thesis's four; others as written).
std::string materialName(const std::string& row, const Words& t) {
  if (!t.thai) return row;
  if (row == "aluminium") return "อะลูมิเนียม";
  if (row == "brass") return "ทองเหลือง";
  if (row == "cast-iron") return "เหล็กหล่อ";
  if (row == "steel") return "เหล็ก";
  return row;
}

// Roughing then finishing of one contour: the outside (side +1, from above the
// bar) or the bore (side -1, from inside the tube's hole, its allowance negative).
struct TurningPass {
  double side;
  double from;    // Ø where the material starts: the bar's, or the tube's hole
  double startX;  // the cycle's start point and where finishing ends
  double depth;   // a side per roughing pass
  double feed;
  const char* comp;  // G42 outside, G41 in the bore
  const char* what;  // "roughing 2 mm a side"
};

void writeTurning(Writer& w, const Contour& contour, const TurningPass& pass, gcode::Dialect dialect, const Words& t) {
  const double u = pass.side * kAllowanceX;
  const std::string finishing = t.pick("finishing with nose radius compensation", "กลึงละเอียดพร้อมชดเชยรัศมีจมูกมีด");
  const gcode::Dialect family = gcode::machineProfile(dialect).family;
  if (family == gcode::Dialect::Classic) {
    // Plain passes `depth` a side. A pass at Ø d may run left only while the
    // contour stays U beyond it (U left for finishing): it stops where the
    // contour reaches d - U (outside; d + U in the bore), W short of it.
    const double side = pass.side;
    const double last = side > 0 ? contour.smallestX() : contour.largestX();
    for (double d = pass.from - side * 2.0 * pass.depth; side * (d - last) > kAllowanceX + 1e-9;
         d -= side * 2.0 * pass.depth) {
      const double zEnd = zAtDiameter(contour, d - u) + kAllowanceZ;
      if (zEnd >= 0.0) continue;
      w.block(fmt::format("G00 X{}", num(d)),
              fmt::format(fmt::runtime(t.pick("roughing pass to D{}", "กลึงหยาบถึง D{}")), plain(d)));
      // The first pass says what every pass does.
      const bool first = std::abs(d - (pass.from - side * 2.0 * pass.depth)) < 1e-9;
      w.block(fmt::format("G01 Z{} F{}", num(zEnd), num(pass.feed)),
              first ? fmt::format(fmt::runtime(t.pick("to 0.1 short of the contour at {} mm/rev",
                                                      "ถึงก่อนรูปร่าง 0.1 มม. ป้อน {} มม./รอบ")),
                                  plain(pass.feed))
                    : std::string());
      w.block(fmt::format("G00 U{} W0.5", num(side)),
              first ? t.pick("off the cut 0.5 a side and 0.5 back", "ถอยออกจากผิว 0.5 มม. และถอยหลัง 0.5 มม.") : "");
      w.block(fmt::format("G00 Z{}", num(kClear)), first ? t.pick("back in front of the face", "กลับมาหน้างาน") : "");
    }
    w.block(fmt::format("{} G00 X{} Z{}", pass.comp, num(contour.x0), num(kClear)), finishing);
    contourBlocks(w, contour, pass.startX, t);
    return;
  }
  const bool haas = family == gcode::Dialect::Haas;
  const long long p = w.next() + w.step() * (haas ? 1 : 2);
  const long long q = p + w.step() * (static_cast<long long>(contour.moves.size()) + 2);
  const std::string left =
      pass.side > 0 ? t.pick("0.4 on the diameter and 0.1 on Z left for finishing",
                             "เหลือเผื่อกลึงละเอียด 0.4 มม. ทางเส้นผ่านศูนย์กลาง และ 0.1 มม. ทาง Z")
                    : t.pick("0.4 on the diameter, U negative in the bore, and 0.1 on Z left for finishing",
                             "เหลือเผื่อกลึงละเอียด 0.4 มม. ทางเส้นผ่านศูนย์กลาง ค่า U ติดลบเพราะอยู่ในรู และ 0.1 มม. ทาง Z");
  if (haas) {
    w.block(fmt::format("G71 P{} Q{} U{} W{} D{} F{}", p, q, num(u), num(kAllowanceZ), num(pass.depth), num(pass.feed)),
            std::string(pass.what) + ", " + left);
  } else {
    w.block(fmt::format("G71 U{} R0.5", num(pass.depth)),
            std::string(pass.what) + t.pick(", 0.5 retract", " ถอยมีด 0.5 มม."));
    w.block(fmt::format("G71 P{} Q{} U{} W{} F{}", p, q, num(u), num(kAllowanceZ), num(pass.feed)), left);
  }
  w.block(fmt::format("G00 X{}", num(contour.x0)), t.pick("the profile starts", "เริ่มรูปร่างชิ้นงาน"));
  contourBlocks(w, contour, pass.startX, t);
  w.block(fmt::format("G00 {} X{} Z{}", pass.comp, num(pass.startX), num(kClear)), finishing);
  w.block(fmt::format("G70 P{} Q{}", p, q),
          t.pick("finishing: the profile's blocks P to Q", "กลึงละเอียดตามบล็อก P ถึง Q"));
}

// The part fits the bar the machine holds, and has steps to turn.
void checkPartFitsBar(const PartDesign& part, const GenerateOptions& options, std::vector<Diagnostic>& why) {
  if (part.outside.empty()) why.push_back(problem(codes::kPartHasNoSteps, {}));
  const double reach = part.stockLength - options.machine.chuckGrip;
  if (part.length() > reach + 1e-9) why.push_back(problem(codes::kPartLongerThanBar, {num(part.length()), num(reach)}));
}

// The cutting speeds table's row for the part's material, or why there is none.
std::optional<CuttingSpeed> findSpeedRow(const PartDesign& part, const GenerateOptions& options,
                                         std::vector<Diagnostic>& why) {
  std::vector<CuttingSpeed> speeds = options.speeds;
  if (speeds.empty()) speeds = readCuttingSpeeds().value.value_or(std::vector<CuttingSpeed>{});
  const auto row =
      std::find_if(speeds.begin(), speeds.end(), [&](const CuttingSpeed& s) { return s.material == part.material; });
  if (row != speeds.end()) return *row;
  std::string names;
  for (const CuttingSpeed& s : speeds) names += (names.empty() ? "" : ", ") + s.material;
  why.push_back(problem(codes::kUnknownMaterial, {part.material, names}));
  return std::nullopt;
}

double boreDepthOf(const PartDesign& part) {
  double boreDepth = 0.0;
  for (const BoreStep& s : part.inside) boreDepth += s.length;
  return boreDepth;
}

// The bore can be drilled and bored: wide enough for the drill in a solid bar,
// not below a tube's hole, not deeper than the part.
void checkBore(const PartDesign& part, const Contour& bore, double depth, std::vector<Diagnostic>& why) {
  if (part.inside.empty()) return;
  if (part.stockBore <= 0.0 && bore.smallestX() < kDrill + 2.0 - 1e-9)
    why.push_back(problem(codes::kBoreInSolidBar, {num(bore.smallestX()), num(kDrill), num(kDrill + 2.0)}));
  for (std::size_t k = 0; k < part.inside.size() && part.stockBore > 0.0; ++k)
    if (part.inside[k].diameter < part.stockBore - 1e-9)
      why.push_back(
          problem(codes::kBoreBelowHole, {std::to_string(k + 1), num(part.inside[k].diameter), num(part.stockBore)}));
  if (depth > part.length() + 1e-9)
    why.push_back(problem(codes::kBoreDeeperThanPart, {num(depth), num(part.length())}));
}

// Each thread on one cylinder (its major Ø), with a pitch that fits it.
std::vector<double> checkThreadsAndFindMajors(const PartDesign& part, std::vector<Diagnostic>& why) {
  std::vector<double> threadMajor(part.threads.size(), 0.0);
  for (std::size_t k = 0; k < part.threads.size(); ++k) {
    const Thread& th = part.threads[k];
    const std::string n = std::to_string(k + 1);
    if (th.pitch < 0.25 || th.pitch > 6.0 || th.pitch * 3.0 > th.length)
      why.push_back(problem(codes::kThreadPitchBad, {n, num(th.pitch)}));
    if (const OutsideStep* s = cylinderUnder(part, th.z, th.z - th.length, false)) threadMajor[k] = s->diameter;
    if (threadMajor[k] <= 0.0) why.push_back(problem(codes::kThreadOffCylinder, {n, num(th.z), num(th.z - th.length)}));
  }
  return threadMajor;
}

// Each groove on one cylinder, no narrower than the blade, not through the part.
std::vector<double> checkGroovesAndFindTops(const PartDesign& part, std::vector<Diagnostic>& why) {
  std::vector<double> grooveTop(part.grooves.size(), 0.0);
  for (std::size_t g = 0; g < part.grooves.size(); ++g) {
    const Groove& gr = part.grooves[g];
    const std::string n = std::to_string(g + 1);
    if (gr.width < kBlade - 1e-9) why.push_back(problem(codes::kGrooveNarrow, {n, num(gr.width), num(kBlade)}));
    const OutsideStep* s = cylinderUnder(part, gr.z, gr.z - gr.width, true);
    if (s) {
      grooveTop[g] = s->diameter;
      if (!(gr.diameter > 0.0 && gr.diameter < s->diameter))
        why.push_back(problem(codes::kGrooveTooDeep, {n, num(gr.diameter), num(s->diameter)}));
    }
    if (!s) why.push_back(problem(codes::kGrooveOffCylinder, {n, num(gr.z), num(gr.z - gr.width)}));
  }
  return grooveTop;
}

// What the writing steps share: the checked part, the contours and the speeds.
struct ProgramPlan {
  const PartDesign& part;
  const GenerateOptions& options;
  const Words& t;
  const Contour& contour;
  const Contour& bore;
  const std::vector<double>& threadMajor;
  const std::vector<double>& grooveTop;
  double boreDepth;
  double hole;  // Ø of the hole the boring bar starts in
  double cuttingSpeed;
  int spindleLimit;
  double stock;
  double exitX;
  bool haas;
  bool classic;
  std::string name;
};

// The job header (SPEC 2): the bar is the part's stock.
std::string jobHeader(const PartDesign& part, const std::string& name) {
  // Sizes in the header have no point: a unit digit (1 = mm), then the number ("150" = 50 mm).
  const auto size = [](double v) {
    std::string s = num(v);
    if (s.back() == '.') s.pop_back();
    return s;
  };
  const std::string tube = part.stockBore > 0.0 ? "x" + size(part.stockBore) : std::string();
  return fmt::format("{}\n{}\n{}\n1{}{}\n1{}\nKlueng generator\n", io::headerText(name), io::headerText(name),
                     io::headerText(commentText(part.material)), size(part.stockDiameter), tube,
                     size(part.stockLength));
}

void writeProgramStart(Writer& w, const ProgramPlan& plan) {
  const Words& t = plan.t;
  if (!plan.classic) w.raw("%");
  w.raw(fmt::format("{} ({})", plan.haas ? "O00100" : "O0100", plan.name));
  // A machine past the three dialects is named at the program's head (docs/program-file.md §8):
  // the file opens on it and klueng-cli checks it there.
  if (static_cast<int>(plan.options.dialect) > static_cast<int>(gcode::Dialect::Classic))
    w.raw(fmt::format("(MACHINE: {})", gcode::machineProfile(plan.options.dialect).id));
  w.raw(fmt::format("({})", t.pick("Written by Klueng from the part design: check it, then simulate it",
                                   "เขียนโดย Klueng จากแบบชิ้นงาน: ตรวจสอบแล้วจำลองการทำงานก่อนใช้")));
  if (plan.classic) {
    w.block("G21 G40", t.pick("millimetres, no nose compensation", "หน่วยมิลลิเมตร ไม่ชดเชยรัศมีจมูกมีด"));
    w.block("G99", t.pick("feed per revolution", "ป้อนเป็น มม./รอบ"));
  } else {
    w.block("G18 G21 G40 G99", t.pick("XZ plane, mm, no nose compensation, feed per revolution",
                                      "ระนาบ XZ หน่วย มม. ไม่ชดเชยรัศมีจมูกมีด ป้อนเป็น มม./รอบ"));
    w.block("G28 U0. W0.", t.pick("to the reference point", "กลับสู่จุดอ้างอิง"));
  }
}

// The outside tool, the spindle at constant cutting speed, the face.
void writeSpindleStartAndFacing(Writer& w, const ProgramPlan& plan) {
  const Words& t = plan.t;
  const PartDesign& part = plan.part;
  const double stock = plan.stock;
  const double rpmAtStock = spindleRpm(plan.cuttingSpeed, stock);
  w.block("T0101", t.pick("outside turning tool, offset 01", "มีดกลึงปอกด้านนอก ออฟเซต 01"));
  w.block(
      fmt::format("G50 S{}", plan.spindleLimit),
      fmt::format(fmt::runtime(t.pick("spindle limit: the machine's {} rpm", "จำกัดความเร็วรอบไว้ที่ {} รอบ/นาที ตามเครื่อง")),
                  plan.spindleLimit));
  w.block(
      fmt::format("G96 S{} M03", num(plan.cuttingSpeed)),
      fmt::format(fmt::runtime(t.pick("Vc {} m/min for {} with a {} tool: S = 1000 x {} / 3.1416 / {} = {} rpm at D{}",
                                      "Vc {} ม./นาที สำหรับ {} มีด{}: S = 1000 x {} / 3.1416 / {} = {} รอบ/นาที ที่ D{}")),
                  plain(plan.cuttingSpeed), materialName(part.material, t),
                  part.toolMaterial == "hss" ? "HSS" : t.pick("carbide", "คาร์ไบด์"), plain(plan.cuttingSpeed),
                  plain(stock), static_cast<long long>(std::llround(rpmAtStock)), plain(stock)));
  w.block(
      fmt::format("G00 X{} Z{} M08", num(stock + 4.0), num(kClear)),
      t.pick("2 mm over the bar, 2 mm in front of it, coolant on", "เหนือผิวชิ้นงานดิบ 2 มม. ห่างหน้า 2 มม. เปิดสารหล่อเย็น"));
  w.block("G00 Z0.", t.pick("to the face", "ไปที่หน้างาน"));
  w.block(fmt::format("G01 X{} F{}", num(part.stockBore > 0.0 ? part.stockBore - 2.0 : -1.6), num(kFaceFeed)),
          t.pick("face the end at 0.2 mm/rev, past the centre", "ปาดหน้า ป้อน 0.2 มม./รอบ เลยศูนย์กลาง"));
  w.block(fmt::format("G00 Z{}", num(kClear)), t.pick("2 mm clear of the face", "ห่างหน้างาน 2 มม."));
  w.block(fmt::format("G00 X{}", num(plan.exitX)),
          t.pick("cycle start point, 1 mm over the bar", "จุดเริ่มวัฏจักร เหนือผิวชิ้นงานดิบ 1 มม."));
}

void writeOutsideTurning(Writer& w, const ProgramPlan& plan) {
  const Words& t = plan.t;
  const TurningPass outsidePass{1.0,
                                plan.stock,
                                plan.exitX,
                                kRoughDepth,
                                kRoughFeed,
                                "G42",
                                t.pick("roughing 2 mm a side", "กลึงหยาบครั้งละ 2 มม.")};
  writeTurning(w, plan.contour, outsidePass, plan.options.dialect, t);
  w.block("G00 G40 X100. Z100.", t.pick("compensation off, to the tool change point", "ยกเลิกชดเชย ไปจุดเปลี่ยนมีด"));
}

void writeDrilling(Writer& w, const ProgramPlan& plan) {
  const Words& t = plan.t;
  const PartDesign& part = plan.part;
  // Drill the solid bar on the axis: through the part (4 mm into the bar beyond), or 3 mm past a blind
  // bore's bottom so the drill's 118° point stays in the hole the boring bar cleans out.
  const double through = plan.boreDepth >= part.length() - 1e-9;
  const double zDrill = -(through ? part.length() + 4.0 : plan.boreDepth + 3.0);
  const double drillRpm = std::min(plan.options.machine.maxSpindleRpm, spindleRpm(plan.cuttingSpeed / 2.0, kDrill));
  w.block("T0606", t.pick("drill D10, offset 06", "ดอกสว่าน D10 ออฟเซต 06"));
  w.block(fmt::format("G97 S{} M03", static_cast<long long>(std::llround(drillRpm))),
          t.pick("half the turning speed at the drill's diameter", "ใช้ความเร็วครึ่งหนึ่งของการกลึงปอกที่ขนาดดอกสว่าน"));
  w.block(fmt::format("G00 X0. Z{}", num(kClear)), t.pick("on the axis", "ที่แนวแกน"));
  if (plan.classic) {
    for (double z = -kPeck; z > zDrill - kPeck + 1e-9; z -= kPeck) {
      const double to = std::max(z, zDrill);
      w.block(
          fmt::format("G01 Z{} F{}", num(to), num(kDrillFeed)),
          to == -kPeck ? t.pick("peck 5 mm, out to clear the chips", "เจาะทีละ 5 มม. ถอยออกเพื่อคายเศษ") : std::string());
      w.block(fmt::format("G00 Z{}", num(kClear)), to == -kPeck ? t.pick("out of the hole", "ถอยออกจากรู") : "");
      if (to > zDrill + 1e-9)
        w.block(fmt::format("G00 Z{}", num(to + 0.5)),
                to == -kPeck ? t.pick("back in, 0.5 short of the last depth", "กลับเข้าไปก่อนความลึกเดิม 0.5 มม.") : "");
    }
  } else if (plan.haas) {
    w.block(fmt::format("G74 Z{} K{} F{}", num(zDrill), num(kPeck), num(kDrillFeed)),
            t.pick("peck drilling, K 5 mm a peck", "เจาะเป็นช่วง K ช่วงละ 5 มม."));
  } else {
    w.block("G74 R1.", t.pick("1 mm back after each peck", "ถอยกลับ 1 มม. หลังเจาะแต่ละช่วง"));
    w.block(fmt::format("G74 Z{} Q{} F{}", num(zDrill), static_cast<long long>(std::llround(kPeck * 1000.0)),
                        num(kDrillFeed)),
            t.pick("Q 5 mm a peck, in microns", "Q ช่วงละ 5 มม. หน่วยไมครอน"));
  }
  w.block("G00 X100. Z100.", t.pick("to the tool change point", "ไปจุดเปลี่ยนมีด"));
  w.block(fmt::format("G96 S{} M03", num(plan.cuttingSpeed)),
          t.pick("back to constant cutting speed", "กลับสู่ความเร็วตัดคงที่"));
}

void writeBoring(Writer& w, const ProgramPlan& plan) {
  const Words& t = plan.t;
  // The boring bar from inside the hole, out along Z before it leaves.
  const double startX = plan.hole - 1.0;
  w.block("T0505", t.pick("boring bar, offset 05", "มีดคว้านรู ออฟเซต 05"));
  w.block(fmt::format("G00 X{} Z{}", num(startX), num(kClear)),
          t.pick("cycle start point, inside the hole", "จุดเริ่มวัฏจักร ภายในรู"));
  const TurningPass borePass{
      -1.0, plan.hole, startX, kBoreDepth, kBoreFeed, "G41", t.pick("boring 1 mm a side", "คว้านครั้งละ 1 มม.")};
  writeTurning(w, plan.bore, borePass, plan.options.dialect, t);
  w.block(fmt::format("G00 G40 Z{}", num(kClear)), t.pick("out of the bore", "ถอยออกจากรู"));
  w.block("G00 X100. Z100.", t.pick("to the tool change point", "ไปจุดเปลี่ยนมีด"));
}

void writeGrooving(Writer& w, const ProgramPlan& plan) {
  const Words& t = plan.t;
  const PartDesign& part = plan.part;
  // The grooving tool: plunges a blade apart from the right wall to the left one, at constant rpm.
  const double grooveRpm =
      std::min(plan.options.machine.maxSpindleRpm, spindleRpm(plan.cuttingSpeed / 2.0, plan.stock));
  w.block("T0404", t.pick("grooving tool, 3 mm blade, offset 04", "มีดกลึงร่อง ใบมีดกว้าง 3 มม. ออฟเซต 04"));
  w.block(fmt::format("G97 S{} M03", static_cast<long long>(std::llround(grooveRpm))),
          t.pick("half the turning speed for the blade", "ใช้ความเร็วครึ่งหนึ่งของการกลึงปอกสำหรับใบมีดร่อง"));
  for (std::size_t g = 0; g < part.grooves.size(); ++g) {
    const Groove& gr = part.grooves[g];
    const double clear = plan.grooveTop[g] + 2.0;
    const double first = gr.z - kBlade, last = gr.z - gr.width;
    std::vector<double> plunges{first};
    for (double zc = first - 0.8 * kBlade; zc > last + 1e-9; zc -= 0.8 * kBlade) plunges.push_back(zc);
    if (std::abs(plunges.back() - last) > 1e-9) plunges.push_back(last);
    // In front of the face first, then along Z over diameters no larger than this cylinder's.
    w.block(fmt::format("G00 X{} Z{}", num(clear), num(kClear)),
            t.pick("2 mm over the cylinder, in front of the face", "เหนือทรงกระบอก 2 มม. หน้างาน"));
    for (const double zc : plunges) {
      w.block(fmt::format("G00 Z{}", num(zc)),
              zc == first ? fmt::format(fmt::runtime(t.pick("groove {} x D{}", "ร่อง {} x D{}")), plain(gr.width),
                                        plain(gr.diameter))
                          : t.pick("next plunge, 0.8 of the blade on", "กินลึกครั้งถัดไป เลื่อน 0.8 เท่าของใบมีด"));
      w.block(fmt::format("G01 X{} F{}", num(gr.diameter), num(kGrooveFeed)),
              t.pick("plunge to the bottom at 0.05 mm/rev", "กินลึกถึงก้นร่อง ป้อน 0.05 มม./รอบ"));
      w.block(fmt::format("G00 X{}", num(clear)), t.pick("out", "ถอยออก"));
    }
  }
  w.block("G00 X100. Z100.", t.pick("to the tool change point", "ไปจุดเปลี่ยนมีด"));
}

void writeThreading(Writer& w, const ProgramPlan& plan) {
  const Words& t = plan.t;
  const PartDesign& part = plan.part;
  w.block("T0303", t.pick("60 degree threading tool, offset 03", "มีดกลึงเกลียว 60 องศา ออฟเซต 03"));
  for (std::size_t k = 0; k < part.threads.size(); ++k) {
    const Thread& th = part.threads[k];
    const double major = plan.threadMajor[k], h = kIsoThreadHeight * th.pitch, minor = major - 2.0 * h;
    const double rpm = std::min(plan.options.machine.maxSpindleRpm, spindleRpm(plan.cuttingSpeed / 2.0, major));
    const double startZ = th.z + 3.0 * th.pitch, endZ = th.z - th.length, clear = major + 4.0;
    const std::string what = fmt::format(fmt::runtime(t.pick("M{}x{}: thread height 0.6134 x {} = {} mm, minor D{}",
                                                             "M{}x{}: ความสูงเกลียว 0.6134 x {} = {} มม. Ø ใน D{}")),
                                         plain(major), plain(th.pitch), plain(th.pitch),
                                         plain(std::round(h * 1000.0) / 1000.0), plain(minor));
    w.block(fmt::format("G97 S{} M03", static_cast<long long>(std::llround(rpm))), what);
    w.block(fmt::format("G00 X{} Z{}", num(clear), num(startZ)),
            t.pick("three pitches in front of the thread", "ห่างหน้าเกลียวสามระยะพิตช์"));
    const double first = std::min(0.4, h / 2.0);
    if (plan.classic) {
      for (int p = 1; p <= kThreadPasses; ++p) {
        const double depth = std::round(h * std::sqrt(static_cast<double>(p) / kThreadPasses) * 1000.0) / 1000.0;
        w.block(fmt::format("G00 X{}", num(major - 2.0 * depth)),
                fmt::format(fmt::runtime(t.pick("pass {} of {}: {} deep, the same chip area each pass",
                                                "ครั้งที่ {} จาก {}: ลึก {} มม. พื้นที่เศษเท่ากันทุกครั้ง")),
                            p, kThreadPasses, plain(depth)));
        w.block(fmt::format("G32 Z{} F{}", num(endZ), num(th.pitch)),
                p == 1 ? t.pick("along the thread, F the pitch", "กลึงตามเกลียว F คือระยะพิตช์") : "");
        w.block(fmt::format("G00 X{}", num(clear)), p == 1 ? t.pick("out", "ถอยออก") : "");
        w.block(fmt::format("G00 Z{}", num(startZ)), p == 1 ? t.pick("back to the start", "กลับจุดเริ่ม") : "");
      }
    } else if (plan.haas) {
      w.block(fmt::format("G76 X{} Z{} K{} D{} A60 F{}", num(minor), num(endZ), num(std::round(h * 1000.0) / 1000.0),
                          num(first), num(th.pitch)),
              t.pick("K thread height, D first pass depth", "K ความสูงเกลียว D ความลึกครั้งแรก"));
    } else {
      w.block("G76 P011060 Q50 R0.05", t.pick("1 finishing pass, 1 pitch pull-out, 60 degrees, 0.05 least depth",
                                              "กลึงเก็บ 1 ครั้ง ถอนมีด 1 ระยะพิตช์ มุม 60 องศา ลึกอย่างน้อย 0.05 มม."));
      w.block(fmt::format("G76 X{} Z{} P{} Q{} F{}", num(minor), num(endZ),
                          static_cast<long long>(std::llround(h * 1000.0)),
                          static_cast<long long>(std::llround(first * 1000.0)), num(th.pitch)),
              t.pick("P thread height, Q first depth, in microns", "P ความสูงเกลียว Q ความลึกครั้งแรก หน่วยไมครอน"));
    }
  }
  w.block("G00 X100. Z100.", t.pick("to the tool change point", "ไปจุดเปลี่ยนมีด"));
}

void writePartingOff(Writer& w, const ProgramPlan& plan) {
  const Words& t = plan.t;
  const PartDesign& part = plan.part;
  // The parting tool's blade (tip 3: its left corner leads) right edge on the part's left end.
  const double zc = -part.length() - kBlade, to = !part.inside.empty() || part.stockBore > 0.0 ? plan.hole - 1.0 : 0.0;
  const double partRpm = std::min(plan.options.machine.maxSpindleRpm, spindleRpm(plan.cuttingSpeed / 2.0, plan.stock));
  w.block("T0707", t.pick("parting tool, 3 mm blade, offset 07", "มีดตัดขาด ใบมีดกว้าง 3 มม. ออฟเซต 07"));
  w.block(fmt::format("G97 S{} M03", static_cast<long long>(std::llround(partRpm))),
          t.pick("half the turning speed for the blade", "ใช้ความเร็วครึ่งหนึ่งของการกลึงปอกสำหรับใบมีด"));
  w.block(fmt::format("G00 X{} Z{}", num(plan.exitX), num(kClear)), t.pick("over the bar", "เหนือผิวชิ้นงานดิบ"));
  w.block(fmt::format("G00 Z{}", num(zc)),
          fmt::format(
              fmt::runtime(t.pick("the blade's right side on the part's end, Z{}", "ด้านขวาของใบมีดอยู่ที่ปลายชิ้นงาน Z{}")),
              plain(-part.length())));
  w.block(fmt::format("G01 X{} F{}", num(to), num(kGrooveFeed)),
          t.pick("part off at 0.05 mm/rev", "ตัดขาด ป้อน 0.05 มม./รอบ"));
  w.block(fmt::format("G00 X{}", num(plan.exitX)), t.pick("out", "ถอยออก"));
  w.block("G00 X100. Z100.", t.pick("to the tool change point", "ไปจุดเปลี่ยนมีด"));
}

void writeProgramEnd(Writer& w, const ProgramPlan& plan) {
  const Words& t = plan.t;
  // Home in the dialect's habit: Fanuc G28 through the current point, Haas G53 machine zero, X before Z.
  if (plan.haas) {
    w.block("G53 G00 X0.", t.pick("X home", "X กลับจุดอ้างอิงเครื่อง"));
    w.block("G53 G00 Z0.", t.pick("Z home", "Z กลับจุดอ้างอิงเครื่อง"));
  } else if (!plan.classic) {
    w.block("G28 U0. W0.", t.pick("to the reference point", "กลับสู่จุดอ้างอิง"));
  }
  w.block("M09", t.pick("coolant off", "ปิดสารหล่อเย็น"));
  w.block("M05", t.pick("spindle stop", "หยุดเพลาหมุน"));
  w.block("M30", t.pick("end of program", "จบโปรแกรม"));
  if (!plan.classic) w.raw("%");
}

// The blocks, numbered N{step}, N{2 step}, ...: each tool's work in turn.
Writer writeBlocks(const ProgramPlan& plan, int step) {
  Writer w(true, step, plan.options.dialect);
  writeProgramStart(w, plan);
  writeSpindleStartAndFacing(w, plan);
  writeOutsideTurning(w, plan);
  if (!plan.bore.moves.empty() && plan.part.stockBore <= 0.0) writeDrilling(w, plan);
  if (!plan.bore.moves.empty()) writeBoring(w, plan);
  if (!plan.part.grooves.empty()) writeGrooving(w, plan);
  if (!plan.part.threads.empty()) writeThreading(w, plan);
  if (plan.part.partOff) writePartingOff(w, plan);
  writeProgramEnd(w, plan);
  return w;
}

}  // namespace

std::optional<GeneratedProgram> generateProgram(const PartDesign& part, const GenerateOptions& options,
                                                std::vector<Diagnostic>* whyOut) {
  std::vector<Diagnostic> why;
  const Words t{options.lang == Lang::Th};
  checkPartFitsBar(part, options, why);
  const std::optional<CuttingSpeed> row = findSpeedRow(part, options, why);
  const Contour contour = outsideContour(part, why);
  const Contour bore = boreContour(part, why);
  const double boreDepth = boreDepthOf(part);
  // A bore in a solid bar is drilled with the Ø10 drill first, then bored out.
  const double hole = part.stockBore > 0.0 ? part.stockBore : kDrill;
  checkBore(part, bore, boreDepth, why);
  const std::vector<double> threadMajor = checkThreadsAndFindMajors(part, why);
  const std::vector<double> grooveTop = checkGroovesAndFindTops(part, why);
  if (!why.empty()) {
    if (whyOut) *whyOut = std::move(why);
    return std::nullopt;
  }

  GeneratedProgram out;
  out.cuttingSpeed = part.toolMaterial == "hss" ? row->hss : row->carbide;
  out.spindleLimit = static_cast<int>(std::floor(options.machine.maxSpindleRpm));
  // The habits of the machine's control family (a user's Haas-based machine writes as a Haas).
  const gcode::Dialect family = gcode::machineProfile(options.dialect).family;
  const std::string name = commentText(part.name);
  const ProgramPlan plan{part,
                         options,
                         t,
                         contour,
                         bore,
                         threadMajor,
                         grooveTop,
                         boreDepth,
                         hole,
                         out.cuttingSpeed,
                         out.spindleLimit,
                         part.stockDiameter,
                         part.stockDiameter + 2.0,
                         family == gcode::Dialect::Haas,
                         family == gcode::Dialect::Classic,
                         name};
  // The blocks, numbered N10, N20, ... as by hand; a program too long for that
  // is numbered more closely rather than past the dialect's largest N (issue 29).
  const gcode::MachineProfile& profile = gcode::machineProfile(options.dialect);
  const long long most = profile.sequenceNumberMax;
  Writer w = writeBlocks(plan, 10);
  for (const int step : {5, 2, 1})
    if (w.last() > most) w = writeBlocks(plan, step);
  if (w.last() > most) {
    // Even N1, N2, ... would pass the largest N the control reads: refused, not written.
    if (whyOut)
      *whyOut = {problem(codes::kProgramTooLong, {std::to_string(w.last()), std::to_string(most),
                                                  std::string(profile.nameEn), std::string(profile.nameTh)})};
    return std::nullopt;
  }
  out.text = jobHeader(part, name) + w.text();
  return out;
}

}  // namespace klueng::core::design
