// klueng-cli generate PART.json -o OUT.nc [--dialect fanuc|haas|classic] [--material M]
//                   [--tool-material hss|carbide] [--lang en|th] [--config DIR]
// Issue 14: a part design (docs/parts.md) to a complete program, written atomically.
// Exit 0 written, 1 the part cannot be turned (reasons on stderr), 2 bad use or files.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.h"
#include "commands.h"
#include "klueng/core/design/part_design.h"
#include "klueng/core/io/program_file.h"

namespace klueng::cli {

using namespace klueng::core;

namespace {

constexpr const char* kGenerateUsage =
    "usage: klueng-cli generate PART.json -o OUT.nc [--dialect fanuc|haas|classic] [--material NAME]\n"
    "                           [--tool-material hss|carbide] [--lang en|th] [--config DIR]\n"
    "  the part file's format: docs/parts.md; cutting speeds: resources/parts/cutting_speeds.cfg\n";

std::string slurp(const std::string& path, bool& ok) {
  std::string out;
  ok = false;
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) out.append(buf, n);
    ok = !std::ferror(f);
    std::fclose(f);
  }
  return out;
}

}  // namespace

int runGenerate(const std::vector<std::string>& args) {
  if (std::find(args.begin(), args.end(), "--help") != args.end()) {
    std::fputs(kGenerateUsage, stdout);
    return 0;
  }
  std::string file, out, configDir;
  std::optional<std::string> material, toolMaterial;
  design::GenerateOptions options;
  options.lang = langFromLocale();
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("-", 0) != 0) {
      file = a;
      continue;
    }
    if (i + 1 >= args.size()) {
      std::fputs(kGenerateUsage, stderr);
      return 2;
    }
    const std::string v = args[++i];
    if (a == "-o" || a == "--output") out = v;
    else if (a == "--config") configDir = v;
    else if (a == "--material") material = v;
    else if (a == "--tool-material" && (v == "hss" || v == "carbide")) toolMaterial = v;
    else if (a == "--dialect" && parseDialect(v)) options.dialect = *parseDialect(v);
    else if (a == "--lang" && parseLang(v)) options.lang = *parseLang(v);
    else {
      std::fprintf(stderr, "klueng-cli generate: bad option %s %s\n", a.c_str(), v.c_str());
      std::fputs(kGenerateUsage, stderr);
      return 2;
    }
  }
  if (file.empty() || out.empty()) {
    std::fputs(kGenerateUsage, stderr);
    return 2;
  }
  const LoadedConfig config = loadConfig(configDir);
  for (const auto& fd : config.diagnostics) printDiagnostic(stderr, fd.file, fd.diagnostic, options.lang);
  if (config.unreadable || config.hasErrors()) return 2;
  options.machine = config.setup.machine;
  bool readable = false;
  const std::string text = slurp(file, readable);
  if (!readable) {
    std::fprintf(stderr, "klueng-cli generate: cannot read %s\n", file.c_str());
    return 2;
  }
  auto design = design::readPartDesign(text, file);
  for (const Diagnostic& d : design.diagnostics) printDiagnostic(stderr, file, d, options.lang);
  if (!design.ok()) return 2;
  if (material) design.value->material = *material;
  if (toolMaterial) design.value->toolMaterial = *toolMaterial;
  std::vector<Diagnostic> why;
  const auto program = design::generateProgram(*design.value, options, &why);
  for (const Diagnostic& d : why) printDiagnostic(stderr, file, d, options.lang);
  if (!program) return 1;
  std::string error;
  if (!io::writeTextFileAtomic(out, program->text, &error)) {
    std::fprintf(stderr, "klueng-cli generate: cannot write %s: %s\n", out.c_str(), error.c_str());
    return 2;
  }
  return 0;
}

}  // namespace klueng::cli
