// Catalog part for the cut module: code, English, Thai. Keep codes sorted.
#include "catalog_parts.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kMessages[] = {
    {"_cut", "(no messages yet)", "(ยังไม่มีข้อความ)"},
};
}  // namespace

std::span<const MessageText> cutMessages() { return kMessages; }

}  // namespace klueng::core::catalog
