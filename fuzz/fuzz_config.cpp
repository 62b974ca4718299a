// libFuzzer target: the io readers (tools.cfg, offset.cfg, machine.cfg, the
// program file and tool bitmaps) on arbitrary bytes. The first byte picks
// the reader so one corpus serves all of them.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "klueng/core/io/image.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/messages.h"

using namespace klueng::core;

namespace {

template <typename T>
void checkDiagnostics(const io::ReadResult<T>& r) {
  for (const Diagnostic& d : r.diagnostics) {
    (void)formatMessage(d, Lang::En);
    (void)formatMessage(d, Lang::Th);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  switch (data[0] % 5) {
    case 0: {
      const auto r = io::parseToolTable(bytes, "/tmp", "tools.cfg");
      checkDiagnostics(r);
      if (r.value) (void)io::formatToolTable(*r.value);
      break;
    }
    case 1: {
      const auto r = io::parseOffsetTable(bytes, "offset.cfg");
      checkDiagnostics(r);
      if (r.ok()) {
        // What the dialog writes, the loader must read back.
        const auto again = io::parseOffsetTable(io::formatOffsetTable(*r.value), "offset.cfg");
        if (!again.ok()) std::abort();
      }
      break;
    }
    case 2: {
      const auto r = io::parseMachineConfig(bytes, "machine.cfg");
      checkDiagnostics(r);
      if (r.ok()) {
        const auto again = io::parseMachineConfig(io::formatMachineConfig(*r.value), "machine.cfg");
        if (!again.ok()) std::abort();
      }
      break;
    }
    case 3: {
      const auto r = io::parseProgramFile(bytes);
      checkDiagnostics(r);
      if (r.value) (void)io::formatProgramFile(*r.value);
      break;
    }
    default: {
      const auto r = io::decodeImage(bytes, "tool.bmp");
      checkDiagnostics(r);
      if (r.value) {
        const io::RgbImage& img = *r.value;
        if (img.width <= 0 || img.height <= 0 ||
            img.pixels.size() != static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height))
          std::abort();
      }
      break;
    }
  }
  return 0;
}
