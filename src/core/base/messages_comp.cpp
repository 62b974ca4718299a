// Catalog part for the comp module: code, English, Thai. Keep codes sorted.
#include "catalog_parts.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kMessages[] = {
    {"_comp", "(no messages yet)", "(ยังไม่มีข้อความ)"},
};
}  // namespace

std::span<const MessageText> compMessages() { return kMessages; }

}  // namespace klueng::core::catalog
