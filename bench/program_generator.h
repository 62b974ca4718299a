#pragma once
// Generates a realistic lathe program of an exact number of body blocks, for
// benchmarks and tests. Header-only so the generator executable, the benchmark
// and the gcode tests share one implementation.
//
// The job: Ø50 x 100 mm bar, the chuck grips the left 15 mm (Z -85..-100), so
// Z never goes below -80. Roughing passes take 1 mm on diameter down to Ø20
// over Z 0..-60; after that the same kind of passes, tapers, arcs (R and I/K)
// and dwells repeat in air above Ø20. The last tenth of the blocks repeats a
// finishing profile under G42. Every rapid moves in Z only above material that
// is already cut below it, or at X52 (above the bar).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace klueng::bench {

class ProgramGenerator {
 public:
  // Body blocks (N-numbered blocks) of the program; O0001 is not counted.
  static constexpr int kMinimumBlocks = 16;

  static std::string generate(int bodyBlocks) {
    ProgramGenerator g;
    g.build(bodyBlocks < kMinimumBlocks ? kMinimumBlocks : bodyBlocks);
    return g.text_;
  }

 private:
  std::string text_;
  int emitted_ = 0;

  void block(const char* words) {
    // N must stay within 1..9999 (SPEC 4); long programs reuse numbers, as
    // real tapes do.
    const int n = emitted_ % 9999 + 1;
    char buf[16];
    std::snprintf(buf, sizeof buf, "N%d ", n);
    text_ += buf;
    text_ += words;
    text_ += '\n';
    ++emitted_;
  }

  static std::string fmtMm(const char* pattern, int value) {
    char buf[96];
    std::snprintf(buf, sizeof buf, pattern, value);
    return buf;
  }

  // One in-air or roughing pattern; each starts and ends at Z2 with X <= 52.
  static std::vector<std::string> roughingPass(int diameter) {
    return {"G00 X52. Z2.", fmtMm("G01 X%d. F0.25", diameter), "G01 Z-60.", fmtMm("G01 X%d.", diameter + 2), "G00 Z2."};
  }
  static std::vector<std::string> taperPass() {
    return {"G00 X52. Z2.", "G01 X20. Z0. F0.25", "X30. Z-10.", "Z-30.", "X52.", "G00 Z2."};
  }
  static std::vector<std::string> arcPassRadius() {
    return {"G00 X52. Z2.", "G01 X20. Z0. F0.25", "G01 Z-20.", "G02 X28. Z-24. R4.",
            "G01 Z-40.",    "G03 X36. Z-44. R4.", "G01 X52.",  "G00 Z2."};
  }
  static std::vector<std::string> arcPassCentre() {
    return {"G00 X52. Z2.", "G01 X20. Z0. F0.25",      "G01 Z-20.", "G02 X28. Z-24. I4. K0.",
            "G01 Z-40.",    "G03 X36. Z-44. I0. K-4.", "G01 X52.",  "G00 Z2."};
  }
  // The finishing profile: Ø20 face corner, 1 mm chamfer, R4 fillet, R4 corner.
  static std::vector<std::string> finishingProfile(bool first) {
    return {first ? "G42 G00 X20. Z2." : "G00 X20. Z2.",
            "G01 Z0. F0.1",
            "X22. Z-1.",
            "Z-20.",
            "G02 X30. Z-24. R4.",
            "G01 Z-40.",
            "G03 X38. Z-44. I0. K-4.",
            "G01 X52.",
            "G00 Z2."};
  }

  // Emits the pattern if it fits in `budget` blocks; returns blocks used.
  int emitIfFits(const std::vector<std::string>& pattern, int budget) {
    if (static_cast<int>(pattern.size()) > budget) return 0;
    for (const std::string& w : pattern) block(w.c_str());
    return static_cast<int>(pattern.size());
  }

