// The code table (SPEC 4, 6, 7, 13): one row per G code and dialect meaning (the M codes: code_table_m.cpp),
// the G-code systems B and C, and the lookups over every row.
#include "klueng/core/gcode/code_table.h"

#include <algorithm>

#include <array>
#include <cmath>
#include <cstdint>

#include "code_index.h"
#include "code_table_rows.h"
#include "klueng/core/gcode/program.h"

#include <fmt/format.h>

#include <string>
#include <vector>

namespace klueng::core::gcode {

namespace {

using namespace table_rows;

// clang-format off: one code per block of lines, its facts in the same places.
constexpr CodeInfo kGRows[] = {
    // --- G codes -------------------------------------------------------------
    {'G',
     0,
     G::Motion,
     P::Motion,
     kAll,
     kNoFlags,
     A::Rapid,
     "Rapid traverse",
     "การเคลื่อนที่เร็ว",
     "G00 X52. Z2. - rapid to diameter 52, 2 mm in front of the face",
     "G00 X52. Z2. - เคลื่อนที่เร็วไปที่เส้นผ่าศก. 52 ห่างหน้างาน 2 มม.",
     {"move at rapid speed, not cutting", "เคลื่อนที่เร็วโดยไม่ตัดเฉือน"},
     "rapid positioning traverse fast move เคลื่อนที่เร็ว"},
    {'G',
     1,
     G::Motion,
     P::Motion,
     kAll,
     kNoFlags,
     A::Line,
     "Linear interpolation",
     "การเคลื่อนที่เป็นเส้นตรง",
     "G01 Z-30. F0.2 - cut in a straight line to Z-30 at 0.2 mm/rev",
     "G01 Z-30. F0.2 - กลึงเป็นเส้นตรงไปที่ Z-30 ด้วยอัตราป้อน 0.2 มม./รอบ",
     {"cut in a straight line", "กลึงเป็นเส้นตรง"},
     "linear straight line feed cut turning taper กลึงเส้นตรง กลึงปอก กลึงเรียว"},
    {'G',
     2,
     G::Motion,
     P::Motion,
     kAll,
     kNoFlags,
     A::ArcCw,
     "Circular interpolation, clockwise",
     "การเคลื่อนที่เป็นส่วนโค้งตามเข็มนาฬิกา",
     "G02 X30. Z-24. R4. - clockwise arc of radius 4 to X30 Z-24",
     "G02 X30. Z-24. R4. - กลึงส่วนโค้งตามเข็มนาฬิการัศมี 4 มม. ไปที่ X30 Z-24",
     {"cut a clockwise arc", "กลึงส่วนโค้งตามเข็มนาฬิกา"},
     kArcWords},
    {'G',
     3,
     G::Motion,
     P::Motion,
     kAll,
     kNoFlags,
     A::ArcCcw,
     "Circular interpolation, counter-clockwise",
     "การเคลื่อนที่เป็นส่วนโค้งทวนเข็มนาฬิกา",
     "G03 X40. Z-22. R2. - counter-clockwise arc of radius 2 to X40 Z-22",
     "G03 X40. Z-22. R2. - กลึงส่วนโค้งทวนเข็มนาฬิการัศมี 2 มม. ไปที่ X40 Z-22",
     {"cut a counter-clockwise arc", "กลึงส่วนโค้งทวนเข็มนาฬิกา"},
     kArcWords},
    {'G',
     4,
     G::NonModal,
     P::Motion,
     kAll,
     kNoFlags,
     A::Dwell,
     "Dwell",
     "การหยุดรอ (หน่วงเวลา)",
     "G04 U0.5 - wait 0.5 s (G04 P500 waits 500 ms)",
     "G04 U0.5 - หยุดรอ 0.5 วินาที (G04 P500 หยุดรอ 500 มิลลิวินาที)",
     {"wait with the tool standing still", "หยุดรอโดยมีดอยู่กับที่"},
     "dwell wait pause delay หยุดรอ หน่วงเวลา",
     WordKinds().dwell("P")},
    {'G',
     9,
     G::ExactStop,
     P::State,
     kFH,
     kNoFlags,
     A::None,
     "Exact stop",
     "หยุดตรงตำแหน่ง",
     "G09 G01 X40. - stop exactly at X40 before the next block (the path does not change)",
     "G09 G01 X40. - หยุดให้ตรง X40 ก่อนทำบล็อกถัดไป (เส้นทางไม่เปลี่ยน)",
     {"stop exactly at the end point, this block only", "หยุดให้ตรงจุดปลายเฉพาะบล็อกนี้"},
     "exact stop sharp corner in position หยุดตรงตำแหน่ง มุมคม"},
    // Fanuc 16i/18i-TB B-63524EN/01 §14.5.2 (0i-TF the same): offsets from the program. Haas lathes
    // read G10 L P for offsets too (docs/dialects.md).
    {'G',
     10,
     G::NonModal,
     P::State,
     kFH,
     kNoFlags,
     A::DataSetting,
     "Programmable data input (offsets)",
     "ป้อนข้อมูลชดเชยจากโปรแกรม",
     "G10 P10001 X0 Z0 R0.8 Q3 - write geometry offset 01 (P1: its wear)",
     "G10 P10001 X0 Z0 R0.8 Q3 - เขียนค่าชดเชยรูปทรงของออฟเซต 01 (P1: ค่าสึกหรอ)",
     {"write an offset from the program: it counts from the next T word", "เขียนค่าชดเชยจากโปรแกรม มีผลตั้งแต่คำสั่ง T ถัดไป"},
     "g10 offset data setting wear geometry tool offset ค่าชดเชย ออฟเซต สึกหรอ",
     WordKinds().whole("LPQ")},
    {'G',
     14,
     G::SpindleSwap,
     P::State,
     kH,
     kNoFlags,
     A::NotSimulated,
     "Secondary spindle swap",
     "สลับไปใช้เพลาที่สอง",
     "G14 - the secondary spindle takes the primary's place (Klueng does not simulate it: a run stops here)",
     "G14 - เพลาที่สองทำงานแทนเพลาหลัก (Klueng ไม่จำลอง การจำลองหยุดที่นี่)",
     {"swap to the secondary spindle", "สลับไปใช้เพลาที่สอง"},
     "secondary spindle swap sub spindle เพลาที่สอง"},
    {'G',
     15,
     G::SpindleSwap,
     P::State,
     kH,
     kNoFlags,
     A::None,
     "Secondary spindle swap cancel",
     "ยกเลิกการสลับเพลา",
     "G15 - back to the primary spindle (no effect when no swap was on)",
     "G15 - กลับไปใช้เพลาหลัก (ไม่มีผลเมื่อไม่ได้สลับ)",
     {"cancel the secondary spindle swap", "ยกเลิกการสลับเพลา"},
     "secondary spindle swap cancel sub spindle เพลาที่สอง"},
    {'G',
     17,
     G::Plane,
     P::State,
     kFH,
     kNoFlags,
     A::XyPlane,
     "XY plane",
     "เลือกระนาบ XY",
     "G17 - the XY plane, for live tools (Klueng draws arcs in the ZX plane only)",
     "G17 - ระนาบ XY สำหรับมีดหมุน (Klueng วาดส่วนโค้งในระนาบ ZX เท่านั้น)",
     {"XY plane, for live tools", "เลือกระนาบ XY สำหรับมีดหมุน"},
     "plane xy live tool milling ระนาบ มีดหมุน"},
    {'G',
     18,
     G::Plane,
     P::State,
     kFH,
     kNoFlags,
     A::ZxPlane,
     "ZX plane",
     "เลือกระนาบ ZX",
     "G18 - select the ZX plane (a lathe always works in it; no effect)",
     "G18 - เลือกระนาบ ZX (เครื่องกลึงใช้ระนาบนี้เสมอ จึงไม่มีผลใด ๆ)",
     {"ZX plane", "เลือกระนาบ ZX"},
     "plane zx xz ระนาบ"},
    {'G',
     19,
     G::Plane,
     P::State,
     kFH,
     kNoFlags,
     A::YzPlane,
     "YZ plane",
     "เลือกระนาบ YZ",
     "G19 - the YZ plane, for live tools (Klueng draws arcs in the ZX plane only)",
     "G19 - ระนาบ YZ สำหรับมีดหมุน (Klueng วาดส่วนโค้งในระนาบ ZX เท่านั้น)",
     {"YZ plane, for live tools", "เลือกระนาบ YZ สำหรับมีดหมุน"},
     "plane yz live tool milling ระนาบ มีดหมุน"},
    {'G',
     20,
     G::Units,
     P::State,
     kAll,
     kNoFlags,
     A::Inch,
     "Inch input",
     "ป้อนค่าเป็นหน่วยนิ้ว",
     "G20 - the values that follow are in inches (up to 4 decimals)",
     "G20 - ค่าที่ตามมาเป็นหน่วยนิ้ว (ทศนิยมได้ไม่เกิน 4 ตำแหน่ง)",
     {"lengths from here on are in inches", "ค่าความยาวต่อจากนี้เป็นหน่วยนิ้ว"},
     kUnitsWords},
    {'G',
     21,
     G::Units,
     P::State,
     kAll,
     kNoFlags,
     A::Metric,
     "Metric input",
     "ป้อนค่าเป็นหน่วยมิลลิเมตร",
     "G21 - the values that follow are in millimetres",
     "G21 - ค่าที่ตามมาเป็นหน่วยมิลลิเมตร",
     {"lengths from here on are in millimetres", "ค่าความยาวต่อจากนี้เป็นหน่วยมิลลิเมตร"},
     kUnitsWords},
    {'G',
     22,
     G::StrokeCheck,
     P::State,
     kF,
     kNoFlags,
     A::None,
     "Stored stroke check on",
     "เปิดการตรวจพื้นที่ห้ามเข้า",
     "G22 - the control keeps the tool out of its forbidden zone (no effect on the path)",
     "G22 - ตัวควบคุมกันไม่ให้มีดเข้าพื้นที่ห้ามเข้า (ไม่มีผลกับเส้นทาง)",
     {"stored stroke check on", "เปิดการตรวจพื้นที่ห้ามเข้า"},
     "stroke check limit barrier forbidden zone พื้นที่ห้ามเข้า ระยะเคลื่อนที่"},
    {'G',
     23,
     G::StrokeCheck,
     P::State,
     kF,
     kNoFlags,
     A::None,
     "Stored stroke check off",
     "ปิดการตรวจพื้นที่ห้ามเข้า",
     "G23 - the forbidden zone is not checked (no effect on the path)",
     "G23 - ไม่ตรวจพื้นที่ห้ามเข้า (ไม่มีผลกับเส้นทาง)",
     {"stored stroke check off", "ปิดการตรวจพื้นที่ห้ามเข้า"},
     "stroke check limit barrier forbidden zone พื้นที่ห้ามเข้า ระยะเคลื่อนที่"},
    {'G',
     25,
     G::SpeedCheck,
     P::State,
     kF,
     kNoFlags,
     A::None,
     "Spindle speed fluctuation detection off",
     "ปิดการตรวจความเร็วรอบเพลาแกว่ง",
     "G25 - the control stops watching the spindle speed (no effect on the path)",
     "G25 - ตัวควบคุมเลิกเฝ้าดูความเร็วรอบเพลา (ไม่มีผลกับเส้นทาง)",
     {"spindle speed fluctuation detection off", "ปิดการตรวจความเร็วรอบเพลาแกว่ง"},
     "spindle speed fluctuation detection ความเร็วรอบ เพลา"},
    {'G',
     26,
     G::SpeedCheck,
     P::State,
     kF,
     kNoFlags,
     A::None,
     "Spindle speed fluctuation detection on",
     "เปิดการตรวจความเร็วรอบเพลาแกว่ง",
     "G26 P1000 Q10 R20 - the control watches the spindle speed (no effect on the path)",
     "G26 P1000 Q10 R20 - ตัวควบคุมเฝ้าดูความเร็วรอบเพลา (ไม่มีผลกับเส้นทาง)",
     {"spindle speed fluctuation detection on", "เปิดการตรวจความเร็วรอบเพลาแกว่ง"},
     "spindle speed fluctuation detection ความเร็วรอบ เพลา",
     WordKinds().whole("P")},
    {'G',
     27,
     G::NonModal,
     P::Motion,
     kAll,
     kNoFlags,
     A::ReferenceCheck,
     "Reference point return check",
     "การตรวจสอบการกลับสู่จุดอ้างอิง",
     "G27 X0. Z300. - rapid to the point and check that it is the reference point",
     "G27 X0. Z300. - เคลื่อนที่เร็วไปยังจุดนั้นแล้วตรวจสอบตำแหน่งว่าเป็นจุดอ้างอิง",
     {"rapid to the point and check it is the reference point", "เคลื่อนที่เร็วไปยังจุดนั้นแล้วตรวจว่าเป็นจุดอ้างอิง"},
     kReferenceWords},
    {'G', 28, G::NonModal, P::Motion, kAll, kNoFlags, A::ReferenceReturn, "Reference point return", "การกลับสู่จุดอ้างอิง",
     "G28 U0. W0. - return to the reference point straight from here", "G28 U0. W0. - กลับสู่จุดอ้างอิงจากตำแหน่งปัจจุบันโดยตรง",
     kReferenceReturnSays, kReferenceWords},
    {'G',
     29,
     G::NonModal,
     P::Motion,
     kAll,
     kNoFlags,
     A::ReturnFromReference,
     "Return from the reference point",
     "การกลับจากจุดอ้างอิง",
     "G29 X30. Z2. - from the reference point through the G28 intermediate point to X30 Z2",
     "G29 X30. Z2. - กลับจากจุดอ้างอิงผ่านจุดกลางทางของ G28 ไปที่ X30 Z2",
     {"come back from the reference point through the G28 point", "กลับจากจุดอ้างอิงผ่านจุดกลางทางของ G28"},
     kReferenceWords},
    {'G', 30, G::NonModal, P::Motion, kFH, kNoFlags, A::SecondReferenceReturn, "2nd reference point return",
     "การกลับสู่จุดอ้างอิงที่ 2", "G30 U0. W0. - return to the 2nd reference point straight from here (P3, P4: 3rd, 4th)",
     "G30 U0. W0. - กลับสู่จุดอ้างอิงที่ 2 จากตำแหน่งปัจจุบันโดยตรง (P3, P4: จุดที่ 3, 4)", kReferenceReturnSays, kReferenceWords,
     WordKinds().whole("P")},
    {'G',
     31,
     G::NonModal,
     P::State,
     kFH,
     kNoFlags,
     A::NotSimulated,
     "Skip function",
     "ฟังก์ชันข้าม (สัญญาณวัด)",
     "G31 X20. F100 - move until a probe signal (Klueng does not simulate it: a run stops here)",
     "G31 X20. F100 - เคลื่อนที่จนมีสัญญาณจากหัววัด (Klueng ไม่จำลอง การจำลองหยุดที่นี่)",
     {"move until a probe signal", "เคลื่อนที่จนมีสัญญาณจากหัววัด"},
     "skip probe measure signal หัววัด วัดชิ้นงาน"},
    {'G',
     32,
     G::Motion,
     P::Motion,
     kAll,
     kNoFlags,
     A::Thread,
     "Thread cutting",
     "การกลึงเกลียว",
     "G32 Z-30. F1.5 - cut a thread of lead 1.5 mm to Z-30 (under G97)",
     "G32 Z-30. F1.5 - กลึงเกลียวระยะพิตช์ 1.5 มม. ไปที่ Z-30 (ใช้กับ G97)",
     {"cut one pass of a thread, the feed locked to the spindle", "กลึงเกลียวหนึ่งเที่ยว อัตราป้อนสัมพันธ์กับรอบเพลา"},
     kThreadWords},
    {'G',
     36,
     G::NonModal,
     P::State,
     kF,
     kNoFlags,
     A::NotSimulated,
     "Automatic tool offset X",
     "ชดเชยมีดอัตโนมัติแกน X",
     "G36 X50. - measure the tool on the tool setter in X (Klueng does not simulate it: a run stops here)",
     "G36 X50. - วัดมีดกับเครื่องตั้งมีดในแกน X (Klueng ไม่จำลอง การจำลองหยุดที่นี่)",
     {"measure the tool's X offset on the tool setter", "วัดค่าชดเชยมีดแกน X กับเครื่องตั้งมีด"},
     "automatic tool offset measure setter ตั้งมีด วัดมีด"},
    {'G',
     37,
     G::NonModal,
     P::State,
     kF,
     kNoFlags,
     A::NotSimulated,
     "Automatic tool offset Z",
     "ชดเชยมีดอัตโนมัติแกน Z",
     "G37 Z0 - measure the tool on the tool setter in Z (Klueng does not simulate it: a run stops here)",
     "G37 Z0 - วัดมีดกับเครื่องตั้งมีดในแกน Z (Klueng ไม่จำลอง การจำลองหยุดที่นี่)",
     {"measure the tool's Z offset on the tool setter", "วัดค่าชดเชยมีดแกน Z กับเครื่องตั้งมีด"},
     "automatic tool offset measure setter ตั้งมีด วัดมีด"},
    {'G',
     40,
     G::NoseComp,
     P::State,
     kAll,
     kNoFlags,
     A::CompOff,
     "Nose radius compensation off",
     "ยกเลิกการชดเชยรัศมีจมูกมีด",
     "G40 G00 X100. Z100. - cancel compensation on a rapid away from the part",
     "G40 G00 X100. Z100. - ยกเลิกการชดเชยขณะเคลื่อนที่เร็วออกจากชิ้นงาน",
     {"cancel tool nose radius compensation", "ยกเลิกการชดเชยรัศมีจมูกมีด"},
     kCompWords},
    {'G',
     41,
     G::NoseComp,
     P::State,
     kAll,
     kNoFlags,
     A::CompLeft,
     "Nose radius compensation, tool left",
     "การชดเชยรัศมีจมูกมีด มีดตัดอยู่ด้านซ้าย",
     "G41 G00 X20. Z2. - start compensation with the tool left of the path (boring)",
     "G41 G00 X20. Z2. - เริ่มการชดเชย มีดตัดอยู่ด้านซ้ายของแนวการเคลื่อนที่ (งานคว้านรู)",
     {"compensate the nose radius with the tool left of the path", "ชดเชยรัศมีจมูกมีด โดยมีดอยู่ทางซ้ายของแนวทางเดิน"},
     kCompWords},
    {'G',
     42,
     G::NoseComp,
     P::State,
     kAll,
     kNoFlags,
     A::CompRight,
     "Nose radius compensation, tool right",
     "การชดเชยรัศมีจมูกมีด มีดตัดอยู่ด้านขวา",
     "G42 G00 X24. Z2. - start compensation with the tool right of the path (outside turning)",
     "G42 G00 X24. Z2. - เริ่มการชดเชย มีดตัดอยู่ด้านขวาของแนวการเคลื่อนที่ (งานกลึงปอกผิว)",
     {"compensate the nose radius with the tool right of the path", "ชดเชยรัศมีจมูกมีด โดยมีดอยู่ทางขวาของแนวทางเดิน"},
     kCompWords},
    {'G',
     50,
     G::NonModal,
     P::Motion,
     kAll,
     kNoFlags,
     A::CoordinateSet,
     "Coordinate setting / spindle speed limit",
     "ตั้งระบบพิกัดงาน / จำกัดความเร็วรอบ",
     "G50 S2500 - limit the spindle to 2500 rpm under G96 (G50 X_ Z_ sets the work coordinates)",
     "G50 S2500 - จำกัดความเร็วรอบไม่เกิน 2500 รอบ/นาที ขณะใช้ G96 (G50 X_ Z_ ตั้งพิกัดงาน)",
     {"set the coordinates, or limit the spindle speed with S", "ตั้งระบบพิกัด หรือจำกัดความเร็วรอบด้วย S"},
     "spindle limit clamp max rpm coordinate จำกัดความเร็วรอบ ตั้งพิกัด"},
    {'G',
     52,
     G::NonModal,
     P::State,
     kFH,
     kNoFlags,
     A::LocalCoordinates,
     "Local coordinate system",
     "ระบบพิกัดเฉพาะที่",
     "G52 Z-50. - the program's Z0 lies 50 mm nearer the chuck until G52 Z0",
     "G52 Z-50. - จุด Z0 ของโปรแกรมเลื่อนเข้าหาหัวจับ 50 มม. จนกว่าจะสั่ง G52 Z0",
     {"shift the program's zero by a local coordinate system", "เลื่อนจุดศูนย์ของโปรแกรมด้วยระบบพิกัดเฉพาะที่"},
     "local coordinate system shift zero ระบบพิกัดเฉพาะที่ เลื่อนจุดศูนย์"},
    {'G',
     53,
     G::NonModal,
     P::Motion,
     kFH,
     kNoFlags,
     A::MachineCoordinates,
     "Move in machine coordinates",
     "เคลื่อนที่ในระบบพิกัดเครื่อง",
     "G53 X0. Z0. - rapid to X0 Z0 of the machine coordinates",
     "G53 X0. Z0. - เคลื่อนที่เร็วไปที่ X0 Z0 ของระบบพิกัดเครื่อง",
     {"move in machine coordinates", "เคลื่อนที่ในระบบพิกัดเครื่อง"},
     "machine coordinates home position ระบบพิกัดเครื่อง"},
    {'G', 54, G::WorkOffset, P::State, kFH, kNoFlags, A::WorkOffset, "Work offset 1", "ระบบพิกัดงานที่ 1",
     "G54 - use work offset 1 (zero unless set)", "G54 - ใช้ระบบพิกัดงานที่ 1 (เป็นศูนย์ถ้าไม่ได้กำหนด)", kWorkOffsetSays,
     kWorkOffsetWords},
    {'G', 55, G::WorkOffset, P::State, kFH, kNoFlags, A::WorkOffset, "Work offset 2", "ระบบพิกัดงานที่ 2",
     "G55 - use work offset 2 (zero unless set)", "G55 - ใช้ระบบพิกัดงานที่ 2 (เป็นศูนย์ถ้าไม่ได้กำหนด)", kWorkOffsetSays,
     kWorkOffsetWords},
    {'G', 56, G::WorkOffset, P::State, kFH, kNoFlags, A::WorkOffset, "Work offset 3", "ระบบพิกัดงานที่ 3",
     "G56 - use work offset 3 (zero unless set)", "G56 - ใช้ระบบพิกัดงานที่ 3 (เป็นศูนย์ถ้าไม่ได้กำหนด)", kWorkOffsetSays,
     kWorkOffsetWords},
    {'G', 57, G::WorkOffset, P::State, kFH, kNoFlags, A::WorkOffset, "Work offset 4", "ระบบพิกัดงานที่ 4",
     "G57 - use work offset 4 (zero unless set)", "G57 - ใช้ระบบพิกัดงานที่ 4 (เป็นศูนย์ถ้าไม่ได้กำหนด)", kWorkOffsetSays,
     kWorkOffsetWords},
    {'G', 58, G::WorkOffset, P::State, kFH, kNoFlags, A::WorkOffset, "Work offset 5", "ระบบพิกัดงานที่ 5",
     "G58 - use work offset 5 (zero unless set)", "G58 - ใช้ระบบพิกัดงานที่ 5 (เป็นศูนย์ถ้าไม่ได้กำหนด)", kWorkOffsetSays,
     kWorkOffsetWords},
    {'G', 59, G::WorkOffset, P::State, kFH, kNoFlags, A::WorkOffset, "Work offset 6", "ระบบพิกัดงานที่ 6",
     "G59 - use work offset 6 (zero unless set)", "G59 - ใช้ระบบพิกัดงานที่ 6 (เป็นศูนย์ถ้าไม่ได้กำหนด)", kWorkOffsetSays,
     kWorkOffsetWords},
    {'G',
     61,
     G::ExactStop,
     P::State,
     kFH,
     kNoFlags,
     A::None,
     "Exact stop mode",
     "โหมดหยุดตรงตำแหน่ง",
     "G61 - stop exactly at the end of every block until G64 (the path does not change)",
     "G61 - หยุดให้ตรงจุดปลายทุกบล็อกจนกว่าจะสั่ง G64 (เส้นทางไม่เปลี่ยน)",
     {"exact stop at the end of every block", "หยุดให้ตรงจุดปลายทุกบล็อก"},
     "exact stop mode sharp corner หยุดตรงตำแหน่ง มุมคม"},
    {'G',
     64,
     G::ExactStop,
     P::State,
     kFH,
     kNoFlags,
     A::None,
     "Cutting mode",
     "โหมดตัดเฉือนต่อเนื่อง",
     "G64 - blocks flow into each other again (cancels G61; the path does not change)",
     "G64 - บล็อกต่อเนื่องกันตามปกติ (ยกเลิก G61 เส้นทางไม่เปลี่ยน)",
     {"cutting mode: blocks flow into each other", "โหมดตัดเฉือน: บล็อกต่อเนื่องกัน"},
     "cutting mode exact stop cancel โหมดตัดเฉือน"},
    {'G',
     65,
     G::NonModal,
     P::Motion,
     kFH,
     kNoFlags,
     A::MacroCall,
     "Macro call",
     "เรียกใช้มาโคร",
     "G65 P9010 L2 A1. B2. - run macro O9010 twice with #1 = 1, #2 = 2",
     "G65 P9010 L2 A1. B2. - เรียกใช้มาโคร O9010 สองครั้ง โดย #1 = 1, #2 = 2",
     {"call a macro with arguments", "เรียกมาโครพร้อมส่งค่าอาร์กิวเมนต์"},
     kCallWords,
     WordKinds().whole("PL")},
    {'G',
     66,
     G::MacroModal,
     P::Motion,
     kFH,
     kNoFlags,
     A::MacroModalCall,
     "Modal macro call",
     "เรียกใช้มาโครแบบโมดอล",
     "G66 P9020 A2. - run macro O9020 after every move until G67",
     "G66 P9020 A2. - เรียกใช้มาโคร O9020 หลังการเคลื่อนที่ทุกครั้งจนกว่าจะสั่ง G67",
     {"call a macro after every move until G67", "เรียกมาโครหลังการเคลื่อนที่ทุกครั้งจนถึง G67"},
     kCallWords,
     WordKinds().whole("PL")},
    {'G',
     67,
     G::MacroModal,
     P::State,
     kFH,
     kNoFlags,
     A::MacroModalCancel,
     "Modal macro call cancel",
     "ยกเลิกการเรียกมาโครแบบโมดอล",
     "G67 - stop calling the G66 macro after each move",
     "G67 - เลิกเรียกมาโครของ G66 หลังการเคลื่อนที่",
     {"stop calling the macro after each move", "เลิกเรียกมาโครหลังการเคลื่อนที่"},
     "macro modal cancel มาโคร ยกเลิก"},
    {'G',
     68,
     G::MirrorImage,
     P::State,
     kF,
     kNoFlags,
     A::NotSimulated,
     "Mirror image for double turret on",
     "เปิดภาพสะท้อนสำหรับป้อมมีดคู่",
     "G68 - the second turret cuts the mirror of the program (Klueng does not simulate it: a run stops here)",
     "G68 - ป้อมมีดที่สองกลึงตามภาพสะท้อนของโปรแกรม (Klueng ไม่จำลอง การจำลองหยุดที่นี่)",
     {"mirror image for double turret on", "เปิดภาพสะท้อนสำหรับป้อมมีดคู่"},
     "mirror image double turret balance ภาพสะท้อน ป้อมมีดคู่"},
    {'G',
     69,
     G::MirrorImage,
     P::State,
     kF,
     kNoFlags,
     A::None,
     "Mirror image for double turret off",
     "ปิดภาพสะท้อนสำหรับป้อมมีดคู่",
     "G69 - mirror image off (no effect when it was off)",
     "G69 - ปิดภาพสะท้อน (ไม่มีผลเมื่อปิดอยู่แล้ว)",
     {"mirror image for double turret off", "ปิดภาพสะท้อนสำหรับป้อมมีดคู่"},
     "mirror image double turret cancel ภาพสะท้อน ป้อมมีดคู่"},
    {'G',
     70,
     G::CannedCycle,
     P::Motion,
     kAll,
     kNoFlags,
     A::Finishing,
     "Finishing cycle",
     "วัฏจักรกลึงเก็บผิว",
     "G70 P100 Q200 - finish along the contour of blocks N100 to N200",
     "G70 P100 Q200 - กลึงเก็บผิวตามรูปร่างในบล็อก N100 ถึง N200",
     {"finishing cycle: follow the profile once at the finishing feed",
      "วัฏจักรกลึงละเอียด: กลึงตามรูปร่างหนึ่งเที่ยวด้วยอัตราป้อนกลึงละเอียด"},
     "finishing finish pass contour กลึงละเอียด กลึงเก็บผิว",
     WordKinds().whole("PQ")},
    {'G', 71, G::CannedCycle, P::Motion, kFC, kNoFlags, A::TurnRoughing, "Stock removal in turning",
     "วัฏจักรกลึงปาดผิวตามแนวแกน Z", "G71 U1. R0.5 - cut 1 mm per side, retract 0.5 mm; then G71 P_ Q_ U_ W_ F_",
     "G71 U1. R0.5 - ป้อนลึกด้านละ 1 มม. ถอยมีด 0.5 มม. แล้วตามด้วย G71 P_ Q_ U_ W_ F_", kTurnRoughingSays, kRoughingWords},
    {'G', 72, G::CannedCycle, P::Motion, kFC, kNoFlags, A::FaceRoughing, "Stock removal in facing", "วัฏจักรกลึงปาดหน้า",
     "G72 W1. R0.5 - cut 1 mm along Z, retract 0.5 mm; then G72 P_ Q_ U_ W_ F_",
     "G72 W1. R0.5 - ป้อนลึกตามแนวแกน Z ครั้งละ 1 มม. ถอยมีด 0.5 มม. แล้วตามด้วย G72 P_ Q_ U_ W_ F_", kFaceRoughingSays,
     kFacingWords},
    {'G', 73, G::CannedCycle, P::Motion, kFC, kNoFlags, A::PatternRepeating, "Pattern repeating cycle",
     "วัฏจักรกลึงซ้ำตามรูปร่าง", "G73 U3. W0. R3 - remove 3 mm in 3 passes that follow the contour; then G73 P_ Q_ U_ W_ F_",
     "G73 U3. W0. R3 - กลึงออก 3 มม. ใน 3 เที่ยวตามรูปร่าง แล้วตามด้วย G73 P_ Q_ U_ W_ F_", kPatternRepeatingSays,
     kPatternWords},
    {'G', 74, G::CannedCycle, P::Motion, kFC, kNoFlags, A::FacePecking, "Face peck drilling cycle",
     "วัฏจักรเจาะแบบถอยเป็นช่วง", "G74 R1. - retract 1 mm after each peck; then G74 Z_ Q_ F_",
     "G74 R1. - ถอยดอกเจาะ 1 มม. หลังเจาะแต่ละช่วง แล้วตามด้วย G74 Z_ Q_ F_", kFacePeckingSays, kDrillingWords},
    {'G', 75, G::CannedCycle, P::Motion, kFC, kNoFlags, A::Grooving, "Grooving cycle", "วัฏจักรกลึงร่อง",
     "G75 R1. - retract 1 mm after each peck; then G75 X_ Z_ P_ Q_ F_",
     "G75 R1. - ถอยมีด 1 มม. หลังป้อนแต่ละช่วง แล้วตามด้วย G75 X_ Z_ P_ Q_ F_", kGroovingSays, kGroovingWords},
    {'G', 76, G::CannedCycle, P::Motion, kFC, kNoFlags, A::ThreadCutting, "Multi-pass threading cycle",
     "วัฏจักรกลึงเกลียวหลายเที่ยว", "G76 P020060 Q50 R0.05 - then G76 X28.16 Z-30. P920 Q300 F1.5",
     "G76 P020060 Q50 R0.05 - แล้วตามด้วย G76 X28.16 Z-30. P920 Q300 F1.5", kThreadCuttingSays, kThreadWords},
    // Haas one-block forms (Haas lathe operator's manual, G-codes; docs/dialects.md).
    {'G', 71, G::CannedCycle, P::Motion, kH, kNoFlags, A::TurnRoughing, "O.D./I.D. stock removal cycle",
     "วัฏจักรกลึงปาดผิวตามแนวแกน Z",
     "G71 P100 Q200 U0.02 W0.005 D0.1 F0.01 - rough the contour N100-N200, 0.1 deep per pass (D, radius)",
     "G71 P100 Q200 U0.02 W0.005 D0.1 F0.01 - กลึงหยาบตามรูปร่าง N100-N200 ลึกเที่ยวละ 0.1 (D, ค่ารัศมี)", kTurnRoughingSays,
     kRoughingWords, WordKinds().whole("PQ").positive("DFS").length("IKUW")},
    {'G', 72, G::CannedCycle, P::Motion, kH, kNoFlags, A::FaceRoughing, "End face stock removal cycle",
     "วัฏจักรกลึงปาดหน้า",
     "G72 P100 Q200 U0.02 W0.005 D0.05 F0.01 - rough the face contour N100-N200, 0.05 per pass along Z",
     "G72 P100 Q200 U0.02 W0.005 D0.05 F0.01 - กลึงหยาบปาดหน้าตามรูปร่าง N100-N200 ป้อนตามแกน Z เที่ยวละ 0.05",
     kFaceRoughingSays, kFacingWords, WordKinds().whole("PQ").positive("DFS").length("IKUW")},
    {'G', 73, G::CannedCycle, P::Motion, kH, kNoFlags, A::PatternRepeating, "Irregular path stock removal cycle",
     "วัฏจักรกลึงซ้ำตามรูปร่าง",
     "G73 P100 Q200 U0.02 W0.005 I0.3 K0.1 D3 F0.01 - remove I/K of stock in D=3 passes that follow the contour",
     "G73 P100 Q200 U0.02 W0.005 I0.3 K0.1 D3 F0.01 - กลึงออกตามระยะ I/K ใน D=3 เที่ยวตามรูปร่าง", kPatternRepeatingSays,
     kPatternWords, WordKinds().whole("PQD").length("IKUW").positive("FS")},
    {'G', 74, G::CannedCycle, P::Motion, kH, kNoFlags, A::FacePecking, "End face grooving cycle", "วัฏจักรกลึงร่องหน้าตัด",
     "G74 X1. Z-0.5 K0.1 F0.005 - peck the face groove 0.1 at a time to Z-0.5 (I: step in X)",
     "G74 X1. Z-0.5 K0.1 F0.005 - ป้อนร่องหน้าตัดครั้งละ 0.1 จนถึง Z-0.5 (I: ระยะเลื่อนตามแกน X)", kFacePeckingSays,
     kDrillingWords, WordKinds().positive("DIKF").length("UWXZ")},
    {'G', 75, G::CannedCycle, P::Motion, kH, kNoFlags, A::Grooving, "O.D./I.D. grooving cycle", "วัฏจักรกลึงร่อง",
     "G75 X1.5 Z-0.8 I0.05 K0.1 F0.004 - peck the groove 0.05 at a time to X1.5 (K: step along Z)",
     "G75 X1.5 Z-0.8 I0.05 K0.1 F0.004 - ป้อนร่องครั้งละ 0.05 จนถึง X1.5 (K: ระยะเลื่อนตามแกน Z)", kGroovingSays,
     kGroovingWords, WordKinds().positive("DIKF").length("UWXZ")},
    {'G', 76, G::CannedCycle, P::Motion, kH, kNoFlags, A::ThreadCutting, "Multi-pass threading cycle",
     "วัฏจักรกลึงเกลียวหลายเที่ยว",
     "G76 X0.9 Z-1. K0.0613 D0.01 F0.0833 A60 - thread 12 TPI: height K, first pass D, 60 degree insert",
     "G76 X0.9 Z-1. K0.0613 D0.01 F0.0833 A60 - กลึงเกลียว 12 เกลียว/นิ้ว: สูง K ป้อนเที่ยวแรก D มีดมุม 60 องศา",
     kThreadCuttingSays, kThreadWords, WordKinds().whole("APQ").positive("DKFE").length("IUWXZ")},
    {'G',
     80,
     G::CannedCycle,
     P::State,
     kFH,
     kNoFlags,
     A::CycleCancel,
     "Canned cycle cancel",
     "ยกเลิกวัฏจักร",
     "G80 - cancel a canned cycle (no effect on this lathe)",
     "G80 - ยกเลิกวัฏจักร (ไม่มีผลกับเครื่องกลึงนี้)",
     {"cancel the drilling cycle", "ยกเลิกวัฏจักรเจาะ"},
     "cancel cycle drilling ยกเลิกวัฏจักร"},
    // A machining centre's habit in a lathe's safety line (`G21 G40 G49 G54 G80 G90`): no source says a
    // Fanuc lathe stops on it (docs/dialects.md §10), so it is read and does nothing, as G80 here.
    {'G',
     49,
     G::ToolLength,
     P::State,
     kF,
     kNoFlags,
     A::None,
     "Tool length compensation cancel",
     "ยกเลิกการชดเชยความยาวมีด",
     "G49 - cancel tool length compensation (a machining-centre code; no effect on this lathe)",
     "G49 - ยกเลิกการชดเชยความยาวมีด (รหัสของเครื่องกัด ไม่มีผลกับเครื่องกลึงนี้)",
     {"cancel tool length compensation", "ยกเลิกการชดเชยความยาวมีด"},
     "tool length compensation cancel mill safety line ยกเลิก ชดเชยความยาว"},
    // Drilling on centre. Fanuc 0i-TF: G83 Q in least increments (or a length with its
    // decimal point, decimal point programming), P in ms;
    // Haas: Q a length with a decimal point, P a dwell as G04 reads it.
    {'G',
     81,
     G::CannedCycle,
     P::Motion,
     kFH,
     kNoFlags,
     A::Drilling,
     "Drilling cycle",
     "วัฏจักรเจาะรู",
     "G81 Z-20. R2. F0.1 - drill on centre to Z-20 from 2 above the face, then rapid out",
     "G81 Z-20. R2. F0.1 - เจาะรูที่ศูนย์กลางถึง Z-20 เริ่มป้อนห่างหน้างาน 2 แล้วถอยออกเร็ว",
     {"drilling cycle: drill to the depth and rapid out", "วัฏจักรเจาะรู: เจาะถึงความลึกแล้วถอยออกเร็ว"},
     kDrillingWords,
     WordKinds().length("R").positive("F")},
    {'G',
     82,
     G::CannedCycle,
     P::Motion,
     kH,
     kNoFlags,
     A::SpotDrilling,
     "Spot drilling cycle",
     "วัฏจักรเจาะนำศูนย์",
     "G82 Z-0.1 R0.1 P0.3 F0.005 - spot drill to Z-0.1 and dwell 0.3 s at the bottom",
     "G82 Z-0.1 R0.1 P0.3 F0.005 - เจาะนำศูนย์ถึง Z-0.1 แล้วหยุดรอ 0.3 วินาทีที่ก้นรู",
     {"drilling cycle with a dwell at the bottom", "วัฏจักรเจาะรูและหยุดรอที่ก้นรู"},
     kDrillingWords,
     WordKinds().dwell("P").length("R").positive("F")},
    {'G', 83, G::CannedCycle, P::Motion, kF, kNoFlags, A::PeckDrilling, "Peck drilling cycle", "วัฏจักรเจาะรูแบบถอยเป็นช่วง",
     "G83 Z-30. R-48. Q5000 F0.1 - peck 5 mm (Q in 0.001 mm) to Z-30, R from the start point",
     "G83 Z-30. R-48. Q5000 F0.1 - เจาะทีละ 5 มม. (Q หน่วย 0.001 มม.) ถึง Z-30 R วัดจากจุดเริ่ม", kPeckDrillingSays,
     kDrillingWords, WordKinds().increment("Q").dwell("P").length("R").whole("K").positive("F")},
    {'G', 83, G::CannedCycle, P::Motion, kH, kNoFlags, A::PeckDrilling, "Peck drilling cycle", "วัฏจักรเจาะรูแบบถอยเป็นช่วง",
     "G83 Z-1.5 R0.1 Q0.25 F0.005 - peck 0.25 at a time to Z-1.5, out to R0.1 after each peck",
     "G83 Z-1.5 R0.1 Q0.25 F0.005 - เจาะทีละ 0.25 ถึง Z-1.5 ถอยออกถึง R0.1 ทุกครั้ง", kPeckDrillingSays, kDrillingWords,
     WordKinds().positive("QIJKF").dwell("P").length("R")},
    {'G',
     90,
     G::Motion,
     P::Motion,
     kAll,
     kNoFlags,
     A::BoxTurning,
     "Turning cycle",
     "วัฏจักรกลึงปอกผิวอย่างง่าย",
     "G90 X45. Z-30. F0.2 - one pass to diameter 45 over 30 mm, then back to the start",
     "G90 X45. Z-30. F0.2 - กลึงหนึ่งเที่ยวที่เส้นผ่าศก. 45 ยาว 30 มม. แล้วกลับจุดเริ่ม",
     {"turning cycle: feed in, cut along Z, come out and return to the start",
      "วัฏจักรกลึงปอก: ป้อนมีดเข้า กลึงตามแนวแกน Z ถอยออก แล้วกลับจุดเริ่ม"},
     "turning cycle roughing box simple กลึงปอก วัฏจักร"},
    {'G',
     92,
     G::Motion,
     P::Motion,
     kAll,
     kNoFlags,
     A::BoxThreading,
     "Threading cycle",
     "วัฏจักรกลึงเกลียวอย่างง่าย",
     "G92 X29.4 Z-30. F1.5 - one thread pass, then back to the start",
     "G92 X29.4 Z-30. F1.5 - กลึงเกลียวหนึ่งเที่ยว แล้วกลับจุดเริ่ม",
     {"threading cycle: one thread pass and back to the start", "วัฏจักรกลึงเกลียว: กลึงเกลียวหนึ่งเที่ยวแล้วกลับจุดเริ่ม"},
     kThreadWords},
    {'G',
     94,
     G::Motion,
     P::Motion,
     kAll,
     kNoFlags,
     A::BoxFacing,
     "Facing cycle",
     "วัฏจักรกลึงปาดหน้าอย่างง่าย",
     "G94 X20. Z-2. F0.2 - one facing pass to Z-2, then back to the start",
     "G94 X20. Z-2. F0.2 - กลึงปาดหน้าหนึ่งเที่ยวถึง Z-2 แล้วกลับจุดเริ่ม",
     {"facing cycle: feed in, cut along X, come out and return to the start",
      "วัฏจักรกลึงปาดหน้า: ป้อนมีดเข้า กลึงตามแนวแกน X ถอยออก แล้วกลับจุดเริ่ม"},
     kFacingWords},
    {'G',
     96,
     G::SpindleMode,
     P::State,
     kAll,
     kNoFlags,
     A::ConstantSurface,
     "Constant surface speed",
     "ความเร็วผิวคงที่",
     "G96 S180 - keep the cutting speed at 180 m/min",
     "G96 S180 - รักษาความเร็วผิวคงที่ 180 ม./นาที",
     {"constant cutting speed: the rpm follows the diameter", "ความเร็วตัดคงที่: รอบเพลาเปลี่ยนตามเส้นผ่าศูนย์กลาง"},
     "css surface speed cutting speed ความเร็วตัด ความเร็วผิว"},
    {'G',
     97,
     G::SpindleMode,
     P::State,
     kAll,
     kNoFlags,
     A::ConstantRpm,
     "Constant spindle speed",
     "ความเร็วรอบคงที่",
     "G97 S1000 - turn the spindle at 1000 rpm",
     "G97 S1000 - หมุนด้วยความเร็วรอบคงที่ 1000 รอบ/นาที",
     {"constant spindle rpm", "ความเร็วรอบเพลาคงที่"},
     "rpm spindle speed ความเร็วรอบ"},
    // G98/G99 stand alone only in the classic dialect (SPEC 5 rule 7, 13).
    {'G', 98, G::FeedMode, P::State, kFH, kNoFlags, A::FeedPerMinute, "Feed per minute", "อัตราป้อนเป็น มม./นาที",
     "G98 - F is in mm/min from here on", "G98 - ค่า F เป็น มม./นาที ตั้งแต่บล็อกนี้", kFeedPerMinuteSays, kFeedWords},
    {'G', 98, G::FeedMode, P::State, kC, kAlone, A::FeedPerMinute, "Feed per minute", "อัตราป้อนเป็น มม./นาที",
     "G98 - alone in its block: F is in mm/min from here on", "G98 - อยู่เดี่ยวในบล็อก: ค่า F เป็น มม./นาที ตั้งแต่บล็อกนี้",
     kFeedPerMinuteSays, kFeedWords},
    {'G', 99, G::FeedMode, P::State, kFH, kNoFlags, A::FeedPerRev, "Feed per revolution", "อัตราป้อนเป็น มม./รอบ",
     "G99 - F is in mm/rev from here on", "G99 - ค่า F เป็น มม./รอบ ตั้งแต่บล็อกนี้", kFeedPerRevSays, kFeedWords},
    {'G', 99, G::FeedMode, P::State, kC, kAlone, A::FeedPerRev, "Feed per revolution", "อัตราป้อนเป็น มม./รอบ",
     "G99 - alone in its block: F is in mm/rev from here on", "G99 - อยู่เดี่ยวในบล็อก: ค่า F เป็น มม./รอบ ตั้งแต่บล็อกนี้",
     kFeedPerRevSays, kFeedWords},

    {'G',
     103,
     G::Lookahead,
     P::State,
     kH,
     kNoFlags,
     A::None,
     "Limit block lookahead",
     "จำกัดการอ่านบล็อกล่วงหน้า",
     "G103 P1 - read one block ahead only (no effect on the path)",
     "G103 P1 - อ่านล่วงหน้าเพียงหนึ่งบล็อก (ไม่มีผลกับเส้นทาง)",
     {"limit how far the control reads ahead", "จำกัดจำนวนบล็อกที่ตัวควบคุมอ่านล่วงหน้า"},
     "lookahead buffer blocks อ่านล่วงหน้า",
     WordKinds().whole("P")},
    {'G',
     112,
     G::PolarInterp,
     P::State,
     kH,
     kNoFlags,
     A::NotSimulated,
     "XY to XC interpolation",
     "การประมาณค่า XY เป็น XC",
     "G112 - live-tool milling in X Y with the C axis (Klueng does not simulate it: a run stops here)",
     "G112 - กัดด้วยมีดหมุนใน X Y โดยใช้แกน C (Klueng ไม่จำลอง การจำลองหยุดที่นี่)",
     {"XY to XC interpolation on", "เปิดการประมาณค่า XY เป็น XC"},
     "xy xc interpolation polar live tool milling มีดหมุน แกน c"},
    {'G',
     113,
     G::PolarInterp,
     P::State,
     kH,
     kNoFlags,
     A::None,
     "XY to XC interpolation cancel",
     "ยกเลิกการประมาณค่า XY เป็น XC",
     "G113 - XY to XC interpolation off (no effect when it was off)",
     "G113 - ปิดการประมาณค่า XY เป็น XC (ไม่มีผลเมื่อปิดอยู่แล้ว)",
     {"XY to XC interpolation off", "ปิดการประมาณค่า XY เป็น XC"},
     "xy xc interpolation cancel มีดหมุน แกน c"},
    {'G',
     154,
     G::WorkOffset,
     P::State,
     kH,
     kNoFlags,
     A::WorkOffset,
     "Additional work coordinates",
     "ระบบพิกัดงานเพิ่มเติม",
     "G154 P1 - work coordinates P1 (P1-P99; Klueng's work coordinates are the program's own)",
     "G154 P1 - ใช้ระบบพิกัดงาน P1 (P1-P99 ใน Klueng ระบบพิกัดงานคือของโปรแกรมเอง)",
     {"use additional work coordinates", "ใช้ระบบพิกัดงานเพิ่มเติม"},
     "work offset coordinates additional ระบบพิกัดงาน",
     WordKinds().whole("P")},
    {'G',
     187,
     G::Smoothness,
     P::State,
     kH,
     kNoFlags,
     A::None,
     "Smoothness level",
     "ระดับความเรียบของเส้นทาง",
     "G187 P1 - rough, P2 medium, P3 finish smoothness (no effect on the path Klueng draws)",
     "G187 P1 - หยาบ P2 กลาง P3 ละเอียด (ไม่มีผลกับเส้นทางที่Klueng วาด)",
     {"set the smoothness and corner rounding level", "ตั้งระดับความเรียบและการมนมุมของเส้นทาง"},
     "smoothness corner rounding accuracy ความเรียบ",
     WordKinds().whole("P")},
};
// clang-format on

static_assert(allComplete(kGRows), "a G code row lacks a name, phrase, keywords or example");

// G-code systems B and C (docs/dialects.md, "G-code systems"): the same
// functions under other numbers. FANUC Series 0i-TF Operator's Manual
// B-64604EN, Part II "Programming", G code list (table of systems A, B, C).
constexpr SystemRename kRenames[] = {
    // System B: G90/G91 are absolute/incremental, the feed modes G94/G95, G92 the
    // coordinate setting and speed clamp, G33 threading, G77-G79 the single cycles.
    {GcodeSystem::B, 33, 32},
    {GcodeSystem::B, 92, 50},
    {GcodeSystem::B, 77, 90},
    {GcodeSystem::B, 78, 92},
    {GcodeSystem::B, 79, 94},
    {GcodeSystem::B, 94, 98},
    {GcodeSystem::B, 95, 99},
    {GcodeSystem::B, 90, -1},
    {GcodeSystem::B, 91, -1},
    {GcodeSystem::B, 98, -1},
    {GcodeSystem::B, 99, -1},
    // System C: as B, and the units become G70/G71, so G70-G76 move up by two and
    // the single cycles become G20, G21, G24.
    {GcodeSystem::C, 70, 20},
    {GcodeSystem::C, 71, 21},
    {GcodeSystem::C, 72, 70},
    {GcodeSystem::C, 73, 71},
    {GcodeSystem::C, 74, 72},
    {GcodeSystem::C, 75, 73},
    {GcodeSystem::C, 76, 74},
    {GcodeSystem::C, 77, 75},
    {GcodeSystem::C, 78, 76},
    {GcodeSystem::C, 33, 32},
    {GcodeSystem::C, 92, 50},
    {GcodeSystem::C, 20, 90},
    {GcodeSystem::C, 21, 92},
    {GcodeSystem::C, 24, 94},
    {GcodeSystem::C, 94, 98},
    {GcodeSystem::C, 95, 99},
    {GcodeSystem::C, 90, -1},
    {GcodeSystem::C, 91, -1},
    {GcodeSystem::C, 98, -1},
    {GcodeSystem::C, 99, -1},
};

// Rows system A has not (the family mask says which controls have them).
// clang-format off
constexpr CodeInfo kSystemOnly[] = {
    {'G', 90, G::Distance, P::State, kF, kNoFlags, A::Absolute,
     "Absolute programming", "กำหนดตำแหน่งแบบสัมบูรณ์",
     "G90 - X and Z are positions from the work zero (U and W stay distances)",
     "G90 - ค่า X และ Z เป็นตำแหน่งวัดจากศูนย์งาน (U และ W ยังเป็นระยะสัมพัทธ์)",
     {"absolute programming", "กำหนดตำแหน่งแบบสัมบูรณ์"},
     kDistanceWords},
    {'G', 91, G::Distance, P::State, kF, kNoFlags, A::Incremental,
     "Incremental programming", "กำหนดตำแหน่งแบบสัมพัทธ์",
     "G91 - X and Z are distances from where the tool is (X on the diameter)",
     "G91 - ค่า X และ Z เป็นระยะจากตำแหน่งปัจจุบันของมีด (X เป็นค่าเส้นผ่านศูนย์กลาง)",
     {"incremental programming", "กำหนดตำแหน่งแบบสัมพัทธ์"},
     kDistanceWords},
    // Systems B and C: G94/G95 are the feed modes, G98/G99 where G83-G85 return (system A: always the initial level).
    {'G', 98, G::ReturnLevel, P::State, kF, kNoFlags, A::ReturnToInitialLevel,
     "Drilling: return to the initial level", "เจาะรู: ถอยกลับถึงระดับเริ่มต้น",
     "G98 - a drilling cycle ends where it started, at the initial level",
     "G98 - วัฏจักรเจาะรูถอยกลับไปจบที่ระดับเริ่มต้น",
     {"drilling cycles return to the initial level", "วัฏจักรเจาะรูถอยกลับถึงระดับเริ่มต้น"},
     kReturnLevelWords},
    {'G', 99, G::ReturnLevel, P::State, kF, kNoFlags, A::ReturnToRPoint,
     "Drilling: return to the R point", "เจาะรู: ถอยกลับถึงจุด R",
     "G99 - a drilling cycle ends at its R point, ready for the next hole",
     "G99 - วัฏจักรเจาะรูถอยกลับไปจบที่จุด R พร้อมเจาะรูถัดไป",
     {"drilling cycles return to the R point", "วัฏจักรเจาะรูถอยกลับถึงจุด R"},
     kReturnLevelWords},
};
// clang-format on
static_assert(allComplete(kSystemOnly), "a system B/C row lacks a name, phrase, keywords or example");

// The G-code rows, then the M-code rows (code_table_m.cpp), in one list that never changes: the
// code index keeps pointers into it. Built on first use, as a machine registered at start-up may ask.
std::span<const CodeInfo> allRows() {
  static const std::vector<CodeInfo> rows = [] {
    std::vector<CodeInfo> all(std::begin(kGRows), std::end(kGRows));
    const std::span<const CodeInfo> m = detail::mCodeRows();
    all.insert(all.end(), m.begin(), m.end());
    return all;
  }();
  return rows;
}

const CodeInfo* baseRow(char letter, int number, Dialect family) {
  for (const CodeInfo& row : allRows())
    if (row.letter == letter && row.number == number && (row.dialects & dialectBit(family))) return &row;
  return nullptr;
}

}  // namespace

namespace detail {

int numberInSystemOf(int numberInA, GcodeSystem system) {
  if (system == GcodeSystem::A) return numberInA;
  bool movedAway = false;
  for (const SystemRename& r : kRenames) {
    if (r.system != system) continue;
    if (r.numberInA == numberInA) return r.number;
    if (r.number == numberInA) movedAway = true;  // the number means another code there
  }
  return movedAway ? -1 : numberInA;
}

void buildCodeIndex(const MachineProfile& profile, CodeIndex& out) {
  out = CodeIndex{};
  const std::uint8_t bit = dialectBit(profile.family);
  for (const CodeInfo& row : allRows()) {
    if (!(row.dialects & bit)) continue;
    if (row.letter == 'M' && !profile.mCodes.empty() &&
        std::find(profile.mCodes.begin(), profile.mCodes.end(), row.number) == profile.mCodes.end())
      continue;
    out.rows[row.letter == 'G' ? 0 : 1][static_cast<std::size_t>(row.number)] = &row;
  }
  if (profile.system == GcodeSystem::A) return;
  auto& g = out.rows[0];
  // A number renamed away leaves its old place, unless the system gives the place a code.
  for (const SystemRename& r : kRenames)
    if (r.system == profile.system && r.numberInA >= 0) g[static_cast<std::size_t>(r.numberInA)] = nullptr;
  for (const SystemRename& r : kRenames) {
    if (r.system != profile.system) continue;
    const CodeInfo* from = nullptr;
    if (r.numberInA >= 0) {
      from = baseRow('G', r.numberInA, profile.family);
    } else {
      for (const CodeInfo& row : kSystemOnly)
        if (row.number == r.number && (row.dialects & bit)) from = &row;
    }
    if (!from) continue;
    CodeInfo& copy = out.renamed.emplace_back(*from);
    copy.number = r.number;
    g[static_cast<std::size_t>(r.number)] = &copy;
  }
  // Names and examples speak the system's numbers ("G33 Z-25. F1.5"): every row
  // whose texts name a renamed code gets a copy. Rows only B and C have are
  // written in their own numbers already.
  const auto own = [](const CodeInfo* row) {
    for (const CodeInfo& s : kSystemOnly)
      if (s.number == row->number && s.action == row->action) return true;
    return false;
  };
  for (auto& letterRows : out.rows) {
    for (const CodeInfo*& row : letterRows) {
      if (!row || own(row)) continue;
      CodeInfo copy = *row;
      std::string_view* fields[] = {&copy.nameEn,    &copy.nameTh,  &copy.exampleEn,
                                    &copy.exampleTh, &copy.says.en, &copy.says.th};
      bool changed = false;
      for (std::string_view* f : fields) {
        std::string text = inSystemNumbers(*f, profile.system);
        if (text == *f) continue;
        *f = out.texts.emplace_back(std::move(text));
        changed = true;
      }
      if (changed) row = &out.renamed.emplace_back(copy);
    }
  }
}

}  // namespace detail

std::span<const CodeInfo> codeTable() { return allRows(); }
std::span<const SystemRename> gcodeSystemRenames() { return kRenames; }
std::span<const CodeInfo> systemOnlyRows() { return kSystemOnly; }

bool CodeInfo::in(Dialect d) const { return (dialects & dialectBit(machineProfile(d).family)) != 0; }

int numberInSystem(char letter, int numberInA, Dialect dialect) {
  if (letter != 'G') return numberInA;
  return detail::numberInSystemOf(numberInA, machineProfile(dialect).system);
}

std::string inSystemNumbers(std::string_view text, Dialect dialect) {
  return detail::inSystemNumbers(text, machineProfile(dialect).system);
}

namespace detail {

std::string inSystemNumbers(std::string_view text, GcodeSystem system) {
  std::string out;
  out.reserve(text.size());
  const auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
  const auto isLetter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); };
  for (std::size_t i = 0; i < text.size();) {
    std::size_t end = i + 1;
    while (end < text.size() && isDigit(text[end])) ++end;
    const bool word = text[i] == 'G' && end > i + 1 && end - i <= 3 &&
                      (i == 0 || (!isLetter(text[i - 1]) && !isDigit(text[i - 1]))) &&
                      (end == text.size() || text[end] != '.');
    if (!word) {
      out += text[i++];
      continue;
    }
    const int inA = std::stoi(std::string(text.substr(i + 1, end - i - 1)));
    const int inSystem = numberInSystemOf(inA, system);
    out += inSystem >= 0 && inSystem != inA ? fmt::format("G{:02}", inSystem) : std::string(text.substr(i, end - i));
    i = end;
  }
  return out;
}

}  // namespace detail

