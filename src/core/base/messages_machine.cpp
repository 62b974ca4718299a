// Catalog part for the machine module: code, English, Thai. Keep codes sorted.
// Run-time alarms of the interpreter (SPEC 8). Numbers in args are already
// formatted (mm, rpm, degrees) by the interpreter.
#include "catalog_parts.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kMachineMessages[] = {
    {codes::kSpindleAboveMaximum, "spindle speed S{0} rpm is above the machine maximum of {1} rpm",
     "ความเร็วรอบ S{0} รอบ/นาที สูงกว่าความเร็วรอบสูงสุดของเครื่อง {1} รอบ/นาที"},
    {codes::kNoFeed, "{0} needs a feed rate, but no F has been given", "{0} ต้องมีอัตราป้อนตัด แต่ยังไม่ได้กำหนด F"},
    {codes::kFeedPerRevWithoutSpeed, "{0} under feed per revolution (G99), but no spindle speed S has been given",
     "{0} ใช้อัตราป้อนแบบ มม./รอบ (G99) แต่ยังไม่ได้กำหนดความเร็วรอบ S"},
    {codes::kFeedPerRevSpindleStopped, "{0} under feed per revolution (G99) while the spindle is stopped",
     "{0} ใช้อัตราป้อนแบบ มม./รอบ (G99) ขณะที่เพลาจับงานหยุดหมุน"},
    {codes::kSpindleReversedWithoutStop, "{0} reverses the spindle without M05 first",
     "{0} กลับทิศทางการหมุนของเพลาจับงานโดยไม่ได้สั่ง M05 ให้หยุดหมุนก่อน"},
    {codes::kSpindleStartedWithBrakeOn, "{0} starts the spindle while the brake is on (release it with M87 first)",
     "{0} สั่งให้เพลาจับงานหมุนขณะที่เบรกทำงานอยู่ (ต้องปลดเบรกด้วย M87 ก่อน)"},
    {codes::kBrakeWhileTurning, "M86 applies the brake while the spindle is turning (stop it with M05 first)",
     "M86 สั่งเบรกขณะที่เพลาจับงานกำลังหมุน (ต้องสั่ง M05 ให้หยุดหมุนก่อน)"},
    {codes::kThreadUnderConstantSurface,
     "thread cutting (G32) under constant surface speed (G96); use constant rpm (G97)",
     "การกลึงเกลียว (G32) ขณะใช้ความเร็วผิวคงที่ (G96) ต้องใช้ความเร็วรอบคงที่ (G97)"},
    {codes::kCAxisOutsideCAxisMode, "{0} rotates the C axis outside C-axis mode (enter it with M41 first)",
     "{0} สั่งหมุนแกน C ขณะไม่ได้อยู่ในโหมดควบคุมการเคลื่อนที่ของแกน C (ต้องสั่ง M41 ก่อน)"},
    {codes::kCAxisModeWithoutBrake, "M41 enters C-axis mode without the brake on (apply it with M86 first)",
     "M41 เข้าสู่โหมดควบคุมการเคลื่อนที่ของแกน C โดยที่เบรกยังไม่ทำงาน (ต้องสั่ง M86 ก่อน)"},
    {codes::kBrakeReleasedInCAxisMode, "M87 releases the brake in C-axis mode (leave it with M91 first)",
     "M87 ปลดเบรกขณะอยู่ในโหมดควบคุมการเคลื่อนที่ของแกน C (ต้องสั่ง M91 ออกจากโหมดก่อน)"},
    {codes::kBeyondTravelLimit, "the move goes beyond the travel limit: {0} {1} is outside {2} .. {3}",
     "การเคลื่อนที่เกินระยะเคลื่อนที่ของเครื่อง: {0} {1} อยู่นอกช่วง {2} .. {3}"},
    {codes::kArcEndsNotOnOneCircle,
     "impossible arc: start and end are not on one circle (radius {0} at the start, {1} at the end)",
     "ส่วนโค้งเป็นไปไม่ได้: จุดเริ่มต้นและจุดปลายไม่อยู่บนวงกลมเดียวกัน (รัศมีที่จุดเริ่มต้น {0} ที่จุดปลาย {1})"},
    {codes::kArcRadiusTooSmall, "impossible arc: radius R{0} is smaller than half the distance {1} from start to end",
     "ส่วนโค้งเป็นไปไม่ได้: รัศมี R{0} น้อยกว่าครึ่งหนึ่งของระยะ {1} จากจุดเริ่มต้นถึงจุดปลาย"},
    {codes::kReferenceCheckFailed,
     "G27 reference-point return check failed: {0} {1} is not the reference point {0} {2}",
     "การตรวจสอบการกลับสู่จุดอ้างอิง (G27) ไม่ผ่าน: {0} {1} ไม่ใช่จุดอ้างอิง {0} {2}"},
    {codes::kThreadSpindleStopped, "thread cutting (G32) while the spindle is stopped",
     "การกลึงเกลียว (G32) ขณะที่เพลาจับงานหยุดหมุน"},
    {codes::kNotSupportedYet, "{0} is not supported by the simulator yet; the run stops here",
     "โปรแกรมจำลองยังไม่รองรับ {0} จึงหยุดการทำงานที่บล็อกนี้"},
    {codes::kNoSuchOffset, "{0} selects offset {1}, which does not exist (offsets 00 to {2})",
     "{0} เลือกค่าออฟเซตหมายเลข {1} ซึ่งไม่มีอยู่ (มีหมายเลข 00 ถึง {2})"},
    {codes::kThreadWithoutSpeed, "thread cutting (G32) with no spindle speed S given",
     "การกลึงเกลียว (G32) โดยยังไม่ได้กำหนดความเร็วรอบ S"},
    {codes::kNoProfileBlock, "{0}: no block N{2} for {1}{2} (the profile runs from block N of P down to block N of Q)",
     "{0}: ไม่พบบล็อก N{2} ตามที่ระบุใน {1}{2} (รูปร่างชิ้นงานเริ่มที่บล็อก N ตาม P และจบที่บล็อก N ตาม Q ซึ่งอยู่ถัดลงไป)"},
    {codes::kProfileNotMonotonic,
     "{0}: the profile turns back at line {1}: a type I profile (X only in its first block) must go one way in X and "
     "Z, a type II profile (X and Z in its first block) one way along the passes",
     "{0}: รูปร่างชิ้นงานย้อนกลับที่บรรทัด {1}: รูปร่างแบบที่ 1 (บล็อกแรกมีแต่ X) ต้องไปทางเดียวทั้งแกน X และ Z ส่วนรูปร่างแบบที่ 2 (บล็อกแรกมีทั้ง "
     "X และ Z) ต้องไปทางเดียวตามแนวการกลึง"},
    {codes::kCycleNeedsPositive, "{0} needs {1} greater than zero (its depth of cut or number of passes)",
     "{0} ต้องกำหนดค่า {1} ให้มากกว่าศูนย์ (ระยะป้อนลึกหรือจำนวนเที่ยวของวัฏจักร)"},
    {codes::kCycleUnderNoseComp, "{0} cannot run under nose radius compensation (G41/G42); cancel it with G40 first",
     "{0} ใช้ร่วมกับการชดเชยรัศมีจมูกมีด (G41/G42) ไม่ได้ ต้องยกเลิกด้วย G40 ก่อน"},
    {codes::kProfileFirstBlockAxis, "{0}: the first profile block must move along {1} only (type I profile)",
     "{0}: บล็อกแรกของรูปร่างชิ้นงานต้องเคลื่อนที่ตามแกน {1} เท่านั้น (รูปร่างแบบที่ 1)"},
    {codes::kProfileHasNoMoves, "{0}: the profile N{1} to N{2} has no moves to follow",
     "{0}: รูปร่างชิ้นงานตั้งแต่ N{1} ถึง N{2} ไม่มีการเคลื่อนที่ให้ตาม"},
    {codes::kCycleNeedsPAndQ, "{0} needs both P and Q: the sequence numbers of the first and last profile blocks",
     "{0} ต้องกำหนดทั้ง P และ Q: หมายเลขลำดับ (N) ของบล็อกแรกและบล็อกสุดท้ายของรูปร่างชิ้นงาน"},
    {codes::kTooManyPasses, "{0} would make {1} passes (depth of cut {2}); more than 10000 passes is refused",
     "{0} จะต้องกลึง {1} เที่ยว (ระยะป้อนลึก {2}) ซึ่งเกิน 10000 เที่ยว จึงไม่ทำงาน"},
    {codes::kNoSuchStation, "{0} selects tool station {1}, which the turret does not have (stations 01 to {2})",
     "{0} เลือกสถานีมีดหมายเลข {1} ซึ่งป้อมมีดไม่มี (มีสถานี 01 ถึง {2})"},
    {codes::kProgramAlarm, "program alarm {2} (#3000 = {0}): {1}",
     "สัญญาณเตือนจากโปรแกรม หมายเลข {2} (#3000 = {0}): {1}"},
    {codes::kDivisionByZero, "division by zero: {0} {1} 0", "หารด้วยศูนย์: {0} {1} 0"},
    // A limit, not a proof that the loop never ends (issue 42 item 6): say which limit and how to raise it;
    // "without end" only where the run came back to a state it was in before (A155).
    {codes::kBlockLimitReached,
     "{0}: stopped at the block limit, machine.cfg max_blocks = {2} ({1} blocks run again by loops, jumps and "
     "calls); if the program is meant to run longer, raise max_blocks in machine.cfg",
     "{0}: หยุดที่ขีดจำกัดจำนวนบล็อก max_blocks = {2} ใน machine.cfg (ทำบล็อกซ้ำไปแล้ว {1} บล็อกจากการวนซ้ำ "
     "การกระโดด และการเรียกโปรแกรมย่อย) ถ้าโปรแกรมนี้ต้องทำงานนานกว่านี้ ให้เพิ่มค่า max_blocks ใน machine.cfg"},
    {codes::kTimeLimitReached,
     "{0}: stopped at the time limit, machine.cfg max_run_time = {2} s ({1} s of machining while blocks run "
     "again); if the program is meant to run longer, raise max_run_time in machine.cfg",
     "{0}: หยุดที่ขีดจำกัดเวลา max_run_time = {2} วินาที ใน machine.cfg (ตัดงานไปแล้ว {1} วินาทีขณะที่ทำบล็อกซ้ำ) "
     "ถ้าโปรแกรมนี้ต้องทำงานนานกว่านี้ ให้เพิ่มค่า max_run_time ใน machine.cfg"},
    {codes::kMoveLimitReached,
     "{0}: stopped at the move limit: blocks run again made {1} moves, and machine.cfg max_blocks = {2} allows {3} "
     "(10 a block); if the program is meant to run longer, raise max_blocks in machine.cfg",
     "{0}: หยุดที่ขีดจำกัดจำนวนการเคลื่อนที่: บล็อกที่ทำซ้ำเคลื่อนที่ไปแล้ว {1} ครั้ง แต่ max_blocks = {2} ใน "
     "machine.cfg ยอมให้ {3} ครั้ง (บล็อกละ 10 ครั้ง) ถ้าโปรแกรมนี้ต้องทำงานนานกว่านี้ ให้เพิ่มค่า max_blocks ใน "
     "machine.cfg"},
    {codes::kEndlessLoop,
     "{0} loops without end: the run came back to line {1} in the same state as on an earlier pass (the same "
     "variables, modes and position), so it would repeat for ever; a control runs it until RESET",
     "{0} วนซ้ำไม่รู้จบ: การทำงานกลับมาที่บรรทัด {1} ในสภาพเดียวกับรอบก่อนหน้าทุกอย่าง (ตัวแปร โหมด และตำแหน่งเดิม) "
     "จึงจะวนซ้ำเช่นนี้ตลอดไป เครื่องจริงจะทำงานต่อไปจนกว่าจะกด RESET"},
    {codes::kNoCAxisOnThisMachine,
     "{0}: this machine has no C axis; a chamfer or a corner round is written with a comma (,C2. ,R3.)",
     "{0}: เครื่องนี้ไม่มีแกน C การลบมุมหรือการมนมุมต้องเขียนโดยมีจุลภาคนำหน้า (,C2. ,R3.)"},
    {codes::kCallsTooDeep, "{0}: subprogram and macro calls nest more than {1} levels deep",
     "{0}: การเรียกโปรแกรมย่อยและมาโครซ้อนกันลึกเกิน {1} ชั้น"},
    {codes::kProfileStartsWithoutMotion,
     "{0}: the first block of the profile, N{1}, holds neither G00 nor G01 (Fanuc alarm PS0065): write the first move "
     "in it (N{1} G00 X.. Z..)",
     "{0}: บล็อกแรกของรูปร่างชิ้นงาน N{1} ไม่มี G00 หรือ G01 (สัญญาณเตือน PS0065 ของ Fanuc) ให้เขียนการเคลื่อนที่แรกไว้ในบล็อกนั้น (N{1} "
     "G00 X.. Z..)"},
    {codes::kCallWithoutProgram,
     "{0} without P: the block names no program to call; write the program's number after P ({0} P1000; Fanuc alarm "
     "PS0076)",
     "{0} ไม่มี P: บล็อกนี้ไม่ได้ระบุโปรแกรมที่จะเรียก ให้เขียนหมายเลขโปรแกรมต่อท้าย P ({0} P1000; สัญญาณเตือน PS0076 ของ "
     "Fanuc)"},
    {codes::kNoSuchProgram, "{0}: no program O{1} in this file or its folder",
     "{0}: ไม่พบโปรแกรม O{1} ในไฟล์นี้หรือในโฟลเดอร์เดียวกัน"},
    {codes::kNoSuchSequence, "{0}: no block N{1} to jump to", "{0}: ไม่มีบล็อก N{1} ให้กระโดดไป"},
    {codes::kNoSuchVariable, "#{0} is not a variable of this control", "#{0} ไม่ใช่ตัวแปรของเครื่องควบคุมนี้"},
    {codes::kOutsideFunctionDomain, "{0}[{1}] has no value (outside the function's domain)",
     "{0}[{1}] หาค่าไม่ได้ (อยู่นอกขอบเขตของฟังก์ชัน)"},
    {codes::kReadOnlyVariable, "{0}: #{1} cannot be written (read-only)", "{0}: เขียนค่าลงใน #{1} ไม่ได้ (อ่านได้อย่างเดียว)"},
    {codes::kVacantValueNeeded, "{0}: the value of {1} is vacant (#0); a code or a jump needs a value",
     "{0}: ค่าของ {1} ว่าง (#0) แต่รหัสคำสั่งหรือการกระโดดต้องมีค่า"},
    {codes::kUnmatchedLoopEnd, "{0} without a matching {1} while running", "{0} ไม่มี {1} ที่คู่กันขณะทำงาน"},
    {codes::kReturnTargetMissing, "{0}: M99 returns to N{1}, which the calling program does not have",
     "{0}: M99 กลับไปที่ N{1} แต่โปรแกรมที่เรียกไม่มีบล็อกนี้"},
    {codes::kValueIsNoCode, "{0}: the value {1} is not a code of this control",
     "{0}: ค่า {1} ไม่ใช่รหัสคำสั่งของเครื่องควบคุมนี้"},
    {codes::kCornerNeedsNextMove, "{0}: a chamfer or corner (,C ,R) needs a move (G01, G02 or G03) in the next block",
     "{0}: การลบมุมหรือมนมุม (,C ,R) ต้องมีบล็อกถัดไปเป็นการเคลื่อนที่ (G01, G02 หรือ G03)"},
    {codes::kCornerLongerThanMove, "{0}: the chamfer or corner is longer than the move it cuts into",
     "{0}: ขนาดลบมุมหรือมนมุมยาวกว่าระยะการเคลื่อนที่"},
    {codes::kAngleUnreachable, "{0}: the angle cannot be reached from here (,A direct drawing)",
     "{0}: ไม่สามารถเคลื่อนที่ตามมุมที่กำหนดจากตำแหน่งนี้ได้ (,A)"},
    {codes::kMacroStop, "#3006 stop: {0}", "#3006 หยุดชั่วคราว: {0}"},
    {codes::kProfileHasMacro,
     "{0}: the profile holds a macro statement at line {1}; a cycle profile holds moves only (a value such as X#1 is "
     "fine)",
     "{0}: รูปร่างชิ้นงานมีคำสั่งมาโครที่บรรทัด {1} รูปร่างของวัฏจักรมีได้เฉพาะคำสั่งเคลื่อนที่ (ใช้ค่าตัวแปร เช่น X#1 ได้)"},
    {codes::kProfileCommandNotAllowed,
     "{0} at line {1} cannot stand in a G70-G73 profile: only G00-G03 moves, F, S, T, G04 and G40-G42",
     "ใช้ {0} ที่บรรทัด {1} ในรูปร่างชิ้นงานของ G70-G73 ไม่ได้ ใช้ได้เฉพาะการเคลื่อนที่ G00-G03, F, S, T, G04 และ G40-G42"},
    {codes::kTooManyCycleMoves,
     "{0} would make {1} moves (more than {2}): check its pecks, steps or passes for a typing slip",
     "{0} จะเคลื่อนที่ {1} ครั้ง (เกิน {2} ครั้ง) ให้ตรวจสอบระยะป้อน ระยะเลื่อน หรือจำนวนเที่ยว ว่าพิมพ์ผิดหรือไม่"},
    {codes::kRunMemoryBudget,
     "the run would need more than {0} MB of memory to keep its moves and block states; it stops at line {1} (a loop "
     "that runs this long, or a program this long, is more than the simulation keeps)",
     "การจำลองต้องใช้หน่วยความจำเกิน {0} MB เพื่อเก็บการเคลื่อนที่และสถานะของทุกบล็อก จึงหยุดที่บรรทัด {1} "
     "(การวนซ้ำที่นานขนาดนี้ หรือโปรแกรมที่ยาวขนาดนี้ เกินกว่าที่การจำลองจะเก็บไว้ได้)"},
    {codes::kMainProgramRepeats,
     "M99 at the end of the main program: the control runs it again from the start; the simulation stops after one "
     "repeat",
     "M99 ท้ายโปรแกรมหลัก: เครื่องจริงจะวนกลับไปทำงานใหม่ตั้งแต่ต้น แต่การจำลองจะหยุดหลังวนซ้ำหนึ่งรอบ"},
    {codes::kVacantAddressOmitted, "{0}: #{1} is vacant, so the control omits the address {2} from this block",
     "{0}: #{1} ว่าง เครื่องควบคุมจึงไม่ใช้ตำแหน่ง {2} ในบล็อกนี้"},
    {codes::kSpindleClampedToMaximum,
     "spindle speed S{0} rpm is above the machine maximum of {1} rpm: the control turns the spindle at {1} rpm; write "
     "S{1} or less",
     "ความเร็วรอบ S{0} รอบ/นาที สูงกว่าค่าสูงสุดของเครื่อง {1} รอบ/นาที เครื่องจะหมุนที่ {1} รอบ/นาที: ให้เขียน S{1} หรือน้อยกว่า"},
    {codes::kSpindleReversed,
     "{0} reverses the spindle while it turns: the control brakes it and turns it the other way; write M05 first",
     "{0} กลับทิศทางหัวจับขณะที่ยังหมุนอยู่ เครื่องจะหยุดแล้วหมุนกลับทิศ: ควรสั่ง M05 ก่อน"},
    {codes::kCycleRunsUncompensated,
     "{0} runs under nose radius compensation (G41/G42): the control offsets the cycle's shape by the nose "
     "radius; Klueng runs the cycle's own passes on the programmed shape, the tool's imaginary tip on it, and "
     "compensates again after the cycle, so a roughing pass may differ by up to the nose radius (the finishing "
     "allowance covers it; G70's pass is compensated)",
     "{0} ทำงานขณะชดเชยรัศมีปลายมีด (G41/G42): เครื่องจริงจะเลื่อนรูปร่างของไซเคิลออกไปเท่ารัศมีปลายมีด "
     "แต่ Klueng เดินมีดของไซเคิลตามรูปร่างที่เขียนไว้ โดยใช้ปลายมีดสมมติ แล้วจึงชดเชยต่อหลังจบไซเคิล "
     "ดังนั้นรอบกลึงหยาบอาจต่างจากเครื่องจริงได้ไม่เกินรัศมีปลายมีด (ค่าเผื่อกลึงละเอียดครอบคลุมส่วนนี้ และรอบ G70 ได้รับการชดเชยตามปกติ)"},
    {codes::kThreadUnderCssWarning,
     "threading under constant surface speed (G96): the rpm is set by the diameter of each pass; write G97 before "
     "threading",
     "กลึงเกลียวขณะใช้ความเร็วผิวคงที่ (G96): ความเร็วรอบขึ้นกับขนาดโตของแต่ละรอบกลึง ควรสั่ง G97 ก่อนกลึงเกลียว"},
};
}  // namespace

std::span<const MessageText> machineMessages() { return kMachineMessages; }

}  // namespace klueng::core::catalog
