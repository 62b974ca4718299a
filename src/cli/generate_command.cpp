// klueng-cli generate PART.json|PART.dxf -o OUT.nc [--dialect fanuc|haas|classic] [--machine NAME|FILE] [--material M]
//                   [--tool-material hss|carbide] [--layer NAME] [--stock DxL[xBORE]] [--lang en|th] [--config DIR]
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

// "50x100" or "50x100x16" (mm): the bar, and a tube's hole.
bool parseStock(const std::string& v, double& d, double& l, double& bore) {
  char x1 = 0, x2 = 0, tail = 0;
  bore = 0.0;
  const int n = std::sscanf(v.c_str(), "%lf%c%lf%c%lf%c", &d, &x1, &l, &x2, &bore, &tail);
  const bool sizes = d > 0.0 && l > 0.0 && d <= 10000.0 && l <= 10000.0 && (x1 == 'x' || x1 == 'X');
  if (n == 3) return sizes;
  return n == 5 && sizes && (x2 == 'x' || x2 == 'X') && bore > 0.0 && bore < d;
}

}  // namespace

int runGenerate(const std::vector<std::string>& args) {
  const Lang lang = langOfArgs(args);
  const std::string usage = cliText(codes::kCliGenerateUsage, lang);
  if (std::find(args.begin(), args.end(), "--help") != args.end()) {
    std::fputs(usage.c_str(), stdout);
    return 0;
  }
  std::string file, out, configDir;
  std::string machine;  // --machine NAME|FILE
  std::optional<std::string> material, toolMaterial;
  std::optional<std::array<double, 3>> stock;
  design::DxfImportOptions dxfOptions;
  design::GenerateOptions options;
  options.lang = lang;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("-", 0) != 0) {
      file = a;
      continue;
    }
    if (i + 1 >= args.size()) {
      printCliError("generate", codes::kCliNeedsValue, lang, {a});
      std::fputs(usage.c_str(), stderr);
      return 2;
    }
    const std::string v = args[++i];
    if (a == "-o" || a == "--output")
      out = v;
    else if (a == "--config")
      configDir = v;
    else if (a == "--material")
      material = v;
    else if (a == "--tool-material" && (v == "hss" || v == "carbide"))
      toolMaterial = v;
    else if (a == "--dialect" && parseDialect(v))
      options.dialect = *parseDialect(v);
    else if (a == "--machine")
      machine = v;
    else if (a == "--layer")
      dxfOptions.layer = v;
    else if (std::array<double, 3> s{}; a == "--stock" && parseStock(v, s[0], s[1], s[2]))
      stock = s;
    else if (a == "--lang" && parseLang(v))
      options.lang = *parseLang(v);
    else {
      printCliError("generate", codes::kCliBadOption, lang, {a, v});
      std::fputs(usage.c_str(), stderr);
      return 2;
    }
  }
  if (file.empty() || out.empty()) {
    printCliError("generate", codes::kCliGenerateNeeds, lang);
    std::fputs(usage.c_str(), stderr);
    return 2;
  }
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
  if (stock) {
    design.value->stockDiameter = (*stock)[0];
    design.value->stockLength = (*stock)[1];
    design.value->stockBore = (*stock)[2];
  }
  std::vector<Diagnostic> why;
  const auto program = design::generateProgram(*design.value, options, &why);
  for (const Diagnostic& d : why) printDiagnostic(stderr, file, d, options.lang);
  if (!program) return 1;
  // A read-only OUT.nc is refused, a failed write keeps the old one: exit 2 (issue 29).
  return writeOutput(out, program->text, options.lang) ? 0 : 2;
}

}  // namespace klueng::cli