int numberInA(char letter, int number, Dialect dialect) {
  const MachineProfile& p = machineProfile(dialect);
  if (letter != 'G' || p.system == GcodeSystem::A) return number;
  for (const SystemRename& r : kRenames)
    if (r.system == p.system && r.number == number) return r.numberInA;
  return number;
}

const CodeInfo* findCode(char letter, int number, Dialect dialect) {
  if ((letter != 'G' && letter != 'M') || number < 0 || number >= kCodeNumbers) return nullptr;
  return detail::codeIndexOf(dialect).rows[letter == 'G' ? 0 : 1][static_cast<std::size_t>(number)];
}

namespace {
using table_rows::kF;
// Fanuc 0i-TF G codes with a decimal point (the manual's G code list for the T series).
constexpr DecimalCode kDecimalCodes[] = {
    {5.1, kF, false, {"AI contour control", "ควบคุมเส้นทางแบบ AI (อ่านล่วงหน้า)"}},
    {5.4, kF, false, {"HRV3 on/off", "เปิด/ปิด HRV3"}},
    {7.1, kF, true, {"cylindrical interpolation", "การประมาณค่าในพิกัดทรงกระบอก"}},
    {10.6, kF, false, {"tool retract and recover", "ถอยมีดและกลับสู่ตำแหน่ง"}},
    {12.1, kF, true, {"polar coordinate interpolation", "การประมาณค่าในพิกัดเชิงขั้ว"}},
    {13.1, kF, false, {"polar coordinate interpolation cancel", "ยกเลิกการประมาณค่าในพิกัดเชิงขั้ว"}},
    {54.1, kF, false, {"additional work coordinate system", "ระบบพิกัดงานเพิ่มเติม"}},
};
}  // namespace

