// Closing the loop: generate, check, run, cut, and hold the cut part against
// the drawing.
#include "klueng/core/design/design_loop.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>

#include "contour.h"
#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/part_check.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/job/job.h"

namespace klueng::core::design {

namespace {

using cut::FeatureKind;
using cut::PartFeature;

constexpr double kZSlack = 0.1;             // mm: two stock columns, where a feature's ends are read
constexpr double kThreadDepthSlack = 0.05;  // mm on the minor Ø: the thread read from the cut columns

std::string plainNum(double v) { return detail::plain(v); }

// A label with no words in it, so one argument reads in both languages.
std::string neutralLabel(const PartFeature& f) {
  if (f.kind == FeatureKind::Groove) return plainNum(f.width) + " × Ø" + plainNum(f.diameter);
  return cut::featureLabel(f, Lang::En);
}

struct Expected {
  std::string label;
  double zRight, zLeft;
  bool inside;
  // Does the cut feature show it?
  std::function<bool(const PartFeature&)> shows;
};

bool overlaps(const PartFeature& f, double zRight, double zLeft) {
  return f.zLeft < zRight - kZSlack && f.zRight > zLeft + kZSlack;
}

std::string num3(double v) {
  std::string s = fmt::format("{:.3f}", std::abs(v) < 5e-4 ? 0.0 : v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

// The feature's sizes to the micron, for when the short label reads as the drawing's.
std::string preciseLabel(const PartFeature& f) {
  switch (f.kind) {
    case FeatureKind::Cylinder: return "Ø" + num3(f.diameter);
    case FeatureKind::Chamfer:
      if (std::abs(f.radialHeight - f.axialLength) < 5e-4) return "C" + num3(f.radialHeight);
      return num3(f.axialLength) + " × " + num3(f.radialHeight);
    case FeatureKind::Arc: return "R" + num3(f.radius);
    case FeatureKind::Groove: return num3(f.width) + " × Ø" + num3(f.diameter);
    case FeatureKind::Thread: return "M" + num3(f.diameter) + "×" + num3(f.pitch);
    default: return neutralLabel(f);
  }
}

// What the cut part has where the drawing's feature should be, never in the
// same words as the drawing's: if the label reads the same, the sizes to the
// micron; if those agree too, it is the place that differs, so say where it is.
std::string whatIsThere(const PartFeature& f, const std::string& drawn) {
  std::string there = neutralLabel(f);
  if (there != drawn) return there;
  there = preciseLabel(f);
  if (there != drawn) return there;
  if (f.kind == FeatureKind::Arc) return fmt::format("{} Z{} X{}", there, num3(f.centre.x()), num3(2.0 * f.centre.y()));
  return fmt::format("{} Z{}–Z{}", there, num3(f.zRight), num3(f.zLeft));
}

bool near(double a, double b, double tol = kDrawingTolerance) { return std::abs(a - b) <= tol + 1e-9; }

void expectSteps(const std::vector<OutsideStep>& steps, bool inside, std::vector<Expected>& out) {
  double z = 0.0, before = 0.0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const OutsideStep s = steps[k];
    const double zr = z, zl = z - s.length, e = s.edge == EdgeBreak::None ? 0.0 : s.edgeSize;
    z = zl;
    const double from = before;
    before = s.diameter;
    const bool sloped = s.kind != StepKind::Cylinder && (k > 0 || !inside);
    if (!sloped) {
      out.push_back({"Ø" + plainNum(s.diameter), zr - e, zl, inside, [=](const PartFeature& f) {
                       return (f.kind == FeatureKind::Cylinder || f.kind == FeatureKind::Thread ||
                               f.kind == FeatureKind::Groove) &&
                              overlaps(f, zr - e, zl) &&
                              near(f.kind == FeatureKind::Groove ? -1.0 : f.diameter, s.diameter);
                     }});
      if (s.edge == EdgeBreak::Chamfer)
        out.push_back({"C" + plainNum(e), zr, zr - e, inside, [=](const PartFeature& f) {
                         return (f.kind == FeatureKind::Chamfer && near(f.radialHeight, e) && near(f.axialLength, e) &&
                                 near(f.zRight, zr, kZSlack)) ||
                                f.kind == FeatureKind::Thread;  // threaded over: the thread's run-in
                       }});
      if (s.edge == EdgeBreak::Round)
        out.push_back({"R" + plainNum(e), zr, zr - e, inside, [=](const PartFeature& f) {
                         return f.kind == FeatureKind::Arc && f.convex && near(f.radius, e) &&
                                near(f.centre.x(), zr - e, kZSlack);
                       }});
      continue;
    }
    if (s.kind == StepKind::Taper)
      out.push_back({"Ø" + plainNum(from) + "–Ø" + plainNum(s.diameter), zr, zl, inside, [=](const PartFeature& f) {
                       return (f.kind == FeatureKind::Taper || f.kind == FeatureKind::Chamfer) &&
                              near(f.diameterLeft, s.diameter) && near(f.zLeft, zl, kZSlack);
                     }});
    else
      out.push_back({"R" + plainNum(s.radius), zr, zl, inside, [=](const PartFeature& f) {
                       return f.kind == FeatureKind::Arc && f.convex != s.concave && near(f.radius, s.radius) &&
                              overlaps(f, zr, zl);
                     }});
  }
}

}  // namespace

std::vector<Diagnostic> compareToDrawing(const PartDesign& part, const cut::PartFeatures& cut) {
  std::vector<Expected> expected;
  expectSteps(part.outside, false, expected);
  expectSteps(part.inside, true, expected);
  for (const Groove& g : part.grooves)
    expected.push_back(
        {plainNum(g.width) + " × Ø" + plainNum(g.diameter), g.z, g.z - g.width, false, [=](const PartFeature& f) {
           return f.kind == FeatureKind::Groove && near(f.diameter, g.diameter) && near(f.zRight, g.z, kZSlack) &&
                  near(f.width, g.width, kZSlack);
         }});
  // A thread is its pitch on the designed major Ø down to the designed minor Ø
  // (a thread cut deeper or shallower than drawn is not the drawn thread).
  for (const ThreadMark& t : partOutline(part).threads)
    expected.push_back(
        {"M" + plainNum(2.0 * t.major) + "×" + plainNum(t.pitch), t.zRight, t.zLeft, false, [=](const PartFeature& f) {
           return f.kind == FeatureKind::Thread && near(f.pitch, t.pitch) && overlaps(f, t.zRight, t.zLeft) &&
                  near(f.diameter, 2.0 * t.major) && near(f.minorDiameter, 2.0 * t.minor, kThreadDepthSlack);
         }});
  std::vector<Diagnostic> out;
  for (const Expected& e : expected) {
    const std::vector<PartFeature>& side = e.inside ? cut.inside : cut.outside;
    bool shown = false;
    for (const PartFeature& f : side) shown = shown || e.shows(f);
    if (shown) continue;
    // What the cut part has there: the feature across the middle of the expected span.
    const double mid = (e.zRight + e.zLeft) / 2.0;
    std::string there = "-";
    for (const PartFeature& f : side)
      if (f.kind != FeatureKind::Face && f.zLeft <= mid && f.zRight >= mid) there = whatIsThere(f, e.label);
    Diagnostic d;
    d.severity = Severity::Warning;
    d.code = codes::kNotAsDrawn;
    d.args = {e.label, plainNum(e.zRight), plainNum(e.zLeft), there};
    out.push_back(std::move(d));
  }
  return out;
}

DesignLoop runDesignLoop(const PartDesign& part, const GenerateOptions& options, const machine::MachineSetup& setup) {
  DesignLoop loop;
  loop.program = generateProgram(part, options, &loop.refused);
  if (!loop.program) return loop;
  const auto file = io::parseProgramFile(loop.program->text);
  if (!file.value) {
    loop.problems = file.diagnostics;
    return loop;
  }
  // The generated program is made for this setup: its tools are checked as they are, not inferred.
  job::JobInput input;
  input.file = std::move(*file.value);
  input.folder = std::string();
  input.setup = setup;
  input.run.dialect = options.dialect;
  input.inferTools = false;
  const std::shared_ptr<const job::Job> job = job::makeJob(std::move(input));
  for (const Diagnostic& d : job->diagnostics())
    if (d.severity == Severity::Error || d.severity == Severity::Alarm) loop.problems.push_back(d);
  if (!job->timeline() || !loop.problems.empty()) return loop;
  const cut::CutSetup cutSetup = cut::CutSetup::from(job->file()->header, setup);
  const machine::Timeline programmed = cut::programmedPath(*job->program(), setup, job->input().run, *job->timeline());
  cut::PartCheck check = cut::checkPart(*job->timeline(), programmed, cutSetup);
  if (check.stoppedBy) loop.problems.push_back(*check.stoppedBy);
  loop.cut = std::make_unique<cut::Stock>(check.cut);
  loop.features = cut::partFeatures(*loop.cut);
  loop.findings = compareToDrawing(part, loop.features);
  for (const Diagnostic& d : cut::partCheckDiagnostics(check))
    if (d.severity == Severity::Warning) loop.findings.push_back(d);
  return loop;
}

}  // namespace klueng::core::design
