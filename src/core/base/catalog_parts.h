#pragma once
// Each module keeps its own part of the catalog in messages_<module>.cpp.
#include <span>

#include "klueng/core/messages.h"

namespace klueng::core::catalog {
std::span<const MessageText> gcodeMessages();
std::span<const MessageText> ioMessages();
std::span<const MessageText> machineMessages();
std::span<const MessageText> compMessages();
std::span<const MessageText> cutMessages();
std::span<const MessageText> designMessages();
std::span<const MessageText> cliMessages();
std::span<const MessageText> controlMessages();
std::span<const MessageText> renderMessages();
}  // namespace klueng::core::catalog
