#include "cut_outputs.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/finished_part.h"
#include "klueng/core/cut/guess_fit.h"
#include "klueng/core/cut/part_features.h"
#include "png_writer.h"
#include "render/section_picture.h"
#include "cli_common.h"

namespace klueng::cli {

using namespace klueng::core;

namespace {

std::string jsonString(const std::string& s) { return "\"" + jsonEscape(s) + "\""; }

std::string jsonDiagnostic(const Diagnostic& d) {
  std::string args;
  for (const auto& a : d.args) args += (args.empty() ? "" : ", ") + jsonString(a);
  return fmt::format(
      "{{\"code\": {}, \"severity\": {}, \"line\": {}, \"column\": {}, \"args\": [{}], \"message_en\": {}, "
      "\"message_th\": {}}}",
      jsonString(d.code), jsonString(std::string(severityName(d.severity, Lang::En))), d.range.line, d.range.column,
      args, jsonString(formatMessage(d, Lang::En)), jsonString(formatMessage(d, Lang::Th)));
}

}  // namespace

bool parseResolution(const std::string& text, double& out) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v) || v < 0.001 || v > 5.0) return false;
  out = v;
  return true;
}

CutOutcome runCut(const std::string& file, const io::JobHeader& header, const machine::MachineSetup& setup,
                  const machine::Timeline& timeline, const CutOutputOptions& options) {
  CutOutcome outcome;
  cut::CutOptions cutOptions;
  cutOptions.resolution = options.resolution;
  cutOptions.checkpointBudgetBytes = 0;  // one run forward: no way back to keep stock copies for
  // A guessed tool that touches gives way to another of its kind that fits (issue 26).
  cut::GuessFit fit = cut::fitGuessedTools(timeline, header, setup, io::shippedToolLibrary(), cutOptions);
  cut::CutSimulator& sim = *fit.cut;
  outcome.setup = fit.setup;
  outcome.guessNotes = fit.notes;
  outcome.alarm = sim.alarm();
  outcome.warnings = sim.warnings();
  outcome.toolErrors = sim.toolDiagnostics();
  const cut::FinishedPart part(sim.stock());

  if (!options.pngPath.empty()) {
    // The screen's painters (render/), offscreen into an image, by the picture module.
    render::SectionPicture picture;
    picture.stock = &sim.stock();
    picture.chuck = &sim.chuck();
    picture.tool = sim.currentTool();
    picture.toolPosition = sim.toolPosition();
    picture.path = &timeline;
    picture.pathUntil = sim.endTime();
    // A failed write is said as every output's is (F1xx, in the run's language), the old file kept.
    if (!reportWrite(options.pngPath, writeSectionPng(picture, options.pngPath), options.lang)) outcome.written = false;
  }

  if (!options.profilePath.empty())
    outcome.written = writeOutput(options.profilePath, part.toCsv(), options.lang) && outcome.written;
  if (!options.svgPath.empty())
    outcome.written = writeOutput(options.svgPath, part.toSvg(), options.lang) && outcome.written;
  if (!options.dxfPath.empty())
    outcome.written = writeOutput(options.dxfPath, part.toDxf(), options.lang) && outcome.written;
  if (options.features) {
    const cut::PartFeatures features = cut::partFeatures(sim.stock());
    for (const auto* list : {&features.outside, &features.inside})
      for (const cut::PartFeature& f : *list)
        std::printf("%s\n", cut::describeFeature(f, options.lang, options.units).c_str());
  }
  if (!options.jsonPath.empty()) {
    std::string alarms;
    const std::optional<Diagnostic> stop = sim.stoppingAlarm();
    if (stop) alarms = jsonDiagnostic(*stop);
    std::string toolErrors;
    for (const auto& d : outcome.toolErrors) toolErrors += (toolErrors.empty() ? "" : ", ") + jsonDiagnostic(d);
    const Vec2 tool = sim.toolPosition();
    const std::string json = fmt::format(
        "{{\n"
        "  \"file\": {},\n"
        "  \"cycle_time_s\": {},\n"
        "  \"completed\": {},\n"
        "  \"alarms\": [{}],\n"
        "  \"tool_errors\": [{}],\n"
        "  \"stock\": {{\"diameter_mm\": {:.4f}, \"length_mm\": {:.4f}, \"bore_mm\": {:.4f}, \"volume_mm3\": "
        "{:.3f}}},\n"
        "  \"removed_volume_mm3\": {:.3f},\n"
        "  \"part\": {{\"volume_mm3\": {:.3f}, \"max_diameter_mm\": {:.4f}, \"length_mm\": {:.4f}, "
        "\"z_min\": {:.4f}, \"z_max\": {:.4f}}},\n"
        "  \"resolution_mm\": {:.4f},\n"
        "  \"tool_end\": {{\"z\": {:.4f}, \"x\": {:.4f}}}\n"
        "}}\n",
        // JSON has no inf: a time no double holds is null (machine.cfg refuses what made it, issue 42).
        jsonString(file), std::isfinite(sim.endTime()) ? fmt::format("{:.4f}", sim.endTime()) : std::string("null"),
        stop ? "false" : "true", alarms, toolErrors, sim.stock().diameter(), sim.stock().length(), sim.stock().bore(),
        sim.stock().initialVolume(), sim.removedVolume(), part.volume(), part.maxDiameter(), part.length(),
        part.leftFaceZ(), part.rightFaceZ(), sim.stock().resolution(), tool.x() + 0.0, 2.0 * tool.y() + 0.0);
    outcome.written = writeOutput(options.jsonPath, json, options.lang) && outcome.written;
  }
  return outcome;
}

}  // namespace klueng::cli
