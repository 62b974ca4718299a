// klueng-png.so: the section picture as PNG bytes, for klueng-cli --png. A module
// the CLI opens only when a picture is asked for, so `check` and `simulate`
// without --png never load Qt (it costs ~5 ms of start-up per run).
#include "render/module_bytes.h"
#include "render/section_painter.h"

extern "C" __attribute__((visibility("default"))) int klueng_section_png(const klueng::render::SectionPicture* picture,
                                                                         char** bytes, std::size_t* size) {
  if (!picture || !bytes || !size) return 0;
  return klueng::render::handBytes(klueng::render::sectionPicturePng(*picture), bytes, size);
}
