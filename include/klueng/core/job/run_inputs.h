#pragma once
// Every file a run reads (issue 42 item 2), so that no output replaces one:
// the CLI's output options and the GUI's exports and screenshot refuse a name
// in this list with F126 (io::outputOverwritesInput).
#include <string>
#include <vector>

#include "klueng/core/job/job.h"
#include "klueng/core/machine/setup_files.h"

namespace klueng::core::job {

// What a run with `loaded` reads besides its program: tools.cfg, offset.cfg,
// machine.cfg and macro_variables.cfg of its folder, each station's tool
// picture, the tool library (library.cfg and its pictures), the cutting-speed
// table and the machine files of the machines folders. Missing files are listed too.
std::vector<std::string> setupInputFiles(const machine::LoadedSetup& loaded);

// The program `path`, the subprogram files `job` read, and setupInputFiles(loaded).
std::vector<std::string> runInputFiles(const std::string& path, const Job* job, const machine::LoadedSetup& loaded);

}  // namespace klueng::core::job
