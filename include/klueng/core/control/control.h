#pragma once
// The machine at the operator panel (issue 31): what a student does before the
// first cycle start — zero return, jogging and the handwheel, touching each tool
// off on the bar, the offset and work shift pages, MDI — with the same checker,
// interpreter and cut as a program run. No Qt; the GUI's Operator panel only
// shows this model and forwards key presses.
//
// Coordinates. Machine positions are the turret's, (Z, X diameter), 0 at the
// reference point (the positive end of travel, as on a Fanuc or Haas lathe).
// The bar is in Klueng's work frame (its face at Z 0, cut/stock.h). Each
// station's tool tip stands at machine position + its true tip vector, which the
// student does not know and measures. The control moves the turret to
//   machine = programmed + geometry + wear + work shift        (Fanuc, Haas)
// so the tip is at programmed + (geometry + wear + work shift + true tip): that
// sum is the offset row the interpreter applies (machine/interpreter.h), zero
// plus offset.cfg's wear when the touch-off was right. Offset row n belongs to
// station n (T0101, T0202), as on most school lathes.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/timeline.h"

namespace klueng::core::control {

enum class Mode { Edit, Memory, Mdi, Jog, Handle, ZeroReturn };
enum class Axis { X, Z };
// The keys and alarm texts follow the machine's control (Haas machines: Haas, others: Fanuc 0i-TF).
enum class Layout { Fanuc, Haas };
Layout layoutFor(gcode::Dialect dialect);

// A position on the panel's pages: X as a diameter, as every lathe control shows it.
struct AxisValues {
  double x = 0.0;
  double z = 0.0;
  friend bool operator==(const AxisValues&, const AxisValues&) = default;
};

struct OffsetRow {
  AxisValues geometry;     // machine position of the tip at the work zero, less the work shift
  AxisValues wear;         // small corrections after measuring a part (starts as offset.cfg's X Z)
  bool measuredX = false;  // set by X MEASURE since power-on (the exercise asks for every tool used)
  bool measuredZ = false;
};

// Override steps as the controls have them.
struct Overrides {
  int feed = 100;     // %, 0..150 in steps of 10 (0 = the axes stand still)
  int rapid = 100;    // %, F0 / 25 / 50 / 100 (F0 = kRapidF0Rate)
  int spindle = 100;  // %, 50..120 in steps of 10
};
inline constexpr double kRapidF0Rate = 400.0;  // mm/min at rapid F0 (Fanuc parameter 1421)
int stepFeedOverride(int percent, int steps);
int stepRapidOverride(int percent, int steps);
int stepSpindleOverride(int percent, int steps);

// The timeline as it runs with these overrides (and dry run at `dryRunFeed`
// mm/min times the feed override): rapids at the rapid override, feeds
// (G98) at the feed override, feeds per revolution (G99) at feed × spindle
// override, threads at the spindle override only (the feed override is
// ignored while threading), dwells as programmed. The moves keep their paths;
// times, feeds and rpm change. Feed override 0: the feed moves never end
// (their tEnd is +inf), as a feed hold.
machine::Timeline withOverrides(const machine::Timeline& timeline, const Overrides& overrides,
                                const io::MachineConfig& machine, bool dryRun = false, double dryRunFeed = 1000.0);

// The run's clock at the panel's overrides (issue 31): a GUI run plays the
// job's own timeline, each move at the length withOverrides gives it, so at
// feed override 50 % a feed move takes twice the playback time and a rapid
// (rapid override 100 %) the same. advance() says how far the timeline gets in
// `seconds` of the machine's time from its time `t`; feed override 0 stands at
// the start of the next feed move (rate 0). The default clock is the timeline's.
class OverrideClock {
 public:
  OverrideClock() = default;
  OverrideClock(const machine::Timeline& timeline, const Overrides& overrides, const io::MachineConfig& machine,
                bool dryRun = false, double dryRunFeed = 1000.0);
  double advance(double t, double seconds) const;
  // Timeline seconds per machine second in move `i` (1 = as programmed, 0 = stands).
  double rate(int i) const {
    return i >= 0 && i < static_cast<int>(rate_.size()) ? rate_[static_cast<std::size_t>(i)] : 1.0;
  }
  const machine::Timeline* timeline() const { return timeline_; }

