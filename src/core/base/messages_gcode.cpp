// Catalog part for the gcode module: code, English, Thai. Keep codes sorted.
// Placeholders are documented in src/core/gcode/diagnostic_codes.h.
#include "catalog_parts.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kGcodeMessages[] = {
    // E1xx: lexical errors and word formats (SPEC 3-4)
    {"E101", "letter {0} has no value: write the number right after it, e.g. {0}20.",
     "อักขระ {0} ไม่มีค่าตัวเลข: เขียนตัวเลขต่อท้ายทันที เช่น {0}20."},
    {"E102", "number {0} has no address letter: put a letter such as X, Z or F right before it",
     "ตัวเลข {0} ไม่มีอักขระนำหน้า: ใส่อักขระ เช่น X, Z หรือ F ไว้หน้าตัวเลขทันที"},
    {"E103", "{0} is not a valid number: write digits with at most one sign and one decimal point, e.g. X-12.5",
     "{0} ไม่ใช่ตัวเลขที่ถูกต้อง: เขียนตัวเลขที่มีเครื่องหมายและจุดทศนิยมได้อย่างละไม่เกินหนึ่งตัว เช่น X-12.5"},
    {"E104", "character '{0}' is not allowed here: remove it, or put text inside ( ) or after ;",
     "ไม่อนุญาตให้ใช้อักขระ '{0}' ตรงนี้: ลบออก หรือเขียนข้อความไว้ใน ( ) หรือหลัง ;"},
    {"E105", "comment opened with ( is not closed on this line: add )", "หมายเหตุที่เปิดด้วย ( ไม่ได้ปิดในบรรทัดนี้: เติม )"},
    {"E106", "'/' (block skip) may only stand at the start of a block: move it to the front or remove it",
     "'/' (ข้ามบล็อก) ต้องอยู่ต้นบล็อกเท่านั้น: ย้ายไปไว้หน้าบล็อกหรือลบออก"},
    {"E107", "'%' (tape start/end) must stand on a line of its own: remove it from this line",
     "'%' (เริ่ม/จบเทป) ต้องอยู่บรรทัดของตัวเองเท่านั้น: ลบออกจากบรรทัดนี้"},
    {"E108", "{0} after '%' is not run: a '%' line marks the tape start or end; move the words to the next line",
     "{0} ที่อยู่หลัง '%' จะไม่ถูกทำงาน: บรรทัด '%' ใช้บอกเริ่มหรือจบเทป ให้ย้ายคำสั่งไปบรรทัดถัดไป"},
    {"E109", "too many errors in the text; the rest of the file is not listed",
     "ข้อผิดพลาดในข้อความมีมากเกินไป จึงไม่แสดงส่วนที่เหลือของไฟล์"},
    {"E110", "{0} is out of range: the value must be from {1} to {2}", "{0} มีค่าเกินขอบเขต: ค่าต้องอยู่ระหว่าง {1} ถึง {2}"},
    {"E111", "{0} has too many decimals: at most {1} digits after the decimal point",
     "{0} มีทศนิยมมากเกินไป: ใช้ทศนิยมได้ไม่เกิน {1} ตำแหน่ง"},
    {"E112", "{0}: {1} must be positive ({2} to {3})", "{0}: ค่า {1} ต้องเป็นบวก ({2} ถึง {3})"},
    {"E143",
     "{0}: a spindle speed of zero: the spindle stands still until the next S (a cutting move then stops the run)",
     "{0}: ความเร็วรอบเพลาเป็นศูนย์ เพลาจะหยุดนิ่งจนกว่าจะสั่ง S ใหม่ (การตัดเฉือนระหว่างนั้นจะทำให้การจำลองหยุด)"},
    {"E113", "{0}: a G or M code is a whole number, write it without a decimal point (e.g. G01)",
     "{0}: รหัส G หรือ M ต้องเป็นจำนวนเต็ม เขียนโดยไม่มีจุดทศนิยม (เช่น G01)"},
    {"E114", "{0} is not a G code of this lathe: see Help > Contents for the list of G codes",
     "{0} ไม่ใช่รหัส G ของเครื่องกลึงนี้: ดูรายการรหัส G ได้ที่ ช่วยเหลือ > เนื้อหาระบบช่วยเหลือ"},
    {"E115", "{0} is not an M code of this lathe: see Help > Contents for the list of M codes",
     "{0} ไม่ใช่รหัส M ของเครื่องกลึงนี้: ดูรายการรหัส M ได้ที่ ช่วยเหลือ > เนื้อหาระบบช่วยเหลือ"},
    {"E116", "{0}: {1} must be a whole number from 1 to {2}", "{0}: ค่า {1} ต้องเป็นจำนวนเต็มตั้งแต่ 1 ถึง {2}"},
    {"E117", "{0}: write T with 4 digits, tool 01-08 then offset 00-16 (e.g. T0101)",
     "{0}: เขียน T ด้วยตัวเลข 4 หลัก คือหมายเลขมีดตัด 01-08 ตามด้วยหมายเลขออฟเซต 00-16 (เช่น T0101)"},
    {"E118", "{0}: write T as tool 01-{1} then offset 00-{2}, e.g. T0101 (or T101)",
     "{0}: เขียน T เป็นหมายเลขมีดตัด 01-{1} ตามด้วยหมายเลขออฟเซต 00-{2} เช่น T0101 (หรือ T101)"},
    {"E119", "{0}: {1} must be a whole number without sign or decimal point (e.g. {1}500)",
     "{0}: ค่า {1} ต้องเป็นจำนวนเต็มไม่มีเครื่องหมายและจุดทศนิยม (เช่น {1}500)"},
    {"E120", "this block has more than {0} words; the rest of the line is not read: split it into several blocks",
     "บล็อกนี้มีคำสั่งมากกว่า {0} คำ จึงไม่อ่านส่วนที่เหลือของบรรทัด: แบ่งเป็นหลายบล็อก"},
    {"E121", "'[' has no matching ']' in this macro expression", "วงเล็บ '[' ไม่มี ']' ปิดในนิพจน์มาโครนี้"},
    {"E122", "a value was expected in this macro expression, but '{0}' was found",
     "นิพจน์มาโครนี้ต้องการค่าตัวเลขหรือตัวแปร แต่พบ '{0}'"},
    {"E123", "'{0}' is not a function or operator of custom macro B", "'{0}' ไม่ใช่ฟังก์ชันหรือตัวดำเนินการของมาโคร B"},
    {"E124", "{0} needs its argument in brackets: {0}[...]", "{0} ต้องมีอาร์กิวเมนต์อยู่ในวงเล็บ: {0}[...]"},
    {"E125", "'{0}' is not a variable: write # and a whole number (#101) or a bracket (#[#1+100])",
     "'{0}' ไม่ใช่ตัวแปร: ต้องเขียน # ตามด้วยจำนวนเต็ม (#101) หรือวงเล็บ (#[#1+100])"},
    {"E126", "the macro expression is nested more than {0} levels deep", "นิพจน์มาโครซ้อนกันลึกเกิน {0} ชั้น"},
    {"E127", "{0} cannot share a block with a macro statement: put the statement on its own line",
     "{0} อยู่ในบล็อกเดียวกับคำสั่งมาโครไม่ได้ ต้องแยกคำสั่งมาโครไว้บรรทัดของตัวเอง"},
    {"E128", "IF [condition] must be followed by GOTO n or THEN #i = value",
     "IF [เงื่อนไข] ต้องตามด้วย GOTO n หรือ THEN #i = ค่า"},
    {"E129", "WHILE [condition] must be followed by DO m (m = 1, 2 or 3)",
     "WHILE [เงื่อนไข] ต้องตามด้วย DO m (m = 1, 2 หรือ 3)"},
    {"E130", "loop number {0} is not allowed: DO and END take 1, 2 or 3",
     "ใช้หมายเลขลูป {0} ไม่ได้: DO และ END ใช้ได้เฉพาะ 1, 2 หรือ 3"},
    {"E131", "'{0}' is not a macro statement: write #i = value", "'{0}' ไม่ใช่คำสั่งมาโครที่ถูกต้อง: ต้องเขียนเป็น #i = ค่า"},
    {"E132", "{0}: chamfer ,C, corner ,R and angle ,A belong to a G01 block",
     "{0}: การลบมุม ,C การมนมุม ,R และมุม ,A ใช้ได้เฉพาะในบล็อก G01"},
    {"E134", "{0}{1}: a G-code number has no exponent (E): write the value of {0}{1} in digits with a decimal point",
     "{0}{1}: ตัวเลขในจีโค้ดเขียนแบบยกกำลัง (E) ไม่ได้: ให้เขียนค่าของ {0}{1} เป็นตัวเลขพร้อมจุดทศนิยม"},
    {"E139",
     "{0}: a number in a macro expression has no exponent (E): write the value of {0} in digits with a decimal point",
     "{0}: ตัวเลขในนิพจน์มาโครเขียนแบบยกกำลัง (E) ไม่ได้: ให้เขียนค่าของ {0} เป็นตัวเลขพร้อมจุดทศนิยม"},
    {"E133", "{0} and {1} in one block: a corner is either a chamfer or a radius",
     "{0} และ {1} อยู่ในบล็อกเดียวกัน: มุมหนึ่งเป็นได้เพียงการลบมุมหรือการมนมุมอย่างใดอย่างหนึ่ง"},
    {"E135",
     "{0} is written with blanks inside: the classic dialect (1999 rules) needs the number right after the letter: "
     "write {0}",
     "{0} เขียนโดยมีช่องว่างอยู่ภายใน: รูปแบบคำสั่งแบบคลาสสิก (กฎปี 2542) ต้องเขียนตัวเลขต่อท้ายอักขระทันที ให้เขียนเป็น {0}"},
    {"E136", "{0}: the letter O is not the digit 0; did you mean {1}?",
     "{0}: ตัวอักษร O ไม่ใช่ตัวเลขศูนย์ (0) หมายถึง {1} ใช่หรือไม่"},
    {"E137", "{0}: a comma is not a decimal point; did you mean {1}?",
     "{0}: เครื่องหมายจุลภาค (,) ไม่ใช่จุดทศนิยม หมายถึง {1} ใช่หรือไม่"},
    {"E138",
     "this line looks like text (\"{0}\"): the control stops here; put the text inside ( ) to make it a comment",
     "บรรทัดนี้ดูเหมือนเป็นข้อความ (\"{0}\") เครื่องจะหยุดทำงานที่บรรทัดนี้: ให้เขียนข้อความไว้ใน ( ) เพื่อให้เป็นหมายเหตุ"},
    {"E141",
     "this control ends the block at ';' and reads \"{0}\" after it as the next block: it is not G-code, so the "
     "control stops here; put the text inside ( )",
     "เครื่องนี้จบบล็อกที่ ';' และอ่าน \"{0}\" ที่อยู่หลังเป็นบล็อกถัดไป ซึ่งไม่ใช่จีโค้ด เครื่องจึงหยุดที่นี่: ให้เขียนข้อความไว้ใน ( )"},
    {"E142",
     "this control ends a comment at its first ')': \"{0}\" after it is read as G-code and the control stops here; "
     "leave out the parentheses inside the comment",
     "เครื่องนี้จบหมายเหตุที่ ')' ตัวแรก: \"{0}\" ที่อยู่หลังจะถูกอ่านเป็นจีโค้ด และเครื่องจะหยุดที่นี่ ให้เอาวงเล็บที่อยู่ภายในหมายเหตุออก"},
    {"E199", "more than {0} errors; the rest of the program is not checked",
     "พบข้อผิดพลาดมากกว่า {0} รายการ จึงไม่ตรวจสอบส่วนที่เหลือของโปรแกรม"},

    // E2nn: block rule nn of SPEC 5
    {"E201", "{0}: letter {1} is not a lathe word; use {2}", "{0}: อักขระ {1} ไม่ใช่คำสั่งของเครื่องกลึง ใช้ได้เฉพาะ {2}"},
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
    {"E301", "{0} needs an end point: add X/U and/or Z/W", "{0} ต้องกำหนดจุดปลายทาง: เติม X/U และ/หรือ Z/W"},
    {"E302", "{0} with both R and I/K: give the arc either by its radius R or by its centre I/K, not both",
     "{0} มีทั้ง R และ I/K: กำหนดส่วนโค้งด้วยรัศมี R หรือด้วยจุดศูนย์กลาง I/K อย่างใดอย่างหนึ่ง"},
    {"E303", "{0} cannot start nose radius compensation on an arc ({1}): start it on a G00 or G01 block",
     "{0} เริ่มการชดเชยรัศมีจมูกมีดบนส่วนโค้ง ({1}) ไม่ได้: ให้เริ่มในบล็อก G00 หรือ G01"},
    {"E304", "G40 cannot end nose radius compensation on an arc ({0}): end it on a G00 or G01 block",
     "G40 ยกเลิกการชดเชยรัศมีจมูกมีดบนส่วนโค้ง ({0}) ไม่ได้: ให้ยกเลิกในบล็อก G00 หรือ G01"},
    {"E305", "{0}: tool {1} has no bitmap in tools.cfg: choose it in Tool setting > Tool select, or use another tool",
     "{0}: มีดตัดหมายเลข {1} ไม่มีรูปภาพใน tools.cfg: กำหนดที่ การตั้งค่ามีดตัด > เลือกมีดตัด หรือใช้มีดตัดอื่น"},
    {codes::kToolBitmapUnusable,
     "{0}: tool {1}'s bitmap in tools.cfg cannot be used ({2}): choose another in Tool setting > Tool select, or use "
     "another tool",
     "{0}: ใช้รูปภาพของมีดตัดหมายเลข {1} ใน tools.cfg ไม่ได้ ({3}): เลือกรูปอื่นที่ การตั้งค่ามีดตัด > เลือกมีดตัด หรือใช้มีดตัดอื่น"},
    {"E306", "{0}: the dwell time cannot be negative", "{0}: เวลาหยุดรอต้องไม่เป็นค่าลบ"},
    {"E307", "{0} and {1} both give the dwell time: use P (milliseconds) or U/X (seconds), not both",
     "{0} และ {1} กำหนดเวลาหยุดรอซ้ำกัน: ใช้ P (มิลลิวินาที) หรือ U/X (วินาที) อย่างใดอย่างหนึ่ง"},
    {"E308", "{0} in a G04 block: a dwell does not move, remove {0} or move it to another block",
     "{0} อยู่ในบล็อก G04: การหยุดรอไม่มีการเคลื่อนที่ ให้ลบ {0} หรือย้ายไปไว้บล็อกอื่น"},
    {"E309", "G28 needs an intermediate point: add X/U and Z/W (e.g. G28 U0. W0.)",
     "G28 ต้องกำหนดจุดกลางทาง: เติม X/U และ Z/W (เช่น G28 U0. W0.)"},
    {"E310", "{0} needs its radius R or its centre I/K: an arc cannot be cut from its end point alone",
     "{0} ต้องกำหนดรัศมี R หรือจุดศูนย์กลาง I/K: ส่วนโค้งกำหนดจากจุดปลายอย่างเดียวไม่ได้"},

    // W1xx: warnings
    {"E401", "DO{0} has no END{0} after it in this program", "DO{0} ไม่มี END{0} ปิดท้ายในโปรแกรมนี้"},
    {"E402", "END{0} has no DO{0} before it in this program", "END{0} ไม่มี DO{0} ก่อนหน้าในโปรแกรมนี้"},
    {"E403", "{0}: there is no block N{1} in this program to jump to", "{0}: ไม่มีบล็อก N{1} ในโปรแกรมนี้ให้กระโดดไป"},
    {"E404", "{0}: program O{1} is neither in this file nor in its folder (as O{1}.nc or {1}.nc)",
     "{0}: ไม่พบโปรแกรม O{1} ทั้งในไฟล์นี้และในโฟลเดอร์เดียวกัน (ชื่อ O{1}.nc หรือ {1}.nc)"},
    {"E416", "{0}: program O{1} is not in this file, and '{2}' in its folder is {3}, not a program file",
     "{0}: ไม่มีโปรแกรม O{1} ในไฟล์นี้ และ '{2}' ในโฟลเดอร์เดียวกันเป็น{4} ไม่ใช่ไฟล์โปรแกรม"},
    {"E405", "{0}: there is no block N{1} in this program for the local subprogram",
     "{0}: ไม่มีบล็อก N{1} ในโปรแกรมนี้สำหรับโปรแกรมย่อยภายใน"},
    {"E406",
     "{0}: the letter {1} cannot pass an argument to a macro (G, N and O are not arguments; P and L name the macro and "
     "its repeats)",
     "{0}: ตัวอักษร {1} ใช้ส่งอาร์กิวเมนต์ให้มาโครไม่ได้ (G, N และ O ไม่ใช่อาร์กิวเมนต์ ส่วน P และ L คือหมายเลขมาโครและจำนวนครั้ง)"},
    {"E407", "{0}: custom macro statements are not part of this dialect (choose Fanuc or Haas)",
     "{0}: ภาษานี้ไม่มีคำสั่งมาโคร (ให้เลือก Fanuc หรือ Haas)"},
    {"E408", "DO{0} is nested more than 3 loops deep", "DO{0} ซ้อนลูปลึกเกิน 3 ชั้น"},
    {"E409", "{0} closes a loop that crosses the loop started at line {1}: loops must nest",
     "{0} ปิดลูปที่ไขว้กับลูปที่เริ่มที่บรรทัด {1}: ลูปต้องซ้อนกันอยู่ภายใน"},
    {"E410", "#{0} cannot be written (read-only or not a variable)",
     "เขียนค่าลงใน #{0} ไม่ได้ (อ่านได้อย่างเดียวหรือไม่ใช่ตัวแปร)"},
    {"E411", "{0}: subprogram calls nest more than {1} levels deep", "{0}: การเรียกโปรแกรมย่อยซ้อนกันลึกเกิน {1} ชั้น"},
    {"E412", "{0} has errors: the first is {3} at line {1}, column {2} of that file (open it to see them all)",
     "{0} มีข้อผิดพลาด: ข้อแรกคือ {3} ที่บรรทัด {1} คอลัมน์ {2} ของไฟล์นั้น (เปิดไฟล์นั้นเพื่อดูทั้งหมด)"},
    {"E413",
     "{0}: there is no block N{1} in this program for the profile (P names its first block, Q its last, at or after P)",
     "{0}: ไม่มีบล็อก N{1} ในโปรแกรมนี้สำหรับรูปร่างชิ้นงาน (P คือบล็อกแรกของรูปร่าง Q คือบล็อกสุดท้าย ซึ่งอยู่ที่หรือถัดจาก P)"},
    {"E415", "{0}: block N{1} lies before N{2}, where the profile starts: Q names the profile's last block, after P's",
     "{0}: บล็อก N{1} อยู่ก่อน N{2} ซึ่งเป็นจุดเริ่มของรูปร่างชิ้นงาน: Q คือบล็อกสุดท้ายของรูปร่าง ซึ่งต้องอยู่ถัดจากบล็อกของ P"},
    {"E417",
     "{0}: the shape N{1}-N{2} holds this cycle's own block, so the cycle would read itself as part of the shape: the "
     "control stops; put the shape after the cycle (or before it) and let P and Q name only its blocks",
     "{0}: รูปร่าง N{1}-N{2} มีบล็อกของวัฏจักรนี้อยู่ด้วย วัฏจักรจึงอ่านตัวเองเป็นส่วนหนึ่งของรูปร่าง เครื่องจะหยุด: "
     "ให้เขียนรูปร่างไว้หลัง (หรือก่อน) วัฏจักร และให้ P กับ Q ระบุเฉพาะบล็อกของรูปร่าง"},
    {"E419",
     "{0} without P: the block names no program to call; write the program's number after P ({0} P1000; Fanuc alarm "
     "PS0076)",
     "{0} ไม่มี P: บล็อกนี้ไม่ได้ระบุโปรแกรมที่จะเรียก ให้เขียนหมายเลขโปรแกรมต่อท้าย P ({0} P1000; สัญญาณเตือน PS0076 ของ "
     "Fanuc)"},
    {"E418",
     "{0} roughs at the feed F of its block or the one in force, but no F has been given before it: the control stops "
     "(feed zero); add F to the cycle's block, e.g. F0.2",
     "{0} กลึงหยาบด้วยอัตราป้อน F ในบล็อกของวัฏจักรหรือค่าที่ใช้อยู่ แต่ยังไม่มีการกำหนด F ก่อนหน้านี้ เครื่องจะหยุด (อัตราป้อนเป็นศูนย์): "
     "ให้เติม F ในบล็อกของวัฏจักร เช่น F0.2"},
    {"E414",
     "{0}: the first block of the profile, N{1}, holds neither G00 nor G01; the control stops there (Fanuc alarm "
     "PS0065): write the first move in it (N{1} G00 X.. Z..)",
     "{0}: บล็อกแรกของรูปร่างชิ้นงาน N{1} ไม่มี G00 หรือ G01 เครื่องจะหยุดที่บล็อกนี้ (สัญญาณเตือน PS0065 ของ Fanuc) "
     "ให้เขียนการเคลื่อนที่แรกไว้ในบล็อกนั้น (N{1} G00 X.. Z..)"},
    {"W101", "{0} is not a standard M code: machine-specific, ignored",
     "{0} ไม่ใช่รหัส M มาตรฐาน: เป็นรหัสเฉพาะของเครื่อง จะไม่ถูกทำงาน"},
    {"W102", "G28 without axis words moves nothing: add U0. W0. to return to the reference point",
     "G28 ที่ไม่มีคำสั่งแกนจะไม่เคลื่อนที่: เติม U0. W0. เพื่อกลับสู่จุดอ้างอิง"},
    {"W103", "{0} has more than {2} decimals: the control rounds it to {1}",
     "{0} มีทศนิยมเกิน {2} ตำแหน่ง: เครื่องจะปัดค่าเป็น {1}"},
    {"W104",
     "{0} with no feed rate in force: no F has been given yet, so the run stops here with alarm A102; add F (e.g. F0.2 "
     "under G99)",
     "{0} ไม่มีอัตราป้อน: ยังไม่ได้กำหนด F มาก่อน เมื่อรันจะหยุดที่บล็อกนี้ด้วยสัญญาณเตือน A102 ให้เติม F (เช่น F0.2 เมื่อใช้ G99)"},
    {"W105",
     "G96 with no G50 S limit before it: near the centre the spindle speeds up to the machine's maximum; give a limit "
     "first (e.g. G50 S2000)",
     "G96 โดยไม่มี G50 S จำกัดความเร็วรอบไว้ก่อน: เมื่อมีดเข้าใกล้ศูนย์กลาง เพลาจะหมุนเร็วขึ้นจนถึงความเร็วรอบสูงสุดของเครื่อง "
     "ให้กำหนดขีดจำกัดก่อน (เช่น G50 S2000)"},
    {"W107",
     "{0} on a G01 is not read: a chamfer or corner round is written with a comma ({1}), so the corner stays sharp",
     "{0} ในบล็อก G01 ไม่ถูกอ่าน การลบมุมหรือการมนมุมต้องเขียนโดยมีจุลภาคนำหน้า ({1}) มุมจึงยังคงเป็นมุมแหลม"},
    {"W106",
     "{0} cannot join the arc's ends: the radius is smaller than half their distance ({1}), so the run stops here with "
     "alarm A114",
     "{0} เชื่อมปลายทั้งสองของส่วนโค้งไม่ได้: รัศมีน้อยกว่าครึ่งหนึ่งของระยะระหว่างปลายทั้งสอง ({1}) เมื่อรันจะหยุดที่บล็อกนี้ด้วยสัญญาณเตือน A114"},
    {"W108",
     "comment opened with ( is not closed on this line: the control reads the rest of the line as the comment; add ) "
     "to close it",
     "หมายเหตุที่เปิดด้วย ( ไม่ได้ปิดในบรรทัดนี้: เครื่องจะถือว่าข้อความที่เหลือทั้งบรรทัดเป็นหมายเหตุ ให้เติม ) เพื่อปิด"},
    {"W109",
     "{0} is read as {1}: the control skips blanks inside a number; if the digits after the blank are another word, "
     "put its letter before them",
     "{0} ถูกอ่านเป็น {1}: เครื่องจะข้ามช่องว่างที่อยู่ในตัวเลข หากตัวเลขหลังช่องว่างเป็นคำสั่งอื่น ให้ใส่อักขระของคำสั่งนั้นไว้ข้างหน้า"},

    {"W110",
     "{0} has no decimal point: this machine reads a length without one in least input increments, so it is {1}; write "
     "{2} for {3}",
     "{0} ไม่มีจุดทศนิยม: เครื่องนี้อ่านความยาวที่ไม่มีจุดทศนิยมเป็นหน่วยป้อนค่าที่เล็กที่สุด จึงได้ {1} ถ้าต้องการ {3} ให้เขียน {2}"},
    {"W111",
     "{0} has no decimal point and is read as {1} (calculator-type input); a control with standard decimal point input "
     "reads it as {2}: if that is meant, write {3} or choose that reading in Job details (--decimal-point increments)",
     "{0} ไม่มีจุดทศนิยมจึงถูกอ่านเป็น {1} (การป้อนค่าแบบเครื่องคิดเลข) เครื่องที่ตั้งการป้อนจุดทศนิยมแบบมาตรฐานจะอ่านเป็น {2} ถ้าต้องการค่านั้น "
     "ให้เขียน {3} หรือเลือกการอ่านแบบนั้นในรายละเอียดงาน (--decimal-point increments)"},

    {"W112",
     "{0} is a single cycle, but this block has no end point (X/U, Z/W): it runs no cycle and only selects {0}, so a "
     "later block with X or Z and no G00/G01 runs the cycle; in G-code system B, G90 is absolute input and G92 S the "
     "spindle speed clamp: if the program is written for system B, choose that machine",
     "{0} เป็นวัฏจักรทำงานครั้งเดียว แต่บล็อกนี้ไม่มีจุดสิ้นสุด (X/U, Z/W) จึงไม่ทำวัฏจักร เพียงเลือกโหมด {0} ไว้ "
     "บล็อกถัดไปที่มี X หรือ Z โดยไม่มี G00/G01 จะทำวัฏจักรนั้น ในระบบรหัส G แบบ B คำสั่ง G90 คือการกำหนดค่าแบบสัมบูรณ์ "
     "และ G92 S คือการจำกัดความเร็วรอบสูงสุด: ถ้าโปรแกรมเขียนสำหรับระบบ B ให้เลือกเครื่องนั้น"},

    {"W115",
     "{0} {1} in G-code system A selects the threading cycle without an end point: it moves nothing and sets the "
     "spindle speed {1} (under G96, a surface speed), not a limit; the speed clamp is G50 {1} in system A and "
     "{0} {1} in system B: if the program is written for system B, choose that machine",
     "{0} {1} ในระบบรหัส G แบบ A คือการเลือกวัฏจักรกลึงเกลียวโดยไม่มีจุดสิ้นสุด จึงไม่เคลื่อนที่ แต่ตั้งความเร็วรอบ {1} "
     "(ถ้าเป็น G96 คือความเร็วตัด) ไม่ใช่การจำกัดความเร็วรอบ การจำกัดความเร็วรอบคือ G50 {1} ในระบบ A และ {0} {1} "
     "ในระบบ B: ถ้าโปรแกรมเขียนสำหรับระบบ B ให้เลือกเครื่องนั้น"},
    {"W116",
     "{0} and {1} belong to the same modal group ({2}): this control uses the last one, {1}; keep only the one you "
     "mean",
     "{0} และ {1} อยู่ในกลุ่มโมดอลเดียวกัน ({2}): เครื่องนี้ใช้ตัวสุดท้ายคือ {1} ให้เหลือไว้เฉพาะคำสั่งที่ต้องการ"},
    {"W113",
     "this control ends a comment at its first ')': \"{0}\" after it stands outside the comment (it holds no word, "
     "the control reads on); leave out the parentheses inside the comment",
     "เครื่องนี้จบหมายเหตุที่ ')' ตัวแรก: \"{0}\" ที่อยู่หลังจึงอยู่นอกหมายเหตุ (ไม่มีคำสั่งใด เครื่องจึงทำงานต่อ) "
     "ให้เอาวงเล็บที่อยู่ภายในหมายเหตุออก"},
    {"W114",
     "this control ends the block at ';' and runs \"{0}\" after it as the next block; Klueng reads it as a comment: "
     "put it on a line of its own",
     "เครื่องนี้จบบล็อกที่ ';' และทำงาน \"{0}\" ที่อยู่หลังเป็นบล็อกถัดไป แต่ Klueng อ่านเป็นหมายเหตุ: ให้เขียนไว้ในบรรทัดของตัวเอง"},
    {"W118",
     "{0} shares its block with other words: this control runs the block's move and other words first, then "
     "stops; a stop on a line of its own is easier to read",
     "{0} อยู่ในบล็อกเดียวกับคำสั่งอื่น: เครื่องนี้ทำการเคลื่อนที่และคำสั่งอื่นในบล็อกก่อนแล้วจึงหยุด "
     "การเขียนคำสั่งหยุดไว้บรรทัดของตัวเองอ่านง่ายกว่า"},
    {"W119",
     "{0} is a code of this control that Klueng does not simulate: the check reads on, but a run stops at this "
     "block (A117); Help > Contents says what the code does",
     "{0} เป็นรหัสของเครื่องนี้ที่ Klueng ไม่จำลอง: การตรวจทำต่อไปได้ แต่การจำลองจะหยุดที่บล็อกนี้ (A117) "
     "ดูความหมายของรหัสได้ที่ วิธีใช้ > สารบัญ"},
    {"W117",
     "{0}: program number 0, as a CAM post leaves it; the program runs, but the control stores programs from O1 "
     "up: give it its own number before you send it to the machine's memory",
     "{0}: หมายเลขโปรแกรม 0 ตามที่โปรแกรม CAM ใส่มา โปรแกรมทำงานได้ แต่เครื่องเก็บโปรแกรมตั้งแต่ O1 ขึ้นไป "
     "ให้ตั้งหมายเลขของโปรแกรมก่อนส่งเข้าหน่วยความจำของเครื่อง"},

    // I1xx: notes
    {"I103",
     "lengths without a decimal point are read in least input increments (0.001 mm, 0.0001 in), as a standard Fanuc or "
     "Haas reads them: {0} on line {1} is {2}; change it in Job details (--decimal-point)",
     "ความยาวที่ไม่มีจุดทศนิยมอ่านเป็นหน่วยป้อนค่าที่เล็กที่สุด (0.001 มม., 0.0001 นิ้ว) แบบที่เครื่อง Fanuc หรือ Haas ทั่วไปอ่าน: {0} ในบรรทัดที่ "
     "{1} คือ {2} เปลี่ยนได้ที่รายละเอียดงาน (--decimal-point)"},
    {"I104",
     "lengths without a decimal point are read in whole millimetres or inches (calculator-type input), as the "
     "program's numbers show: {0} on line {1} is {2}; change it in Job details (--decimal-point)",
     "ความยาวที่ไม่มีจุดทศนิยมอ่านเป็นมิลลิเมตรหรือนิ้วเต็มหน่วย (การป้อนค่าแบบเครื่องคิดเลข) ตามที่ตัวเลขในโปรแกรมบอก: {0} ในบรรทัดที่ {1} คือ "
     "{2} เปลี่ยนได้ที่รายละเอียดงาน (--decimal-point)"},
    {"I107",
     "the program names no units (no G20 or G21) and its sizes are in {0} ({1} and its other cycle depths, feeds "
     "and speeds are {0} values): it is read in {0}; choose the units in Tool setting (--units) if that is wrong",
     "โปรแกรมไม่ได้ระบุหน่วย (ไม่มี G20 หรือ G21) และขนาดต่าง ๆ เป็นหน่วย {0} ({1} รวมทั้งระยะป้อนลึก "
     "อัตราป้อน และความเร็วอื่น ๆ เป็นค่าในหน่วย {0}) จึงอ่านเป็น {0}: ถ้าไม่ถูกต้องให้เลือกหน่วยที่ ตั้งค่ามีดตัด (--units)"},
    {"I106",
     "{0} is an angle without its comma, as a Fanuc 0-T reads it (parameter 3405#4): write {1}, or set "
     "angle_without_comma = 1 in the machine file",
     "{0} เป็นมุมที่ไม่มีเครื่องหมายจุลภาค แบบที่ Fanuc 0-T อ่าน (พารามิเตอร์ 3405#4): ให้เขียน {1} หรือตั้งค่า "
     "angle_without_comma = 1 ในไฟล์เครื่อง"},
    {"I163",
     "lines {0}-{1} stand after the closing '%': a control stops reading the file there (the tape's end), so they "
     "are not checked or run",
     "บรรทัดที่ {0}-{1} อยู่หลังเครื่องหมาย '%' ปิดท้าย: เครื่องหยุดอ่านไฟล์ที่นั่น (จบเทป) จึงไม่ตรวจและไม่ทำงาน"},
    {"I105",
     "lines 1-{0} stand before the first '%': a control reading the file skips this leader (a title, a label), so it "
     "is not checked or run",
     "บรรทัดที่ 1-{0} อยู่ก่อนเครื่องหมาย '%' ตัวแรก: เครื่องที่อ่านไฟล์จะข้ามส่วนนำนี้ (ชื่อเรื่อง ป้ายชื่อ) จึงไม่ตรวจและไม่ทำงาน"},
    {"I102", "blocks with errors or warnings that are {1} forms: {0}; choose the {1} dialect (--dialect {2})",
     "บล็อกที่ผิดพลาดหรือมีคำเตือน {0} บล็อกเป็นรูปแบบของ {1}: เลือกรูปแบบคำสั่ง {1} (--dialect {2})"},
};
}  // namespace

std::span<const MessageText> gcodeMessages() { return kGcodeMessages; }

}  // namespace klueng::core::catalog
