#pragma once
// Helpers for the generator's tests: read a shipped part, turn a generated
// program (compile, run, cut), find a feature of the cut part by its label.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/design/part_design.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/cut/part_check.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/setup_files.h"

namespace klueng::core::design {

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline PartDesign stepShaft() {
  const auto d = readPartDesign(slurp(KLUENG_SOURCE_DIR "/resources/parts/step-shaft.json"), "step-shaft.json");
  EXPECT_TRUE(d.ok());
  return *d.value;
}

struct Turned {
  std::shared_ptr<const job::Job> job;
  machine::Timeline programmed;  // the part check's programmed path
  std::unique_ptr<cut::CutSimulator> sim;
};

inline Turned turn(const std::string& text, gcode::Dialect dialect, const machine::MachineSetup& setup) {
  Turned t;
  const auto file = io::parseProgramFile(text);
  EXPECT_TRUE(file.value.has_value());
  job::JobInput input;
  input.file = *file.value;
  input.setup = setup;
  input.run.dialect = dialect;
  input.inferTools = false;  // the generated program's own setup
  t.job = job::makeJob(input);
  for (const Diagnostic& d : t.job->diagnostics())
    EXPECT_NE(d.severity, Severity::Error) << d.code << " line " << d.range.line << "\n" << text;
  if (!t.job->timeline()) return t;
  t.programmed = cut::programmedPath(*t.job->program(), setup, input.run, *t.job->timeline());
  t.sim = std::make_unique<cut::CutSimulator>(*t.job->timeline(), cut::CutSetup::from(file.value->header, setup));
  t.sim->runToEnd();
  return t;
}

// The generator's options for a dialect on this machine.
inline GenerateOptions optionsFor(gcode::Dialect dialect, const machine::MachineSetup& setup) {
  GenerateOptions options;
  options.dialect = dialect;
  options.machine = setup.machine;
  return options;
}

inline const cut::PartFeature* find(const cut::PartFeatures& p, cut::FeatureKind kind, const std::string& label,
                                    bool inside = false) {
  for (const cut::PartFeature& f : inside ? p.inside : p.outside)
    if (f.kind == kind && cut::featureLabel(f, Lang::En) == label) return &f;
  return nullptr;
}

}  // namespace klueng::core::design
