// klueng-cli generate PART.json|PART.dxf -o OUT.nc [--dialect fanuc|haas|classic] [--machine NAME|FILE] [--material M]
//                   [--tool-material hss|carbide] [--layer NAME] [--stock DxL[xBORE][in]] [--lang en|th] [--config DIR]
// Issue 14: a part design (docs/parts.md) or a DXF half section to a complete program, written atomically.
// Exit 0 written, 1 the part cannot be turned (reasons on stderr), 2 bad use or files.
#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.h"
#include "klueng/core/diagnostic_codes.h"
#include "commands.h"
#include "klueng/core/design/dxf_import.h"
#include "klueng/core/design/part_design.h"
#include "klueng/core/io/program_file.h"

namespace klueng::cli {

using namespace klueng::core;

namespace {

bool isDxf(const std::string& path) {
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : std::string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".dxf";
}

}  // namespace

int runGenerate(const std::vector<std::string>& args) {
  JobOptions job;
  std::string file, out;
  std::optional<std::string> material, toolMaterial;
  design::DxfImportOptions dxfOptions;
  // generate's option table (cli_common.h): the shared rows, then its own. --stock is the
  // bar the design is turned from, read as check and simulate read it (a size in inches is
  // turned into millimetres, the design's unit).
  std::vector<CliOption> table = machineOptions(job);
  const std::vector<CliOption> own = {
      valueOption("--output", out, "-o"),
      valueOption("--layer", dxfOptions.layer),
      {"--material",
       {},
       true,
       nullptr,
       [&material](const std::string& v) {
         material = v;
         return !v.empty();
       }},
      {"--tool-material",
       {},
       true,
       codes::kCliAllowedToolMaterial,
       [&toolMaterial](const std::string& v) {
         toolMaterial = v;
         return v == "hss" || v == "carbide";
       }},
      {"--stock",
       {},
       true,
       codes::kCliAllowedStock,
       [&job](const std::string& v) {
         job.stock = parseStock(v);
         return job.stock.has_value();
       }},
  };
  table.insert(table.end(), own.begin(), own.end());
  const auto exit =
      parseCommandLine("generate", codes::kCliGenerateUsage, args, table, oneFile("generate", file, langOfArgs(args)));
  if (exit) return *exit;
  if (file.empty() || out.empty())
    return usageError("generate", codes::kCliGenerateUsage, job.lang, codes::kCliGenerateNeeds);
  design::GenerateOptions options;
  options.lang = job.lang;
  options.dialect = job.dialect;
  const std::string& configDir = job.configDir;
  const std::string& machine = job.machine;
  LoadedConfig config = loadConfig(configDir);
  // --machine NAME|FILE: the program in that machine's G-code system, with its machine.cfg keys.
  if (!chooseMachine(machine, config, options.dialect, options.lang)) return 2;
  for (const auto& fd : config.diagnostics) printDiagnostic(stderr, fd.file, fd.diagnostic, options.lang);
  if (config.unreadable || config.hasErrors()) return 2;
  options.machine = config.setup.machine;
  // Refused before any work, as a compiler refuses `-o` naming its source.
  std::vector<std::string> inputs = setupFiles(config);
  inputs.push_back(file);
  if (!outputsAllowed({out}, inputs, options.lang)) return 2;
  // Bounded as program files are: /dev/zero or a 90 MB drawing is refused, not read to the end (issue 29).
  const io::ReadResult<std::string> read = design::readPartFile(file);
  for (const Diagnostic& d : read.diagnostics) printDiagnostic(stderr, file, d, options.lang);
  if (!read.ok()) return 2;
  const std::string& text = *read.value;
  dxfOptions.chuckGrip = options.machine.chuckGrip;
  auto design = isDxf(file) ? design::importDxf(text, file, dxfOptions) : design::readPartDesign(text, file);
  for (const Diagnostic& d : design.diagnostics) printDiagnostic(stderr, file, d, options.lang);
  if (!design.ok()) return 2;
  if (material) design.value->material = *material;
  if (toolMaterial) design.value->toolMaterial = *toolMaterial;
  if (job.stock) {
    design.value->stockDiameter = job.stock->diameterMm();
    design.value->stockLength = job.stock->lengthMm();
    design.value->stockBore = job.stock->boreMm();
  }
  std::vector<Diagnostic> why;
  const auto program = design::generateProgram(*design.value, options, &why);
  for (const Diagnostic& d : why) printDiagnostic(stderr, file, d, options.lang);
  if (!program) return 1;
  // A read-only OUT.nc is refused, a failed write keeps the old one: exit 2 (issue 29).
  return writeOutput(out, program->text, options.lang) ? 0 : 2;
}

}  // namespace klueng::cli