const DecimalCode* findDecimalCode(double value, Dialect dialect) {
  const std::uint8_t bit = dialectBit(machineProfile(dialect).family);
  for (const DecimalCode& c : kDecimalCodes)
    if (std::abs(c.value - value) < 1e-6 && (c.dialects & bit)) return &c;
  return nullptr;
}

std::string codeWord(const CodeInfo& row) { return fmt::format("{}{:02}", row.letter, row.number); }

const CodeInfo* findAction(char letter, CodeAction action, Dialect dialect) {
  if (letter != 'G' && letter != 'M') return nullptr;
  for (const CodeInfo* row : detail::codeIndexOf(dialect).rows[letter == 'G' ? 0 : 1])
    if (row && row->action == action) return row;
  return nullptr;
}

CodeAction actionOf(const Word& word, Dialect dialect) {
  if (word.expr >= 0 || word.hasDecimalPoint) return CodeAction::None;
  const CodeInfo* row = findCode(word.letter, word.code(), dialect);
  return row ? row->action : CodeAction::None;
}

const Word* macroCallWord(const Block& block, Dialect dialect, const CodeInfo** row) {
  if (!block.mayHave('G')) return nullptr;  // (most blocks: their words are not read)
  for (const Word& w : block.words) {
    if (w.letter != 'G' || w.expr >= 0 || w.hasDecimalPoint) continue;
    const CodeInfo* info = findCode('G', w.code(), dialect);
    if (info && (info->action == CodeAction::MacroCall || info->action == CodeAction::MacroModalCall ||
                 info->action == CodeAction::MacroModalCancel)) {
      if (row) *row = info;
      return &w;
    }
  }
  return nullptr;
}