 private:
  const machine::Timeline* timeline_ = nullptr;
  std::vector<double> rate_;
};

// What a motion key did.
struct MotionResult {
  bool moved = false;              // the turret moved (maybe less than asked)
  bool cut = false;                // material came off the bar (chips: the tool touches)
  std::optional<Diagnostic> stop;  // why it stopped short: overtravel, a crash, not allowed
};

class Control {
 public:
  // `setup`: the machine, tools and offset.cfg of the job; `stock`: the bar of the job.
  Control(machine::MachineSetup setup, io::JobHeader stock, gcode::Dialect dialect);
  // The cut keeps a pointer to the moves: a control stays where it was made.
  Control(const Control&) = delete;
  Control& operator=(const Control&) = delete;

  Layout layout() const { return layout_; }
  gcode::Dialect dialect() const { return dialect_; }
  // The control's own alarm label for a Klueng code (A601 -> "PS0224 ZERO RETURN NOT FINISHED").
  std::string controlLabel(std::string_view code) const;

  // --- the true tools (what a touch-off measures) ---
  // Tip position in the bar's frame (z, X diameter) with the turret at machine 0.
  AxisValues trueTip(int station) const;
  void setTrueTip(int station, AxisValues tip);
  // The geometry a perfect touch-off with the current work shift gives.
  AxisValues trueGeometry(int station) const;
  // The exercise (issue 31 item 5): every geometry row 0, nothing measured.
  void forgetGeometry();
  bool exercise() const { return exercise_; }
  // What the touch-off got wrong for a station: geometry + work shift against the
  // true tool (X diameter), the wear left out. {0, 0} for a perfect touch-off.
  AxisValues touchOffError(int station) const;
  // I611 for the station of `stations` with the largest error (X Ø or Z), nullopt when none is given.
  std::optional<Diagnostic> compareTouchOff(const std::vector<int>& stations) const;

  // --- modes and switches ---
  Mode mode() const { return mode_; }
  void setMode(Mode m);
  int handleStep() const { return handleStep_; }  // clicks of 0.001 mm: 1, 10, 100
  void setHandleStep(int step);
  Axis handleAxis() const { return handleAxis_; }
  void setHandleAxis(Axis a) { handleAxis_ = a; }
  Overrides& overrides() { return overrides_; }
  const Overrides& overrides() const { return overrides_; }
  bool singleBlock = false;
  bool optionalStop = false;
  bool blockDelete = false;
  bool dryRun = false;
  bool coolant = false;
  double jogFeed = 500.0;  // mm/min at 100 % feed override (JOG feed, dry run)

  // --- position ---
  bool referenced(Axis a) const { return referenced_[a == Axis::X ? 0 : 1]; }
  AxisValues machinePosition() const { return machine_; }
  AxisValues absolutePosition() const;  // the work position the control computes with row = station
  AxisValues relativePosition() const;
  void originRelative(Axis a);      // ORIGIN / "X" + ORIGIN: relative 0 here
  AxisValues distanceToGo() const;  // of the MDI block loaded, 0 when none
  AxisValues tip() const;           // the real tip of the tool at the turret, bar frame (X diameter)
  // Soft limits (machine.cfg travel, reference at the positive end): valid after a zero return.
  AxisValues travelMin() const;
  AxisValues travelMax() const;

  // --- turret and spindle ---
  int station() const { return station_; }
  std::optional<Diagnostic> indexTurret(int station);
  machine::SpindleDir spindle() const { return spindle_; }
  void setSpindle(machine::SpindleDir dir);
  double spindleSpeed() const { return sWord_; }  // the S last given (rpm)
  void setSpindleSpeed(double rpm) { sWord_ = rpm; }
  double actualRpm() const;  // S × spindle override, 0 when stopped

