#pragma once
// Modal state (one field per modal group) and machine run state: small
// copyable values, snapshotted after every block for stepping and step back.
#include <cstdint>

#include "klueng/core/geometry.h"

namespace klueng::core::machine {

enum class MotionMode : std::uint8_t { Rapid, Line, ArcCw, ArcCcw, Thread };  // G00 G01 G02 G03 G32
enum class Units : std::uint8_t { Mm, Inch };                                 // G21 G20
enum class NoseCompMode : std::uint8_t { Off, Left, Right };                  // G40 G41 G42
enum class SpindleMode : std::uint8_t { ConstantRpm, ConstantSurface };       // G97 G96
enum class FeedMode : std::uint8_t { PerMinute, PerRev };                     // G98 G99
enum class SpindleDir : std::uint8_t { Stopped, Cw, Ccw };                    // M05 M03 M04

struct ModalState {
  MotionMode motion = MotionMode::Rapid;
  Units units = Units::Mm;
  NoseCompMode noseComp = NoseCompMode::Off;
  SpindleMode spindleMode = SpindleMode::ConstantRpm;
  FeedMode feedMode = FeedMode::PerRev;
  double feed = 0.0;            // F as programmed (mm/min, mm/rev, or lead for G32), 0 = not set
  double sWord = 0.0;           // last S (rpm under G97, m/min under G96), 0 = not set
  double rpmClamp = 0.0;        // G50 S, 0 = none
  int workCoordinate = 54;      // G54..G59 (Fanuc; all work offsets are zero)
  bool incremental = false;     // G91 of G-code systems B and C: X and Z are read as U and W
  bool returnToRPoint = false;  // G99 of systems B and C: drilling cycles end at the R point (G98: initial level)
};

struct MachineState {
  // (Doubles first, flags last: 104 bytes, not 128; snapshotted after every block.)
  Vec2 position = Vec2::Zero();   // controlled point, work coordinates (z, x radius)
  Vec2 workShift = Vec2::Zero();  // work minus machine coordinates, changed by G50 X Z
  double rpm = 0.0;               // actual spindle speed now
  double cAngle = 0.0;            // degrees
  double offsetX = 0.0;           // active offset, diameter
  double offsetZ = 0.0;
  double noseRadius = 0.0;
  int tool = 0;    // 1..8, 0 = none
  int offset = 0;  // 0..16, 0 = none
  int tip = 0;
  int gearRange = 0;  // Fanuc M41/M42 (no motion), 0 = not selected
  SpindleDir spindle = SpindleDir::Stopped;
  bool coolant = false;        // M08/M09
  bool brake = false;          // M86/M87
  bool cAxisMode = false;      // M41/M91 (classic)
  bool positionCheck = false;  // G27 lamp
  bool optionalStopSwitch = false;
  bool threadChamfer = true;  // Haas M23 (on, the power-on state) / M24 (off): G76 pull-out
};

struct StateSnapshot {
  MachineState machine;
  ModalState modal;
  double time = 0.0;          // seconds when the block has finished
  int line = 0;               // block's file line
  int blockIndex = 0;         // index into Program::blocks
  int file = 0;               // Program::files index of the block (0 = the program itself)
  int callStack = 0;          // Timeline::flow.stacks index: the call stack while the block ran
  int callLevel = 0;          // 0 = main program, 1 = first subprogram or macro level ...
  int program = 0;            // O number of the program the block belongs to (0 = none)
  int moveEnd = 0;            // Timeline::moves index one past the block's last move
  bool stopped = false;       // M00, M01 with the switch on, M02/M30
  bool optionalStop = false;  // the block holds M01 (whatever the switch): players decide while playing
};

}  // namespace klueng::core::machine
