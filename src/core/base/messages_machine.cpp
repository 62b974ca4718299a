// Catalog part for the machine module: code, English, Thai. Keep codes sorted.
#include "catalog_parts.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kMessages[] = {
    {"_machine", "(no messages yet)", "(ยังไม่มีข้อความ)"},
};
}  // namespace

std::span<const MessageText> machineMessages() { return kMessages; }

}  // namespace klueng::core::catalog
