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
    // Cutting data (issue 39, docs/cutting-data.md): a teacher's warnings, never errors.
    // W330/W331: {0} Vc, {1} its unit, {2}/{3} tool material en/th, {4}/{5} material en/th,
    // {6} the range's end, {7} the spindle speed that reaches it here (rpm).
    {codes::kCutSpeedHigh,
     "cutting speed {0} {1} is above the {6} {1} a {2} tool stands in {4}: the edge burns; lower the spindle speed "
     "to about S{7} (rpm, G97) or the G96 S value",
     "ความเร็วตัด {0} {1} สูงกว่า {6} {1} ที่มีด{3}ทนได้เมื่อกลึง{5}: คมมีดจะไหม้ ให้ลดความเร็วรอบลงเหลือประมาณ S{7} "
     "(รอบ/นาที G97) หรือลดค่า S ของ G96"},
    {codes::kCutSpeedLow,
     "cutting speed {0} {1} is below the {6} {1} a {2} tool wants in {4}: built-up edge and a torn surface; raise "
     "the spindle speed to about S{7} (rpm, G97) or use G96",
     "ความเร็วตัด {0} {1} ต่ำกว่า {6} {1} ที่มีด{3}ต้องการเมื่อกลึง{5}: เศษโลหะจะพอกติดคมมีดและผิวฉีก ให้เพิ่มความเร็วรอบเป็น"
     "ประมาณ S{7} (รอบ/นาที G97) หรือใช้ G96"},
    // {0} f, {1} nose radius, {2} Ra um, {3} Rz um, {4} the Ra allowed, {5} the largest feed for it, {6} unit,
    // {7}/{8} where the Ra allowed comes from (the drawing's mark, or the default), en/th
    {codes::kFinishTooRough,
     "finishing feed {0} {6}/rev with nose radius R{1} leaves Ra {2} um (Rz {3} um), rougher than Ra {4} um ({7}): "
     "use F{5} or less, or an insert with a larger nose radius",
     "อัตราป้อนกลึงละเอียด {0} {6}/รอบ กับรัศมีปลายมีด R{1} ให้ผิว Ra {2} ไมครอน (Rz {3} ไมครอน) หยาบกว่า Ra {4} ไมครอน "
     "({8}) ให้ใช้ F{5} หรือน้อยกว่า หรือใช้เม็ดมีดที่มีรัศมีปลายมีดโตกว่า"},
    // {0} ap, {1} the edge's length, {2} the largest depth for it, {3} unit
    {codes::kDepthOverEdge,
     "depth of cut {0} {3} is more than the {2} {3} the insert's {1} {3} cutting edge takes (about 2/3 of it): cut "
     "in more passes",
     "ความลึกป้อนตัด {0} {3} มากกว่า {2} {3} ที่คมตัดยาว {1} {3} ของเม็ดมีดรับได้ (ประมาณ 2/3 ของความยาวคม) "
     "ให้แบ่งกลึงหลายเที่ยว"},
    // {0} Pc kW, {1} the spindle's kW, {2} ap, {3} f, {4} unit
    {codes::kPowerOverSpindle,
     "this cut needs {0} kW at the edge (depth {2} {4}, feed {3} {4}/rev) but the spindle gives {1} kW: the spindle "
     "stalls; take a smaller depth or feed",
     "การตัดนี้ต้องใช้กำลัง {0} กิโลวัตต์ที่คมมีด (ลึก {2} {4} ป้อน {3} {4}/รอบ) แต่มอเตอร์เพลาจับงานให้ได้ {1} กิโลวัตต์: "
     "เพลาจับงานจะหยุดหมุน ให้ลดความลึกหรืออัตราป้อน"},
    // {0} torque N*m, {1} the spindle's, {2} diameter, {3} unit
    {codes::kTorqueOverSpindle,
     "this cut needs {0} N*m of torque at diameter {2} {3} but the spindle gives {1} N*m: take a smaller depth or "
     "feed",
     "การตัดนี้ต้องใช้แรงบิด {0} นิวตันเมตร ที่เส้นผ่านศูนย์กลาง {2} {3} แต่เพลาจับงานให้ได้ {1} นิวตันเมตร "
     "ให้ลดความลึกหรืออัตราป้อน"},
    {codes::kRpmOverChuck,
     "spindle speed {0} rpm is above the chuck's limit of {1} rpm: the jaws lose their grip; clamp it with G50 S{1} "
     "(G92 S on system B/C) or lower S",
     "ความเร็วรอบ {0} รอบ/นาที สูงกว่าที่หัวจับรับได้ {1} รอบ/นาที: ปากจับจะคลายแรงจับ ให้จำกัดรอบด้วย G50 S{1} "
     "(G92 S ในระบบ B/C) หรือลดค่า S"},
    {codes::kMaterialUnknown,
     "material '{0}' is not in materials.cfg: cutting speeds and power are not judged; known materials: {1}",
     "ไม่มีวัสดุ '{0}' ใน materials.cfg: จึงไม่ตรวจความเร็วตัดและกำลังตัด วัสดุที่รู้จัก: {1}"},
    {codes::kMaterialNotNamed, "the job names no material: cutting speeds and power are not judged; name one of: {0}",
     "งานนี้ไม่ได้ระบุวัสดุ: จึงไม่ตรวจความเร็วตัดและกำลังตัด ให้ระบุวัสดุอย่างใดอย่างหนึ่ง: {0}"},
};
}  // namespace

std::span<const MessageText> cutMessages() { return kCutMessages; }

}  // namespace klueng::core::catalog
