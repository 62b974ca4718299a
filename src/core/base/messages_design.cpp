// Catalog part for the design module (issue 14): part files and the generator.
#include "catalog_parts.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kDesignMessages[] = {
    {codes::kPartUndercut,
     "Step {0} (Ø{1}) is thinner than the step before it (Ø{2}): an undercut the turning tool cannot reach from the "
     "right",
     "ขั้นที่ {0} (Ø{1}) เล็กกว่าขั้นก่อนหน้า (Ø{2}): เป็นร่องคอดที่มีดกลึงปอกเข้าไปกลึงจากทางขวาไม่ถึง"},
    {codes::kPartEdgeTooLarge, "The chamfer or round of step {0} ({1} mm) is larger than the step allows ({2} mm)",
     "ขนาดลบมุมหรือมุมโค้งของขั้นที่ {0} ({1} มม.) ใหญ่เกินกว่าที่ขั้นนี้รับได้ ({2} มม.)"},
    {codes::kPartLongerThanBar, "The part is {0} mm long: the bar leaves {1} mm outside the chuck jaws",
     "ชิ้นงานยาว {0} มม. แต่ชิ้นงานดิบยื่นออกจากปากจับได้เพียง {1} มม."},
    {codes::kPartWiderThanBar, "Step {0} (Ø{1}) is larger than the bar (Ø{2})", "ขั้นที่ {0} (Ø{1}) ใหญ่กว่าชิ้นงานดิบ (Ø{2})"},
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
     "The bore Ø{0} is too small to drill with the Ø{1} drill and bore out (at least Ø{2}) in a solid bar: give the "
     "stock a hole (\"bore\" under \"stock\", a tube) no larger than the bore",
     "รูคว้าน Ø{0} เล็กเกินกว่าจะเจาะด้วยดอกสว่าน Ø{1} แล้วคว้านได้ (ต้องอย่างน้อย Ø{2}) ในเพลาตัน: กำหนดรูของชิ้นงานดิบ "
     "(\"bore\" ใน \"stock\" เป็นท่อ) ไม่ใหญ่กว่ารูคว้าน"},
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
    {codes::kProgramTooLong,
     "The program would have {0} blocks, but {2} numbers blocks only from N1 to N{1}: it is not written; turn the "
     "part in fewer steps",
     "โปรแกรมจะมี {0} บล็อก แต่ {3} ใช้หมายเลขบล็อกได้เพียง N1 ถึง N{1}: จึงไม่เขียนโปรแกรม ให้ลดจำนวนขั้นของชิ้นงาน"},
    {codes::kPartFileNotJson, "{0} is not a part file: {1}", "{0} ไม่ใช่ไฟล์ชิ้นงาน: {2}"},
    {codes::kPartFieldMissing, "{0}: \"{1}\" is missing", "{0}: ไม่มีค่า \"{1}\""},
    {codes::kPartFieldBad, "{0}: \"{1}\" must be {2}", "{0}: ค่า \"{1}\" ต้องเป็น{3}"},
    {codes::kSpeedsLineBad, "{0}: \"{1}\" is not \"material | HSS m/min | carbide m/min\"",
     "{0}: \"{1}\" ไม่อยู่ในรูป \"วัสดุ | มีด HSS ม./นาที | มีดคาร์ไบด์ ม./นาที\""},
    {codes::kDxfEmpty, "{0} is empty: there is no drawing in it", "{0} ว่างเปล่า: ไม่มีแบบอยู่ในไฟล์"},
    {codes::kDxfNotDxf, "{0} is not an ASCII DXF drawing: {1}", "{0} ไม่ใช่แบบ DXF แบบข้อความ (ASCII): {2}"},
    {codes::kDxfNothingOnLayer, "{0}: there are no lines or arcs on layer \"{1}\" (layers with lines: {2})",
     "{0}: ไม่มีเส้นหรือส่วนโค้งบนเลเยอร์ \"{1}\" (เลเยอร์ที่มีเส้น: {2})"},
    {codes::kDxfPickLayer, "{0}: the drawing has lines on several layers ({1}): choose the layer of the part's outline",
     "{0}: แบบมีเส้นอยู่หลายเลเยอร์ ({1}): เลือกเลเยอร์ที่เป็นรูปร่างของชิ้นงาน"},
    {codes::kDxfUnsupportedEntity,
     "{0}: a {1} on layer \"{2}\" near X{3} Y{4}: a turned profile is read from lines, arcs and polylines only; "
     "convert it to lines and arcs",
     "{0}: มี {1} บนเลเยอร์ \"{2}\" ใกล้ X{3} Y{4}: รูปร่างงานกลึงอ่านได้จากเส้นตรง ส่วนโค้ง และโพลีไลน์เท่านั้น "
     "ให้แปลงเป็นเส้นตรงและส่วนโค้งก่อน"},
    {codes::kDxfOpenContour, "{0}: the outline is open at X{1} Y{2}: {3}", "{0}: รูปร่างไม่ปิดที่ X{1} Y{2}: {4}"},
    {codes::kDxfArcApart, "{0}: the arc R{1} ending at X{2} Y{3} does not meet its neighbours: {4}",
     "{0}: ส่วนโค้ง R{1} ที่สิ้นสุดที่ X{2} Y{3} ไม่ต่อกับเส้นข้างเคียง: {5}"},
    {codes::kDxfUnits, "{0}: the drawing's units ($INSUNITS {1}) are not a length Klueng can turn",
     "{0}: หน่วยของแบบ ($INSUNITS {1}) ไม่ใช่หน่วยความยาวที่ Klueng ใช้กลึงได้"},
    {codes::kDxfSize,
     "{0}: in {3} the part would be Ø{1} mm and {2} mm long: the drawing's units look wrong (set $INSUNITS or scale "
     "it)",
     "{0}: ในหน่วย{4} ชิ้นงานจะมีขนาด Ø{1} มม. ยาว {2} มม.: หน่วยของแบบน่าจะผิด (ตั้งค่า $INSUNITS หรือย่อขยายแบบ)"},
    {codes::kDxfBranch, "{0}: {3} lines meet at X{1} Y{2}: the part must be drawn as one outline",
     "{0}: มีเส้น {3} เส้นมาบรรจบกันที่ X{1} Y{2}: ต้องเขียนชิ้นงานเป็นรูปร่างเดียว"},
    {codes::kDxfTurnsBack,
     "{0}: the outline runs back toward the right-hand face at X{1} Y{2}: a turned profile runs one way along the axis",
     "{0}: รูปร่างย้อนกลับไปทางหน้าด้านขวาที่ X{1} Y{2}: รูปร่างงานกลึงต้องไปทางเดียวตามแนวแกน"},
    {codes::kDxfSeveralOutlines,
     "{0}: layer \"{2}\" holds {1} separate outlines: put only the part's half section on it",
     "{0}: เลเยอร์ \"{2}\" มีรูปร่างแยกกัน {1} รูป: ให้มีเฉพาะรูปตัดครึ่งของชิ้นงานบนเลเยอร์นี้"},
    {codes::kNotAsDrawn, "The drawing's {0} (Z{1} to Z{2}) is not on the cut part within 0.01 mm: there it is {3}",
     "{0} ตามแบบ (Z{1} ถึง Z{2}) ไม่มีบนชิ้นงานที่กลึงได้ภายใน 0.01 มม.: ตรงนั้นเป็น {3}"},
    {codes::kDxfReachesAxis,
     "{0}: the outline comes down to the axis at X{1} Y{2} before the part's left end: no step of a turned part is "
     "Ø0",
     "{0}: รูปร่างลงมาถึงแนวแกนที่ X{1} Y{2} ก่อนถึงปลายซ้ายของชิ้นงาน: ขั้นของงานกลึงต้องไม่มี Ø0"},
    {codes::kDxfArcTooFlat,
     "{0}: the arc R{1} ending at X{2} Y{3} is over 10000 mm, the largest radius a part design holds: draw it as "
     "a line, or check the drawing's units",
     "{0}: ส่วนโค้ง R{1} ที่สิ้นสุดที่ X{2} Y{3} มีรัศมีเกิน 10000 มม. ซึ่งเป็นรัศมีใหญ่สุดที่แบบชิ้นงานรับได้: "
     "เขียนเป็นเส้นตรงแทน หรือตรวจหน่วยของแบบ"},
    {codes::kDxfArcInBore,
     "{0}: the bore has an arc R{1} ending at X{2} Y{3}: a part design bores cylinders and tapers (with a chamfer "
     "or round at their mouth) only",
     "{0}: รูคว้านมีส่วนโค้ง R{1} ที่สิ้นสุดที่ X{2} Y{3}: แบบชิ้นงานคว้านรูได้เฉพาะทรงกระบอกและเรียว "
     "(ลบมุมหรือมนที่ปากรูได้)"},
    {codes::kDxfInches, "{0}: the drawing is in {2}: sizes multiplied by {1} to millimetres",
     "{0}: แบบใช้หน่วย{3}: คูณขนาดด้วย {1} เป็นมิลลิเมตร"},
};
}  // namespace

std::span<const MessageText> designMessages() { return kDesignMessages; }

}  // namespace klueng::core::catalog
