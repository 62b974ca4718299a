// libFuzzer target: part designs (issue 14) on arbitrary bytes — JSON part
// files when the input starts with '{', DXF drawings otherwise. A design that
// reads is written back and must read the same; one the generator accepts
// must give a program that compiles without an error (the generator's
// promise), and its outline must be finite.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "klueng/core/design/dxf_import.h"
#include "klueng/core/design/part_design.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/job/job.h"
#include "klueng/core/messages.h"

using namespace klueng::core;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 200000) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const bool json = !text.empty() && text[0] == '{';
  const io::ReadResult<design::PartDesign> read =
      json ? design::readPartDesign(text, "f.json") : design::importDxf(text, "f.dxf");
  for (const Diagnostic& d : read.diagnostics) (void)formatMessage(d, Lang::Th);
  if (!read.value) return 0;
  const design::PartDesign& part = *read.value;
  const auto again = design::readPartDesign(design::writePartDesign(part), "again.json");
  if (!again.value || design::writePartDesign(*again.value) != design::writePartDesign(part)) std::abort();
  for (const Vec2& p : design::partOutline(part).outside)
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) std::abort();
  // Keep the run short: the generator's passes grow with the bar.
  if (part.stockDiameter > 300.0 || part.stockLength > 500.0 || part.outside.size() + part.inside.size() > 40) return 0;
  design::GenerateOptions options;
  options.speeds = {{"steel", 30.0, 200.0}};
  std::vector<Diagnostic> why;
  const auto program = design::generateProgram(part, options, &why);
  for (const Diagnostic& d : why) (void)formatMessage(d, Lang::En);
  if (!program) return 0;
  const auto file = io::parseProgramFile(program->text);
  if (!file.value) std::abort();
  machine::MachineSetup setup;
  setup.machine = options.machine;
  job::JobInput input;
  input.file = std::move(*file.value);
  input.setup = setup;
  input.inferTools = false;  // the generated program's own setup
  const std::shared_ptr<const job::Job> job = job::makeJob(std::move(input));
  (void)job->timeline();
  for (const Diagnostic& d : job->diagnostics())
    if (d.severity == Severity::Error) std::abort();
  return 0;
}