std::optional<CodeInfo> lookupCode(char letter, int number, Dialect dialect) {
  const CodeInfo* row = findCode(letter, number, dialect);
  if (!row) return std::nullopt;
  return *row;
}

std::string_view modalGroupNumber(ModalGroup group) {
  switch (group) {
    case ModalGroup::NonModal: return "00";
    case ModalGroup::Motion: return "01";
    case ModalGroup::SpindleMode: return "02";
    case ModalGroup::FeedMode: return "05";
    case ModalGroup::Units: return "06";
    case ModalGroup::NoseComp: return "07";
    case ModalGroup::CannedCycle: return "10";
    case ModalGroup::MacroModal: return "12";
    case ModalGroup::Distance: return "03";
    case ModalGroup::ReturnLevel: return "11";
    case ModalGroup::WorkOffset: return "14";
    case ModalGroup::Plane: return "16";
    case ModalGroup::ToolLength: return "08";
    case ModalGroup::ExactStop: return "15";
    case ModalGroup::StrokeCheck: return "09";
    case ModalGroup::SpeedCheck: return "08";
    case ModalGroup::MirrorImage: return "04";
    case ModalGroup::Lookahead: return "G103";
    case ModalGroup::Smoothness: return "G187";
    case ModalGroup::SpindleSwap: return "G14/G15";
    case ModalGroup::PolarInterp: return "G112/G113";
    case ModalGroup::MSpindle: return "M03/M04/M05";
    case ModalGroup::MCoolant: return "M08/M09";
    case ModalGroup::MCAxis: return "M41/M91";
    case ModalGroup::MBrake: return "M86/M87";
    case ModalGroup::MGear: return "M41/M42";
    case ModalGroup::MProgram: return "M00/M01/M02/M30";
    case ModalGroup::MSubprogram: return "M98/M99";
    case ModalGroup::MChuck: return "M10/M11";
    case ModalGroup::MAirBlast: return "M12/M13";
    case ModalGroup::MTailstock: return "M21/M22";
    case ModalGroup::MThreadChamfer: return "M23/M24";
    case ModalGroup::MConveyor: return "M31/M33";
    case ModalGroup::MPartsCatcher: return "M36/M37";
    case ModalGroup::MDoor: return "M85/M86";
    case ModalGroup::MHighPressureCoolant: return "M88/M89";
    case ModalGroup::MOther: return "M";
  }
  return "?";
}

std::string_view dialectName(Dialect dialect) { return machineProfile(dialect).id; }

}  // namespace klueng::core::gcode
