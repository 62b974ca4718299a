#pragma once
// The address letters of a lathe program (issue 12): one table says what each
// letter is (its kind, whether a block may hold it once only) and what it
// means in English and Thai. The checker, the editor's colours and tool tips
// read it; nothing else keeps a switch over letters.
#include <span>
#include <string_view>

namespace klueng::core::gcode {

enum class AddressKind {
  GCode,      // G
  MCode,      // M
  Tool,       // T
  Axis,       // X Z U W I K R C H: positions, centres, radii, spindle angles
  FeedSpeed,  // F S, and P Q (dwell, cycle and call parameters)
  Parameter,  // A D E J L: cycle words of the Haas forms, repeat counts
  Sequence,   // N
  Program,    // O
};

struct AddressInfo {
  char letter;
  AddressKind kind;
  bool oncePerBlock;           // SPEC 4 rule 2: at most once in a block
  std::string_view meaningEn;  // "X position (diameter)"
  std::string_view meaningTh;
};

// Every lathe address, in alphabetical order.
std::span<const AddressInfo> addressTable();
// The entry of an upper-case letter; nullptr for a letter that is no lathe address (B, V, Y).
const AddressInfo* addressInfo(char letter);

// What a T word's number selects: the turret station (all but the last two
// digits) and the offset (the last two): T0303 -> 3 and 3, T0100 -> 1 and 0.
struct ToolNumber {
  int station = 0;
  int offset = 0;
};
constexpr ToolNumber splitToolNumber(long long number) {
  return {static_cast<int>(number / 100), static_cast<int>(number % 100)};
}

}  // namespace klueng::core::gcode
