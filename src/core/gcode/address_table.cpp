// The address letters (address_table.h). The Thai is a lathe teacher's
// (GLOSSARY.md): แกน, เส้นผ่านศูนย์กลาง, อัตราป้อน, ความเร็วรอบ, มีดตัด, ค่าออฟเซต.
#include "klueng/core/gcode/address_table.h"

#include <algorithm>
#include <array>

namespace klueng::core::gcode {

namespace {

using K = AddressKind;

constexpr std::array<AddressInfo, 23> kAddresses{{
    {'A', K::Parameter, true, "thread angle in degrees (Haas G76)", "มุมของเกลียว หน่วยองศา (G76 ของ Haas)"},
    {'C', K::Axis, true, "spindle angle in C-axis mode (absolute, degrees)",
     "มุมของเพลาหัวจับในโหมดควบคุมการเคลื่อนที่ของแกน C (ค่าสัมบูรณ์, องศา)"},
    {'D', K::Parameter, true, "cycle parameter (Haas: depth of cut, relief)",
     "ค่าพารามิเตอร์ของวัฏจักร (Haas: ความลึกตัด ระยะถอย)"},
    {'E', K::Parameter, true, "cycle parameter (Haas cycles)", "ค่าพารามิเตอร์ของวัฏจักร (วัฏจักรของ Haas)"},
    {'F', K::FeedSpeed, true, "feed rate (mm/rev under G99, mm/min under G98, lead for G32)",
     "อัตราป้อน (มม./รอบ เมื่อใช้ G99, มม./นาที เมื่อใช้ G98, ระยะพิตช์เกลียวสำหรับ G32)"},
    {'G', K::GCode, false, "preparatory function (G code)", "รหัสคำสั่งเตรียมการ (รหัส G)"},
    {'H', K::Axis, true, "spindle angle in C-axis mode (incremental, degrees)",
     "มุมของเพลาหัวจับในโหมดควบคุมการเคลื่อนที่ของแกน C (ค่าสัมพัทธ์, องศา)"},
    {'I', K::Axis, true, "arc centre in X from the start point (radius)", "จุดศูนย์กลางส่วนโค้งในแนวแกน X วัดจากจุดเริ่ม (รัศมี)"},
    {'J', K::Parameter, true, "cycle parameter (Haas cycles)", "ค่าพารามิเตอร์ของวัฏจักร (วัฏจักรของ Haas)"},
    {'K', K::Axis, true, "arc centre in Z from the start point", "จุดศูนย์กลางส่วนโค้งในแนวแกน Z วัดจากจุดเริ่ม"},
    {'L', K::Parameter, false, "repeat count (M98, G65)", "จำนวนครั้งที่ทำซ้ำ (M98, G65)"},
    {'M', K::MCode, false, "miscellaneous function (M code)", "รหัสคำสั่งช่วย (รหัส M)"},
    {'N', K::Sequence, true, "sequence (block) number", "หมายเลขบล็อก"},
    {'O', K::Program, true, "program number", "หมายเลขโปรแกรม"},
    {'P', K::FeedSpeed, false, "dwell time in ms, or a cycle/subprogram parameter",
     "เวลาหยุดรอ (มิลลิวินาที) หรือค่าพารามิเตอร์ของวัฏจักร/โปรแกรมย่อย"},
    {'Q', K::FeedSpeed, false, "cycle parameter", "ค่าพารามิเตอร์ของวัฏจักรการกลึง"},
    {'R', K::Axis, true, "arc radius or cycle value", "รัศมีส่วนโค้ง หรือค่าของวัฏจักรการกลึง"},
    {'S', K::FeedSpeed, true, "spindle speed (rpm under G97, m/min under G96)",
     "ความเร็วรอบ (รอบ/นาที เมื่อใช้ G97, ม./นาที เมื่อใช้ G96)"},
    {'T', K::Tool, true, "tool number (first two digits) and offset number (last two)",
     "หมายเลขมีดตัด (สองหลักแรก) และหมายเลขค่าออฟเซต (สองหลักหลัง)"},
    {'U', K::Axis, true, "incremental X move (diameter)", "ระยะเคลื่อนที่แกน X แบบสัมพัทธ์ (เส้นผ่านศูนย์กลาง)"},
    {'W', K::Axis, true, "incremental Z move", "ระยะเคลื่อนที่แกน Z แบบสัมพัทธ์"},
    {'X', K::Axis, true, "X position (diameter)", "ตำแหน่งแกน X (เส้นผ่านศูนย์กลาง)"},
    {'Z', K::Axis, true, "Z position", "ตำแหน่งแกน Z"},
}};

}  // namespace

std::span<const AddressInfo> addressTable() { return kAddresses; }

const AddressInfo* addressInfo(char letter) {
  const auto it = std::lower_bound(kAddresses.begin(), kAddresses.end(), letter,
                                   [](const AddressInfo& a, char l) { return a.letter < l; });
  return it != kAddresses.end() && it->letter == letter ? &*it : nullptr;
}

}  // namespace klueng::core::gcode
