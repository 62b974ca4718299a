#pragma once
// The one message catalog: every diagnostic and alarm code with its English
// and Thai text. Texts use fmt placeholders {0} {1} ... filled from
// Diagnostic::args. The GUI and CLI call formatMessage(); tests may check that
// every code has both texts.
#include <span>
#include <string>
#include <string_view>

#include "klueng/core/diagnostic.h"

namespace klueng::core {

enum class Lang { En, Th };

struct MessageText {
  std::string_view code;
  std::string_view en;
  std::string_view th;
};

// Every catalog entry of every module.
std::span<const MessageText> allMessages();
// nullptr when the code is unknown.
const MessageText* findMessage(std::string_view code);
// Text of the diagnostic in the language; an unknown code gives the code and args.
// An argument longer than kMaxMessageArgChars code points (a 10 MB tool name, the
// layer list of a 100,000-layer drawing) is shortened in its middle, and the message
// says how much was left out (issue 42 item 6); Diagnostic::args stay whole.
std::string formatMessage(const Diagnostic& d, Lang lang);
inline constexpr std::size_t kMaxMessageArgChars = 1000;
// `text` shortened so: its first and last code points around "… [N characters left out] …".
std::string elideMessageArg(std::string_view text, Lang lang);

// Where a message is read. The CLI's texts name its flags (--stock,
// --dialect haas, --decimal-point); the GUI's name the menu items that do the
// same (File ▸ Job details, Tool setting ▸ G-code dialect), in the words of the
// GUI's own menus. Codes without such a place read the same on both.
enum class Surface { Cli, Gui };
std::string formatMessage(const Diagnostic& d, Lang lang, Surface surface);
// The GUI's own text of a code, nullptr when it reads as the CLI's.
const MessageText* findGuiMessage(std::string_view code);
// GCC style, as the CLI prints it and the GUI shows it:
// "file:line:column: error F104: text" (no line:column when the diagnostic has none).
std::string formatWithPlace(std::string_view file, const Diagnostic& d, Lang lang);
// "error", "warning", "alarm" / Thai equivalents.
std::string_view severityName(Severity s, Lang lang);

}  // namespace klueng::core
