// Catalog part for the design module (issue 14): part files and the generator.
#include "catalog_parts.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kMessages[] = {
    {codes::kPartUndercut,
     "Step {0} (Ø{1}) is thinner than the step before it (Ø{2}): an undercut the turning tool cannot reach from the "
     "right",
     "ขั้นที่ {0} (Ø{1}) เล็กกว่าขั้นก่อนหน้า (Ø{2}): เป็นร่องคอดที่มีดกลึงปอกเข้าไปกลึงจากทางขวาไม่ถึง"},
    {codes::kPartEdgeTooLarge, "The chamfer or round of step {0} ({1} mm) is larger than the step allows ({2} mm)",
     "ขนาดลบมุมหรือมุมโค้งของขั้นที่ {0} ({1} มม.) ใหญ่เกินกว่าที่ขั้นนี้รับได้ ({2} มม.)"},
    {codes::kPartLongerThanBar, "The part is {0} mm long: the bar leaves {1} mm outside the chuck jaws",
     "ชิ้นงานยาว {0} มม. แต่ชิ้นงานดิบยื่นออกจากปากจับได้เพียง {1} มม."},
    {codes::kPartWiderThanBar, "Step {0} (Ø{1}) is larger than the bar (Ø{2})",
     "ขั้นที่ {0} (Ø{1}) ใหญ่กว่าชิ้นงานดิบ (Ø{2})"},
    {codes::kUnknownMaterial, "No cutting speed for \"{0}\": the table has {1}",
     "ไม่มีความเร็วตัดของวัสดุ \"{0}\": ในตารางมี {1}"},
    {codes::kPartHasNoSteps, "The part has no outside steps to turn", "ชิ้นงานไม่มีขั้นด้านนอกให้กลึง"},

    {codes::kGrooveNarrow, "Groove {0} is {1} mm wide: the grooving tool's blade is {2} mm",
     "ร่องที่ {0} กว้าง {1} มม. แต่ใบมีดกลึงร่องกว้าง {2} มม."},
    {codes::kGrooveOffCylinder, "Groove {0} (Z{1} to Z{2}) does not lie on one cylinder of the part",
     "ร่องที่ {0} (Z{1} ถึง Z{2}) ไม่ได้อยู่บนทรงกระบอกเดียวของชิ้นงาน"},
    {codes::kGrooveTooDeep, "Groove {0}'s bottom Ø{1} must be above 0 and below its cylinder's Ø{2}",
     "ก้นร่องที่ {0} Ø{1} ต้องมากกว่า 0 และเล็กกว่าทรงกระบอก Ø{2}"},
    {codes::kThreadOffCylinder, "Thread {0} (Z{1} to Z{2}) is longer than its cylinder or not on one",
     "เกลียวที่ {0} (Z{1} ถึง Z{2}) ยาวกว่าทรงกระบอกหรือไม่ได้อยู่บนทรงกระบอกเดียว"},
    {codes::kThreadPitchBad, "Thread {0}'s pitch {1} mm must be from 0.25 to 6 mm and less than a third of its length",
     "ระยะพิตช์ {1} มม. ของเกลียวที่ {0} ต้องอยู่ระหว่าง 0.25 ถึง 6 มม. และน้อยกว่าหนึ่งในสามของความยาวเกลียว"},
    {codes::kBoreUndercut,
     "Bore step {0} (Ø{1}) is wider than the bore step before it (Ø{2}): the boring bar cannot reach behind it",
     "ขั้นรูคว้านที่ {0} (Ø{1}) กว้างกว่าขั้นก่อนหน้า (Ø{2}): มีดคว้านเข้าไปกลึงด้านหลังไม่ถึง"},
    {codes::kBoreEdgeTooLarge, "The chamfer or round of bore step {0} ({1} mm) is larger than the step allows ({2} mm)",
     "ขนาดลบมุมหรือมุมโค้งของขั้นรูคว้านที่ {0} ({1} มม.) ใหญ่เกินกว่าที่ขั้นนี้รับได้ ({2} มม.)"},
    {codes::kBoreInSolidBar,
     "The part has a bore (Ø{0}) but the bar is solid: give the stock a hole (\"bore\" under \"stock\", a tube) no "
     "larger than the bore; the generator does not drill",
     "ชิ้นงานมีรูคว้าน (Ø{0}) แต่ชิ้นงานดิบเป็นเพลาตัน: กำหนดรูของชิ้นงานดิบ (\"bore\" ใน \"stock\" เป็นท่อ) ไม่ใหญ่กว่ารูคว้าน "
     "เครื่องสร้างโปรแกรมยังไม่เจาะรูให้"},
    {codes::kBoreBelowHole, "Bore step {0} (Ø{1}) is smaller than the tube's hole (Ø{2})",
     "ขั้นรูคว้านที่ {0} (Ø{1}) เล็กกว่ารูของท่อชิ้นงานดิบ (Ø{2})"},
    {codes::kBoreDeeperThanPart, "The bore is {0} mm deep, deeper than the part is long ({1} mm)",
     "รูคว้านลึก {0} มม. มากกว่าความยาวชิ้นงาน ({1} มม.)"},
    {codes::kArcCannotJoin,
     "Step {0}'s arc R{1} does not meet its neighbours: from Ø{2} to Ø{3} its ends are {4} mm apart, more than 2 × R",
     "ส่วนโค้ง R{1} ของขั้นที่ {0} ไม่ต่อกับส่วนข้างเคียง: จาก Ø{2} ถึง Ø{3} ปลายทั้งสองห่างกัน {4} มม. มากกว่า 2 × R"},
    {codes::kArcNeedsUndercut,
     "Step {0}'s arc R{1} turns back toward the axis at Ø{2}: an undercut the turning tool cannot reach from the right",
     "ส่วนโค้ง R{1} ของขั้นที่ {0} วกกลับเข้าหาแกนที่ Ø{2}: เป็นร่องคอดที่มีดกลึงปอกเข้าไปกลึงจากทางขวาไม่ถึง"},
    {codes::kPartFileNotJson, "{0} is not a part file: {1}", "{0} ไม่ใช่ไฟล์ชิ้นงาน: {1}"},
    {codes::kPartFieldMissing, "{0}: \"{1}\" is missing", "{0}: ไม่มีค่า \"{1}\""},
    {codes::kPartFieldBad, "{0}: \"{1}\" must be {2}", "{0}: ค่า \"{1}\" ต้องเป็น{2}"},
    {codes::kSpeedsLineBad, "{0}: \"{1}\" is not \"material | HSS m/min | carbide m/min\"",
     "{0}: \"{1}\" ไม่อยู่ในรูป \"วัสดุ | มีด HSS ม./นาที | มีดคาร์ไบด์ ม./นาที\""},
};
}  // namespace

std::span<const MessageText> designMessages() { return kMessages; }

}  // namespace klueng::core::catalog
