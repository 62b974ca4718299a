// Catalog part for the cut module: code, English, Thai. Keep codes sorted.
// Alarm args: {0} = Z, {1} = X (diameter) of the controlled point where it happened.
// Part check (W320-W323): {0}-{4} in the display unit, {5} its name (units.h: kUnitArgMm/kUnitArgInch).
#include "catalog_parts.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kCutMessages[] = {
    {codes::kRapidIntoStock, "Rapid move runs into the stock at Z{0} X{1}: a rapid move may not remove material",
     "การเคลื่อนที่เร็วชนชิ้นงานที่ Z{0} X{1}: การเคลื่อนที่เร็วต้องไม่ตัดเนื้อชิ้นงาน"},
    {codes::kCutWithSpindleStopped, "Cutting while the spindle is not turning, at Z{0} X{1}",
     "มีดตัดกินเนื้อชิ้นงานขณะเพลาจับงานหยุดหมุน ที่ Z{0} X{1}"},
    {codes::kHolderHitsStock, "The tool holder hits the stock at Z{0} X{1}", "ด้ามจับมีดชนชิ้นงานที่ Z{0} X{1}"},
    {codes::kToolHitsChuck, "The tool hits the chuck at Z{0} X{1}", "มีดตัดชนหัวจับ (ชัค) ที่ Z{0} X{1}"},
    // A tool Klueng guessed from the program (issue 26): the shop's real tool was another.
    {codes::kGuessHitsStock,
     "the holder of {1}, guessed for T{0}, touches the stock at Z{2} X{3}, {4} mm deep: the real tool needs {4} mm "
     "more "
     "reach here (a longer blade, a slimmer bar) than any of the library's; choose it in Tool Select",
     "ด้ามของ {1} ที่เดาไว้สำหรับ T{0} แตะชิ้นงานที่ Z{2} X{3} ลึก {4} มม.: มีดจริงต้องยื่นได้ลึกกว่านี้อีก {4} มม. "
     "(ใบมีดที่ยาวกว่า หรือด้ามคว้านที่เล็กกว่า) ซึ่งไม่มีในคลังมีด ให้เลือกมีดจริงในหน้าเลือกมีด"},
    {codes::kGuessEdgeBrushesStock,
     "the edge of {1}, guessed for T{0}, brushes the stock by less than 0.2 mm in a rapid at Z{2} X{3}: the shop's "
     "real insert is shaped otherwise; choose it in Tool Select",
     "คมของ {1} ที่เดาไว้สำหรับ T{0} เฉี่ยวชิ้นงานไม่ถึง 0.2 มม. ขณะเคลื่อนเร็วที่ Z{2} X{3}: เม็ดมีดจริงของโรงงานมีรูปร่างต่างออกไป "
     "ให้เลือกมีดจริงในหน้าเลือกมีด"},
    {codes::kGuessHitsChuck,
     "the body of {1}, guessed for T{0}, touches the chuck at Z{2} X{3}: the real tool is shorter or slimmer there "
     "than "
     "any of the library's; choose it in Tool Select",
     "ตัวมีด {1} ที่เดาไว้สำหรับ T{0} แตะหัวจับที่ Z{2} X{3}: มีดจริงของโรงงานสั้นกว่าหรือเล็กกว่ามีดในคลังตรงนี้ "
     "ให้เลือกมีดจริงในหน้าเลือกมีด"},
    {codes::kBitmapHasNoEdge,
     "Tool bitmap {0} has no cutting-edge pixels (every colour other than black and white is cutting edge)",
     "ภาพมีดตัด {0} ไม่มีจุดภาพของคมตัด (สีอื่นที่ไม่ใช่สีดำและสีขาวคือคมตัด)"},
    {codes::kBitmapTooLarge,
     "Tool bitmap {0} is {1} x {2} pixels; a tool bitmap may be at most {3} x {3} pixels (2 pixels per mm)",
     "ภาพมีดตัด {0} มีขนาด {1} x {2} จุดภาพ ซึ่งใหญ่เกินไป ภาพมีดตัดต้องไม่เกิน {3} x {3} จุดภาพ (2 จุดภาพต่อ มม.)"},
    {codes::kPartGouge,
     "Gouge {0} {5} deep from Z{1} to Z{2} (deepest at Z{3}, Ø{4}): the tool's edge cut into the part the program "
     "describes",
     "มีดตัดกินเนื้อชิ้นงานเกินแบบ ลึก {0} {5} จาก Z{1} ถึง Z{2} (ลึกที่สุดที่ Z{3} Ø{4}): คมตัดของมีดตัดเข้าไปในรูปชิ้นงานที่โปรแกรมกำหนด"},
    {codes::kPartLeftover,
     "Material left {0} {5} from Z{1} to Z{2} (most at Z{3}, Ø{4}): this block's path should have removed it",
     "เนื้อชิ้นงานเหลือเกินแบบ {0} {5} จาก Z{1} ถึง Z{2} (มากที่สุดที่ Z{3} Ø{4}): เส้นทางของบล็อกนี้ควรตัดออก"},
    {codes::kBoreGouge,
     "Gouge in the bore {0} {5} deep from Z{1} to Z{2} (deepest at Z{3}, Ø{4}): the tool's edge cut into the part "
     "the program describes",
     "มีดตัดกินเนื้อผิวรูเกินแบบ ลึก {0} {5} จาก Z{1} ถึง Z{2} (ลึกที่สุดที่ Z{3} Ø{4}): คมตัดของมีดตัดเข้าไปในรูปชิ้นงานที่โปรแกรมกำหนด"},
    {codes::kBoreLeftover,
     "Material left in the bore {0} {5} from Z{1} to Z{2} (most at Z{3}, Ø{4}): this block's path should have "
     "removed it",
     "เนื้อชิ้นงานในรูเหลือเกินแบบ {0} {5} จาก Z{1} ถึง Z{2} (มากที่สุดที่ Z{3} Ø{4}): เส้นทางของบล็อกนี้ควรตัดออก"},
    {codes::kPartCheckStopped, "The run stopped on alarm {0} here: the part check compares what was cut up to it",
     "การทำงานหยุดด้วยสัญญาณเตือน {0} ที่บรรทัดนี้: การตรวจชิ้นงานเปรียบเทียบเฉพาะส่วนที่ตัดไปแล้วจนถึงจุดนั้น"},
    {codes::kPartCheckNothingCut, "Part check: no move cut the stock, so there is no part to check",
     "การตรวจชิ้นงาน: ไม่มีการเคลื่อนที่ใดตัดเนื้อชิ้นงาน จึงไม่มีชิ้นงานให้ตรวจ"},
};
}  // namespace

std::span<const MessageText> cutMessages() { return kCutMessages; }

}  // namespace klueng::core::catalog