  void build(int bodyBlocks) {
    text_.reserve(static_cast<std::size_t>(bodyBlocks) * 24 + 64);
    text_ += "Generated lathe job\nBenchmark shaft\nAluminium 6061\n150\n1100\nklueng-gen-program\n";
    text_ += "O0001\n";

    const int preamble = 5;
    const int ending = 3;
    const int finishing = bodyBlocks / 10;
    int middle = bodyBlocks - preamble - ending - finishing;

    block("G21 G40 G97");
    block("G99");
    block("T0101");
    block("G50 S2500");
    block("G96 S180 M03");

    // Roughing Ø49 down to Ø20, then passes in air.
    int diameter = 49;
    int passes = 0;
    int cycle = 0;
    while (middle > 0) {
      int used = 0;
      if (diameter >= 20) {
        used = emitIfFits(roughingPass(diameter), middle);
        if (used) --diameter;
      } else {
        switch (cycle++ % 5) {
          case 0: used = emitIfFits(roughingPass(20), middle); break;
          case 1: used = emitIfFits(taperPass(), middle); break;
          case 2: used = emitIfFits(arcPassRadius(), middle); break;
          case 3: used = emitIfFits(arcPassCentre(), middle); break;
          default: used = emitIfFits(roughingPass(20), middle); break;
        }
      }
      if (used == 0) {
        // Not enough room for a whole pass: fill with no-op rapids to the safe point.
        block("G00 X52. Z2.");
        used = 1;
      } else if (++passes % 7 == 0 && middle - used > 0) {
        block(passes % 14 == 0 ? "G04 P300" : "G04 U0.5");
        ++used;
      }
      middle -= used;
    }

    // Finishing under G42: the profile repeated, padded with safe-point rapids.
    int left = finishing;
    bool first = true;
    while (left > 0) {
      int used = emitIfFits(finishingProfile(first), left);
      if (used == 0) {
        block(first ? "G42 G00 X52. Z2." : "G00 X52. Z2.");
        used = 1;
      }
      first = false;
      left -= used;
    }

    block("G40 G00 X100. Z100.");
    block("M05");
    block("M30");
  }
};

// The heavy roughing job of issue 29 item 14: a Ø60 x 120 mm bar (the chuck
// grips Z -105..-120) turned down level by level, 1 mm on diameter a level
// from Ø59 to Ø21, each pass along the whole Z 0..-100 at 0.05 mm columns.
// Each level has many passes: the first takes the level, the others run over
// the cut surface and retract at the uncut shoulder (spring passes, as a
// student's program repeats them). Unlike ProgramGenerator's job, nearly every
// feed touches the stock, so this program weighs on the cut, not on reading.
// With linuxcnc = true the same blocks come in LinuxCNC's rs274ngc dialect, to
// time its `rs274` interpreter on the same work (a reference, never a dependency).
class RoughingGenerator {
 public:
  static constexpr int kLevels = 39;                          // Ø59 .. Ø21
  static constexpr int kMinimumBlocks = 5 + kLevels * 5 + 3;  // preamble, a pass a level, ending

  static std::string generate(int bodyBlocks, bool linuxcnc = false) {
    RoughingGenerator g;
    g.linuxcnc_ = linuxcnc;
    g.build(bodyBlocks < kMinimumBlocks ? kMinimumBlocks : bodyBlocks);
    return g.text_;
  }

 private:
  std::string text_;
  int emitted_ = 0;
  bool linuxcnc_ = false;