  // --- motion keys ---
  MotionResult zeroReturn(Axis a);                        // ZERO RETURN mode + the axis key
  MotionResult jog(Axis a, double distance, bool rapid);  // JOG: X in diameter, sign = direction
  MotionResult handle(int clicks);                        // HANDLE: clicks × handleStep µm on handleAxis
  // MDI: the blocks run at once with the same checker, interpreter and cut;
  // returns the check's diagnostics (lines of `text`) or the alarm that stopped them.
  std::vector<Diagnostic> runMdi(std::string_view text);
  // MEM: why cycle start is refused (not referenced, an alarm, tools not touched off), or nothing.
  std::optional<Diagnostic> cycleStartRefusal(const std::vector<int>& stationsUsed = {}) const;
  void reset();  // RESET: clears the alarm
  const std::optional<Diagnostic>& alarm() const { return alarm_; }
  const std::vector<Diagnostic>& notices() const { return notices_; }

  // --- offset pages ---
  OffsetRow& row(int n) { return rows_.at(static_cast<std::size_t>(n - 1)); }
  const OffsetRow& row(int n) const { return rows_.at(static_cast<std::size_t>(n - 1)); }
  AxisValues workShift() const { return shift_; }
  void setWorkShift(AxisValues s) { shift_ = s; }
  // Geometry page: "Z0" / "X49.6" + MEASURE (Fanuc), Z FACE / X DIA MEASURE (Haas),
  // into row `n` from where the turret stands now. A warning when the tool
  // touched with the spindle stopped; an error without a tool at the station.
  std::optional<Diagnostic> measure(int n, Axis a, double value);
  // Work shift page: Z MEASURE with the tool at the turret (its geometry row = station).
  std::optional<Diagnostic> measureWorkShift(double z);
  // The simulated micrometer: the bar's diameter at Z (bar frame), 0.001 mm.
  double micrometer(double z) const;

  // --- what a run uses ---
  // The job's setup with offset rows = geometry + wear + work shift + true tip.
  machine::MachineSetup runSetup() const;
  const machine::MachineSetup& setup() const { return setup_; }
  const io::JobHeader& stockHeader() const { return header_; }
  // The bar as cut at the panel, and the manual and MDI moves so far.
  const cut::Stock& stock() const { return sim_->stock(); }
  const cut::Chuck& chuck() const { return sim_->chuck(); }
  const machine::Timeline& moves() const { return moves_; }

 private:
  MotionResult moveTo(const AxisValues& target, bool rapid, double feed);
  MotionResult runMoves(std::vector<machine::Move> moves);
  void rebuildSim();
  Diagnostic diag(Severity s, const char* code, std::vector<std::string> args = {}) const;
  bool motionAllowed(Mode wanted, const char* key, MotionResult& out);
  bool homedForJog(Axis a, MotionResult& out) const;  // Haas jogs only a referenced axis

  machine::MachineSetup setup_;
  io::JobHeader header_;
  gcode::Dialect dialect_;
  Layout layout_;
  Mode mode_ = Mode::Jog;
  int handleStep_ = 1;
  Axis handleAxis_ = Axis::Z;
  Overrides overrides_;
  std::array<bool, 2> referenced_{};
  AxisValues machine_;
  AxisValues relativeOrigin_;
  AxisValues shift_;
  std::optional<AxisValues> mdiTarget_;
  int station_ = 1;
  machine::SpindleDir spindle_ = machine::SpindleDir::Stopped;
  double sWord_ = 500.0;
  std::array<AxisValues, io::kMaxStations> trueTips_{};
  std::array<OffsetRow, io::kOffsetCount> rows_{};
  std::optional<Diagnostic> alarm_;
  std::vector<Diagnostic> notices_;
  bool touchedStopped_ = false;
  bool exercise_ = false;  // forgetGeometry(): every tool used must be touched off  // the tool at the turret touched
                           // the bar with the spindle stopped
  std::optional<machine::ModalState> mdiModal_;
  machine::Timeline moves_;
  std::unique_ptr<cut::CutSimulator> sim_;
};

}  // namespace klueng::core::control

namespace klueng::core::control {
// What a student types on the offset page before MEASURE: "X49.6", "z0", "Z -0.5".
struct MeasureInput {
  Axis axis = Axis::Z;
  double value = 0.0;
};
// nullopt when it is not X or Z followed by one number (the caller reports E608 with the text).
std::optional<MeasureInput> parseMeasureInput(std::string_view text);
}  // namespace klueng::core::control
