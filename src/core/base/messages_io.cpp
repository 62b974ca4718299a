// Catalog part for the io module: code, English, Thai. Keep codes sorted.
#include "catalog_parts.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kMessages[] = {
    {"_io", "(no messages yet)", "(ยังไม่มีข้อความ)"},
};
}  // namespace

std::span<const MessageText> ioMessages() { return kMessages; }

}  // namespace klueng::core::catalog
