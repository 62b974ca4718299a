// Catalog part for the gcode module: code, English, Thai. Keep codes sorted.
#include "catalog_parts.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kMessages[] = {
    {"_gcode", "(no messages yet)", "(ยังไม่มีข้อความ)"},
};
}  // namespace

std::span<const MessageText> gcodeMessages() { return kMessages; }

}  // namespace klueng::core::catalog
