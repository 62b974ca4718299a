#pragma once
// Helpers shared by the cut tests: hand-built moves and tools, and the whole
// pipeline (file -> parse -> check -> interpret -> cut) on the shipped config.
#include <memory>
#include <string>
#include <vector>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/interpreter.h"

namespace klueng::core::cut::testing {

// A bitmap: `w` x `h` pixels, all white; fill() paints boxes given in pixels.
inline io::RgbImage blankImage(int w, int h) {
  io::RgbImage img;
  img.width = w;
  img.height = h;
  img.pixels.assign(static_cast<std::size_t>(w) * h, 0xFFFFFF);
  return img;
}
inline void paint(io::RgbImage& img, int col0, int row0, int col1, int row1, std::uint32_t colour) {
  for (int r = row0; r <= row1; ++r)
    for (int c = col0; c <= col1; ++c) img.pixels[static_cast<std::size_t>(r) * img.width + c] = colour;
}

// A 5 x 5 mm square insert (10 x 10 px, gold) with a 5 mm wide, 10 mm tall
// holder (black) on top: the bitmap is 10 x 30 px, insert rows 20..29.
inline io::RgbImage squareToolImage() {
  io::RgbImage img = blankImage(10, 30);
  paint(img, 0, 20, 9, 29, 0xE0A000);
  paint(img, 0, 0, 9, 19, 0x000000);
  return img;
}

inline ToolShape squareTool(double r = 0.8, int tip = 3) {
  return *makeToolShape(squareToolImage(), "square.bmp", r, tip).value;
}

inline machine::Move move(machine::MoveKind kind, const Segment& path, double t0, double t1, int line,
                          machine::SpindleDir spindle = machine::SpindleDir::Cw) {
  machine::Move m;
  m.kind = kind;
  m.path = path;
  m.tStart = t0;
  m.tEnd = t1;
  m.line = line;
  m.tool = 1;
  m.offset = 1;
  m.spindle = spindle;
  m.rpm = spindle == machine::SpindleDir::Stopped ? 0.0 : 1000.0;
  m.rpmEnd = m.rpm;
  return m;
}

// Builds a timeline of moves with consecutive times (1 s each).
inline machine::Timeline timelineOf(std::vector<machine::Move> moves) {
  machine::Timeline t;
  double time = 0.0;
  for (auto& m : moves) {
    const double span = m.tEnd - m.tStart > 0 ? m.tEnd - m.tStart : 1.0;
    m.tStart = time;
    m.tEnd = time + span;
    time += span;
    t.moves.push_back(m);
  }
  return t;
}

inline CutSetup barSetup(double diameter, double length) {
  CutSetup s;
  s.stockDiameter = diameter;
  s.stockLength = length;
  return s;
}

inline ToolLibrary libraryWith(const ToolShape& shape, int tool = 1, int offset = 1) {
  ToolLibrary lib;
  lib.set(tool, offset, shape);
  return lib;
}

inline std::string sourceDir() { return KLUENG_SOURCE_DIR; }
inline std::string samplesDir() { return KLUENG_SAMPLES_DIR; }

// The whole pipeline on a program text with the shipped tools/offsets/machine.
struct Run {
  io::ProgramFile file;
  std::vector<Diagnostic> checkDiagnostics;
  machine::MachineSetup setup;
  machine::Timeline timeline;
  machine::Timeline programmed;  // G41/G42 read, not applied (the part check's programmed path)
};

inline Run runProgramText(const std::string& text) {
  Run run;
  run.setup.tools = *io::readToolTable(sourceDir() + "/tools.cfg").value;
  run.setup.offsets = *io::readOffsetTable(sourceDir() + "/offset.cfg").value;
  run.setup.machine = *io::readMachineConfig(sourceDir() + "/machine.cfg").value;
  auto file = io::parseProgramFile(text);
  run.file = *file.value;
  const gcode::Program program = gcode::parse(run.file.gcode, run.file.gcodeFirstLine);
  run.checkDiagnostics = gcode::check(program);
  run.timeline = machine::interpret(program, run.setup);
  machine::RunOptions plain;
  plain.noseCompensation = false;
  run.programmed = machine::interpret(program, run.setup, plain);
  return run;
}

// The pipeline and the cut to the end (the simulator is kept: FinishedPart and
// partFeatures read its stock by reference).
struct CutRun {
  Run run;
  std::unique_ptr<CutSimulator> sim;
};

inline CutRun cutToEnd(const std::string& text) {
  CutRun c;
  c.run = runProgramText(text);
  c.sim = std::make_unique<CutSimulator>(c.run.timeline, CutSetup::from(c.run.file.header, c.run.setup));
  c.sim->runToEnd();
  return c;
}

inline std::string readText(const std::string& path) {
  std::string out;
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) out.append(buf, n);
    std::fclose(f);
  }
  return out;
}

}  // namespace klueng::core::cut::testing
