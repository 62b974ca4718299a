// Catalog part for the gcode module: code, English, Thai. Keep codes sorted.
// Placeholders are documented in src/core/gcode/diagnostic_codes.h.
#include "catalog_parts.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kMessages[] = {
    // E1xx: lexical errors and word formats (SPEC 3-4)
    {"E101", "letter {0} has no value: write the number right after it, e.g. {0}20.",
     "อักขระ {0} ไม่มีค่าตัวเลข: เขียนตัวเลขต่อท้ายทันที เช่น {0}20."},
    {"E102", "number {0} has no address letter: put a letter such as X, Z or F right before it",
     "ตัวเลข {0} ไม่มีอักขระนำหน้า: ใส่อักขระ เช่น X, Z หรือ F ไว้หน้าตัวเลขทันที"},
    {"E103", "{0} is not a valid number: write digits with at most one sign and one decimal point, e.g. X-12.5",
     "{0} ไม่ใช่ตัวเลขที่ถูกต้อง: เขียนตัวเลขที่มีเครื่องหมายและจุดทศนิยมได้อย่างละไม่เกินหนึ่งตัว เช่น X-12.5"},
    {"E104", "character '{0}' is not allowed here: remove it, or put text inside ( ) or after ;",
     "ไม่อนุญาตให้ใช้อักขระ '{0}' ตรงนี้: ลบออก หรือเขียนข้อความไว้ใน ( ) หรือหลัง ;"},
    {"E105", "comment opened with ( is not closed on this line: add )",
     "หมายเหตุที่เปิดด้วย ( ไม่ได้ปิดในบรรทัดนี้: เติม )"},
    {"E106", "'/' (block skip) may only stand at the start of a block: move it to the front or remove it",
     "'/' (ข้ามบล็อก) ต้องอยู่ต้นบล็อกเท่านั้น: ย้ายไปไว้หน้าบล็อกหรือลบออก"},
    {"E107", "'%' (tape start/end) must stand on a line of its own: remove it from this line",
     "'%' (เริ่ม/จบเทป) ต้องอยู่บรรทัดของตัวเองเท่านั้น: ลบออกจากบรรทัดนี้"},
    {"E108", "{0} after '%' is not run: a '%' line marks the tape start or end; move the words to the next line",
     "{0} ที่อยู่หลัง '%' จะไม่ถูกทำงาน: บรรทัด '%' ใช้บอกเริ่มหรือจบเทป ให้ย้ายคำสั่งไปบรรทัดถัดไป"},
    {"E109", "too many errors in the text; the rest of the file is not listed",
     "ข้อผิดพลาดในข้อความมีมากเกินไป จึงไม่แสดงส่วนที่เหลือของไฟล์"},
    {"E110", "{0} is out of range: the value must be from {1} to {2}",
     "{0} มีค่าเกินขอบเขต: ค่าต้องอยู่ระหว่าง {1} ถึง {2}"},
    {"E111", "{0} has too many decimals: at most {1} digits after the decimal point",
     "{0} มีทศนิยมมากเกินไป: ใช้ทศนิยมได้ไม่เกิน {1} ตำแหน่ง"},
    {"E112", "{0}: {1} must be positive ({2} to {3})",
     "{0}: ค่า {1} ต้องเป็นบวก ({2} ถึง {3})"},
    {"E113", "{0}: a G or M code is a whole number, write it without a decimal point (e.g. G01)",
     "{0}: รหัส G หรือ M ต้องเป็นจำนวนเต็ม เขียนโดยไม่มีจุดทศนิยม (เช่น G01)"},
    {"E114", "{0} is not a G code of this lathe: see Help > Contents for the list of G codes",
     "{0} ไม่ใช่รหัส G ของเครื่องกลึงนี้: ดูรายการรหัส G ได้ที่ ช่วยเหลือ > เนื้อหาระบบช่วยเหลือ"},
    {"E115", "{0} is not an M code of this lathe: see Help > Contents for the list of M codes",
     "{0} ไม่ใช่รหัส M ของเครื่องกลึงนี้: ดูรายการรหัส M ได้ที่ ช่วยเหลือ > เนื้อหาระบบช่วยเหลือ"},
    {"E116", "{0}: {1} must be a whole number from 1 to {2}",
     "{0}: ค่า {1} ต้องเป็นจำนวนเต็มตั้งแต่ 1 ถึง {2}"},
    {"E117", "{0}: write T with 4 digits, tool 01-08 then offset 00-16 (e.g. T0101)",
     "{0}: เขียน T ด้วยตัวเลข 4 หลัก คือหมายเลขมีดตัด 01-08 ตามด้วยหมายเลขออฟเซต 00-16 (เช่น T0101)"},
    {"E118", "{0}: write T as tool 01-{1} then offset 00-{2}, e.g. T0101 (or T101)",
     "{0}: เขียน T เป็นหมายเลขมีดตัด 01-{1} ตามด้วยหมายเลขออฟเซต 00-{2} เช่น T0101 (หรือ T101)"},
    {"E119", "{0}: {1} must be a whole number without sign or decimal point (e.g. {1}500)",
     "{0}: ค่า {1} ต้องเป็นจำนวนเต็มไม่มีเครื่องหมายและจุดทศนิยม (เช่น {1}500)"},
    {"E120", "this block has more than {0} words; the rest of the line is not read: split it into several blocks",
     "บล็อกนี้มีคำสั่งมากกว่า {0} คำ จึงไม่อ่านส่วนที่เหลือของบรรทัด: แบ่งเป็นหลายบล็อก"},
    {"E199", "more than {0} errors; the rest of the program is not checked",
     "พบข้อผิดพลาดมากกว่า {0} รายการ จึงไม่ตรวจสอบส่วนที่เหลือของโปรแกรม"},

    // E2nn: block rule nn of SPEC 5
    {"E201", "{0}: letter {1} is not a lathe word; use {2}",
     "{0}: อักขระ {1} ไม่ใช่คำสั่งของเครื่องกลึง ใช้ได้เฉพาะ {2}"},
    {"E202", "{0} appears twice in this block: keep only one {0} word",
     "{0} ปรากฏสองครั้งในบล็อกนี้: ให้เหลือคำสั่ง {0} เพียงคำเดียว"},
    {"E203", "{0} must stand alone in its block (only N may come before it): move the other words to another block",
     "{0} ต้องอยู่เดี่ยวในบล็อก (มีได้เพียง N นำหน้า): ย้ายคำสั่งอื่นไปไว้บล็อกอื่น"},
    {"E204", "{0} and {1} cannot share a block: keep one of them, or put them in separate blocks",
     "{0} และ {1} อยู่ในบล็อกเดียวกันไม่ได้: เลือกใช้เพียงหนึ่งคำสั่ง หรือแยกไว้คนละบล็อก"},
    {"E205", "{0} and {1} belong to the same modal group ({2}): keep only one of them in this block",
     "{0} และ {1} อยู่ในกลุ่มโมดอลเดียวกัน ({2}): ให้เหลือเพียงหนึ่งคำสั่งในบล็อกนี้"},
    {"E206", "{0} (one-shot, group 00) cannot share a block with {1} (motion, group 01): put them in separate blocks",
     "{0} (ทำงานครั้งเดียว กลุ่ม 00) อยู่บล็อกเดียวกับ {1} (การเคลื่อนที่ กลุ่ม 01) ไม่ได้: แยกไว้คนละบล็อก"},
    {"E207", "{0} must stand alone in its block in the classic dialect: move the other words to another block",
     "{0} ต้องอยู่เดี่ยวในบล็อกเมื่อใช้รูปแบบคำสั่งแบบคลาสสิก (Rook classic): ย้ายคำสั่งอื่นไปไว้บล็อกอื่น"},
    {"E208", "{0}: the program number O may only be the first word of the program, alone in its block",
     "{0}: หมายเลขโปรแกรม O ต้องเป็นคำสั่งแรกของโปรแกรมและอยู่เดี่ยวในบล็อกเท่านั้น"},
    {"E209", "{0}: the block number N must be the first word of the block: move it to the front",
     "{0}: หมายเลขบล็อก N ต้องเป็นคำสั่งแรกของบล็อก: ย้ายไปไว้หน้าบล็อก"},
    {"E210", "{0} and {1} in one block: use {0} (absolute) or {1} (incremental), not both",
     "{0} และ {1} อยู่ในบล็อกเดียวกัน: ใช้ {0} (ค่าสัมบูรณ์) หรือ {1} (ค่าส่วนเพิ่ม) อย่างใดอย่างหนึ่ง"},
    {"E211", "G04 needs the dwell time: add U or X (seconds) or P (milliseconds), e.g. G04 U0.5",
     "G04 ต้องกำหนดเวลาหยุดรอ: เติม U หรือ X (วินาที) หรือ P (มิลลิวินาที) เช่น G04 U0.5"},

    // E3xx: "ext" block rules
    {"E301", "{0} needs an end point: add X/U and/or Z/W",
     "{0} ต้องกำหนดจุดปลายทาง: เติม X/U และ/หรือ Z/W"},
    {"E302", "{0} with both R and I/K: give the arc either by its radius R or by its centre I/K, not both",
     "{0} มีทั้ง R และ I/K: กำหนดส่วนโค้งด้วยรัศมี R หรือด้วยจุดศูนย์กลาง I/K อย่างใดอย่างหนึ่ง"},
    {"E303", "{0} cannot start nose radius compensation on an arc ({1}): start it on a G00 or G01 block",
     "{0} เริ่มการชดเชยรัศมีจมูกมีดบนส่วนโค้ง ({1}) ไม่ได้: ให้เริ่มในบล็อก G00 หรือ G01"},
    {"E304", "G40 cannot end nose radius compensation on an arc ({0}): end it on a G00 or G01 block",
     "G40 ยกเลิกการชดเชยรัศมีจมูกมีดบนส่วนโค้ง ({0}) ไม่ได้: ให้ยกเลิกในบล็อก G00 หรือ G01"},
    {"E305", "{0}: tool {1} has no bitmap in tools.cfg: choose it in Tool setting > Tool select, or use another tool",
     "{0}: มีดตัดหมายเลข {1} ไม่มีรูปภาพใน tools.cfg: กำหนดที่ การตั้งค่ามีดตัด > เลือกมีดตัด หรือใช้มีดตัดอื่น"},
    {"E306", "{0}: the dwell time cannot be negative",
     "{0}: เวลาหยุดรอต้องไม่เป็นค่าลบ"},
    {"E307", "{0} and {1} both give the dwell time: use P (milliseconds) or U/X (seconds), not both",
     "{0} และ {1} กำหนดเวลาหยุดรอซ้ำกัน: ใช้ P (มิลลิวินาที) หรือ U/X (วินาที) อย่างใดอย่างหนึ่ง"},
    {"E308", "{0} in a G04 block: a dwell does not move, remove {0} or move it to another block",
     "{0} อยู่ในบล็อก G04: การหยุดรอไม่มีการเคลื่อนที่ ให้ลบ {0} หรือย้ายไปไว้บล็อกอื่น"},
    {"E309", "G28 needs an intermediate point: add X/U and Z/W (e.g. G28 U0. W0.)",
     "G28 ต้องกำหนดจุดกลางทาง: เติม X/U และ Z/W (เช่น G28 U0. W0.)"},

    // W1xx: warnings
    {"W101", "{0} is not a standard M code: machine-specific, ignored",
     "{0} ไม่ใช่รหัส M มาตรฐาน: เป็นรหัสเฉพาะของเครื่อง จะไม่ถูกทำงาน"},
    {"W102", "G28 without axis words moves nothing: add U0. W0. to return to the reference point",
     "G28 ที่ไม่มีคำสั่งแกนจะไม่เคลื่อนที่: เติม U0. W0. เพื่อกลับสู่จุดอ้างอิง"},
    {"W103", "{0} has more than {2} decimals: the control rounds it to {1}",
     "{0} มีทศนิยมเกิน {2} ตำแหน่ง: เครื่องจะปัดค่าเป็น {1}"},

    // I1xx: notes
    {"I102", "blocks with errors that are {1} forms: {0}; choose the {1} dialect (--dialect {2})",
     "บล็อกที่ผิดพลาด {0} บล็อกเป็นรูปแบบของ {1}: เลือกรูปแบบคำสั่ง {1} (--dialect {2})"},
};
}  // namespace

std::span<const MessageText> gcodeMessages() { return kMessages; }

}  // namespace klueng::core::catalog