  void block(const std::string& words) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "N%d ", emitted_ % 9999 + 1);  // N within 1..9999 (SPEC 4)
    text_ += buf;
    text_ += words;
    text_ += '\n';
    ++emitted_;
  }
  static std::string x(const char* word, int diameter) {
    char buf[48];
    std::snprintf(buf, sizeof buf, word, diameter);
    return buf;
  }

  void build(int bodyBlocks) {
    text_.reserve(static_cast<std::size_t>(bodyBlocks) * 20 + 64);
    if (linuxcnc_) {
      text_ += "%\n";
    } else {
      text_ += "Generated roughing job\nHeavy roughing shaft\nMild steel\n160\n1120\nklueng-gen-program\n";
      text_ += "O0001\n";
    }
    // rs274ngc: feed per revolution is G95, the speed clamp is G96's D word, a tool change is M6.
    block("G21 G40 G97");
    block(linuxcnc_ ? "G95" : "G99");
    block(linuxcnc_ ? "T1 M6" : "T0101");
    block(linuxcnc_ ? "G18" : "G50 S2500");
    block(linuxcnc_ ? "G96 D2500 S180 M03" : "G96 S180 M03");
    const int passes = (bodyBlocks - 5 - 3) / 5;
    for (int level = 0; level < kLevels; ++level) {
      const int d = 59 - level;
      const int count = passes / kLevels + (level < passes % kLevels ? 1 : 0);
      for (int p = 0; p < count; ++p) {
        block(x("G00 X%d. Z2.", d + 2));
        block(x("G01 X%d. F0.25", d));
        block("G01 Z-100.");
        block(x("G01 X%d.", d + 1));
        block("G00 Z2.");
      }
    }
    while (emitted_ < bodyBlocks - 3) block("G00 X62. Z2.");
    block("G00 X100. Z100.");
    block("M05");
    block("M30");
    if (linuxcnc_) text_ += "%\n";
  }
};

// The yardstick of issue 40 (Klueng's speed is judged on it beside LinuxCNC's rs274): a CAM-style
// roughing job on a Ø50 x 100 aluminium bar, 140 passes, each a chain of short G01 moves that keeps
// a ±0.01 mm wave on the radius (as a CAM system's output does, so no two moves are alike), a 45°
// retract into the space just cut and a rapid back. Most blocks are bare "X.. Z.." words without an
// N number: the text a post-processor writes. With linuxcnc = true the same moves in LinuxCNC's
// dialect (G7 diameter mode, G95), to time `rs274 -t tool.tbl -g OUT.ngc /dev/null` on them.
class YardstickGenerator {
 public:
  static constexpr int kPasses = 140;
  static constexpr int kMinimumBlocks = kPasses * 8;  // four G01 moves a pass at least

  // steps = true: the chain in steps of one word a block ("Z-12.345", then "X49.816"), about
  // 8.5 bytes a block, so that a 5,000,000-block program stays under the 64 MB a file may
  // have (issue 42 item 3: the check's memory a block).
  static std::string generate(int blocks, bool linuxcnc = false, bool steps = false) {
    std::string text;
    const int per = std::max(4, blocks / kPasses - 4);  // the G01 chain's length a pass
    text.reserve(static_cast<std::size_t>(kPasses) * static_cast<std::size_t>(per + 4) * 18 + 256);
    text += linuxcnc ? "G18 G7 G21 G90 G40\nT1 M6\nM3 S1000\nG0 X60 Z5\nG95 F0.25\n"
                     : "Benchmark\nRoughing passes\nAluminium\n150\n1100\nyardstick\nO0100\n"
                       "N1 G21 G40 G97\nN2 G99\nN3 T0101\nN4 M03 S1000\nN5 G00 X60. Z5.\nN6 F0.25\n";
    char buf[64];
    const auto move = [&](const char* g, double x, double z) {
      std::snprintf(buf, sizeof buf, "%sX%.3f Z%.3f\n", g, x, z);
      text += buf;
    };
    for (int p = 0; p < kPasses; ++p) {
      const double d = 49.8 - 0.2 * p;  // this pass's diameter
      std::snprintf(buf, sizeof buf, "G00 X%.3f Z2.\nG01 X%.3f Z1.\n", d + 1.0, d);
      text += buf;
      for (int j = 1; j <= per; ++j) {
        const double z = 1.0 - (61.0 * j) / per;
        if (!steps) {
          move("", d + 0.02 * std::sin(z), z);
        } else {
          std::snprintf(buf, sizeof buf, j % 2 ? "Z%.3f\n" : "X%.3f\n", j % 2 ? z : d + 0.02 * std::sin(z));
          text += buf;
        }
      }
      move("", d + 0.5, -59.75);
      text += "G00 Z2.\n";
    }
    text += linuxcnc ? "G0 X100 Z100\nM5\nM2\n" : "G00 X100. Z100.\nM05\nM30\n";
    return text;
  }
};

}  // namespace klueng::bench
