// Catalog part for the operator panel (core/control, issue 31): code, English, Thai.
// {0} of A601/A602 is the control's own alarm (number and text as the control shows it).
#include "catalog_parts.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kControlMessages[] = {
    {codes::kNotReferenced, "{0}: axis {1} has not returned to the reference point; do ZERO RETURN first",
     "{0}: แกน {1} ยังไม่ได้กลับสู่จุดอ้างอิง ต้องทำ ZERO RETURN (กลับจุดอ้างอิงเครื่อง) ก่อน"},
    {codes::kOvertravel, "{0}: {1} stops at its travel limit {2} (machine position)",
     "{0}: แกน {1} หยุดที่ขีดจำกัดระยะเคลื่อนที่ {2} (ตำแหน่งเครื่อง)"},
    {codes::kTouchedSpindleStopped,
     "tool T{0} touched the bar at Z{1} X{2} with the spindle stopped: start the spindle before touching off, a still "
     "bar chips the insert and gives no true cut",
     "มีด T{0} แตะชิ้นงานที่ Z{1} X{2} ขณะเพลาจับงานหยุดหมุน: ต้องเปิดเพลาจับงานก่อนแตะมีด ชิ้นงานที่ไม่หมุนทำให้เม็ดมีดบิ่นและไม่ได้ผิวกลึงจริง"},
    {codes::kMeasuredAfterStoppedTouch,
     "offset {0} measured from a touch with the spindle stopped: the value may be off; touch again with the spindle "
     "turning",
     "วัดค่าออฟเซต {0} จากการแตะขณะเพลาจับงานหยุดหมุน ค่าอาจคลาดเคลื่อน ควรแตะใหม่ขณะเพลาจับงานหมุน"},
    {codes::kMeasureWithoutTool, "station T{0} has no tool: index the turret to the tool being touched off",
     "สถานี T{0} ไม่มีมีด ต้องหมุนป้อมมีดไปยังมีดที่กำลังตั้งศูนย์"},
    {codes::kKeyNotInMode, "{0} works in {1} mode", "ปุ่ม {0} ใช้ได้ในโหมด {1}"},
    {codes::kResetFirst, "alarm {0} is on: press RESET first", "มีสัญญาณเตือน {0} อยู่ ต้องกด RESET ก่อน"},
    {codes::kNotMeasureInput,
     "'{0}' is not an axis and a value: type X and the measured diameter, or Z and the face position (Z0)",
     "'{0}' ไม่ใช่แกนและค่า ต้องพิมพ์ X ตามด้วยขนาดโตที่วัดได้ หรือ Z ตามด้วยตำแหน่งผิวหน้า (Z0)"},
    {codes::kToolsNotTouchedOff, "the offsets are unknown: touch off {0} (X and Z) before cycle start",
     "ยังไม่รู้ค่าออฟเซต ต้องตั้งศูนย์มีด {0} (ทั้ง X และ Z) ก่อนกด CYCLE START"},
    {codes::kFeedOverrideZero, "feed override is 0 %: the axes do not move", "ปรับอัตราป้อนไว้ที่ 0 % แกนจึงไม่เคลื่อนที่"},
    {codes::kOffsetsCompared, "touch-off: offset {0} is off by X{1} (diameter) Z{2} mm, the largest of the tools used",
     "การตั้งศูนย์มีด: ออฟเซต {0} คลาดเคลื่อน X{1} (ขนาดโต) Z{2} มม. มากที่สุดในบรรดามีดที่ใช้"},
    {codes::kTouchOffWithin, "T{0} touched off at X{1} Z{2}, true X{3} Z{4}: within {5} mm",
     "T{0} ตั้งศูนย์ได้ X{1} Z{2} ค่าจริง X{3} Z{4}: อยู่ในพิกัด {5} มม."},
    {codes::kTouchOffOutside, "T{0} touched off at X{1} Z{2}, true X{3} Z{4}: outside {5} mm",
     "T{0} ตั้งศูนย์ได้ X{1} Z{2} ค่าจริง X{3} Z{4}: เกินพิกัด {5} มม."},
    {codes::kTouchOffNotSaved,
     "the offsets are unknown but {0} was not found{1}: touch off at the Operator panel, then MEM + CYCLE START saves "
     "it",
     "โจทย์ไม่บอกค่าออฟเซต แต่ไม่พบไฟล์ {0}{1} ต้องตั้งศูนย์มีดที่แผงควบคุมเครื่อง แล้วกด MEM + CYCLE START เพื่อบันทึก"},
};
}  // namespace

std::span<const MessageText> controlMessages() { return kControlMessages; }

}  // namespace klueng::core::catalog
