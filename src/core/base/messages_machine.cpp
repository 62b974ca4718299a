// Catalog part for the machine module: code, English, Thai. Keep codes sorted.
// Run-time alarms of the interpreter (SPEC 8). Numbers in args are already
// formatted (mm, rpm, degrees) by the interpreter.
#include "catalog_parts.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kMessages[] = {
    {"A101", "spindle speed S{0} rpm is above the machine maximum of {1} rpm",
     "ความเร็วรอบ S{0} รอบ/นาที สูงกว่าความเร็วรอบสูงสุดของเครื่อง {1} รอบ/นาที"},
    {"A102", "{0} needs a feed rate, but no F has been given",
     "{0} ต้องมีอัตราป้อนตัด แต่ยังไม่ได้กำหนด F"},
    {"A103", "{0} under feed per revolution (G99), but no spindle speed S has been given",
     "{0} ใช้อัตราป้อนแบบ มม./รอบ (G99) แต่ยังไม่ได้กำหนดความเร็วรอบ S"},
    {"A104", "{0} under feed per revolution (G99) while the spindle is stopped",
     "{0} ใช้อัตราป้อนแบบ มม./รอบ (G99) ขณะที่เพลาจับงานหยุดหมุน"},
    {"A105", "{0} reverses the spindle without M05 first",
     "{0} กลับทิศทางการหมุนของเพลาจับงานโดยไม่ได้สั่ง M05 ให้หยุดหมุนก่อน"},
    {"A106", "{0} starts the spindle while the brake is on (release it with M87 first)",
     "{0} สั่งให้เพลาจับงานหมุนขณะที่เบรกทำงานอยู่ (ต้องปลดเบรกด้วย M87 ก่อน)"},
    {"A107", "M86 applies the brake while the spindle is turning (stop it with M05 first)",
     "M86 สั่งเบรกขณะที่เพลาจับงานกำลังหมุน (ต้องสั่ง M05 ให้หยุดหมุนก่อน)"},
    {"A108", "thread cutting (G32) under constant surface speed (G96); use constant rpm (G97)",
     "การกลึงเกลียว (G32) ขณะใช้ความเร็วผิวคงที่ (G96) ต้องใช้ความเร็วรอบคงที่ (G97)"},
    {"A109", "{0} rotates the C axis outside C-axis mode (enter it with M41 first)",
     "{0} สั่งหมุนแกน C ขณะไม่ได้อยู่ในโหมดควบคุมการเคลื่อนที่ของแกน C (ต้องสั่ง M41 ก่อน)"},
    {"A110", "M41 enters C-axis mode without the brake on (apply it with M86 first)",
     "M41 เข้าสู่โหมดควบคุมการเคลื่อนที่ของแกน C โดยที่เบรกยังไม่ทำงาน (ต้องสั่ง M86 ก่อน)"},
    {"A111", "M87 releases the brake in C-axis mode (leave it with M91 first)",
     "M87 ปลดเบรกขณะอยู่ในโหมดควบคุมการเคลื่อนที่ของแกน C (ต้องสั่ง M91 ออกจากโหมดก่อน)"},
    {"A112", "the move goes beyond the travel limit: {0} {1} is outside {2} .. {3}",
     "การเคลื่อนที่เกินระยะเคลื่อนที่ของเครื่อง: {0} {1} อยู่นอกช่วง {2} .. {3}"},
    {"A113", "impossible arc: start and end are not on one circle (radius {0} at the start, {1} at the end)",
     "ส่วนโค้งเป็นไปไม่ได้: จุดเริ่มต้นและจุดปลายไม่อยู่บนวงกลมเดียวกัน (รัศมีที่จุดเริ่มต้น {0} ที่จุดปลาย {1})"},
    {"A114", "impossible arc: radius R{0} is smaller than half the distance {1} from start to end",
     "ส่วนโค้งเป็นไปไม่ได้: รัศมี R{0} น้อยกว่าครึ่งหนึ่งของระยะ {1} จากจุดเริ่มต้นถึงจุดปลาย"},
    {"A115", "G27 reference-point return check failed: {0} {1} is not the reference point {0} {2}",
     "การตรวจสอบการกลับสู่จุดอ้างอิง (G27) ไม่ผ่าน: {0} {1} ไม่ใช่จุดอ้างอิง {0} {2}"},
    {"A116", "thread cutting (G32) while the spindle is stopped",
     "การกลึงเกลียว (G32) ขณะที่เพลาจับงานหยุดหมุน"},
    {"A117", "{0} is not supported by the simulator yet; the run stops here",
     "โปรแกรมจำลองยังไม่รองรับ {0} จึงหยุดการทำงานที่บล็อกนี้"},
    {"A118", "{0} selects offset {1}, which does not exist (offsets 00 to 64)",
     "{0} เลือกค่าออฟเซตหมายเลข {1} ซึ่งไม่มีอยู่ (มีหมายเลข 00 ถึง 64)"},
    {"A119", "thread cutting (G32) with no spindle speed S given",
     "การกลึงเกลียว (G32) โดยยังไม่ได้กำหนดความเร็วรอบ S"},
    {"A120", "{0}: no block N{2} for {1}{2} (the profile runs from block N of P down to block N of Q)",
     "{0}: ไม่พบบล็อก N{2} ตามที่ระบุใน {1}{2} (รูปร่างชิ้นงานเริ่มที่บล็อก N ตาม P และจบที่บล็อก N ตาม Q ซึ่งอยู่ถัดลงไป)"},
    {"A121", "{0}: the profile is not monotonic in X and Z at line {1} (type I profiles only)",
     "{0}: รูปร่างชิ้นงานไม่เปลี่ยนแปลงไปทางเดียวในแกน X และ Z ที่บรรทัด {1} (รองรับเฉพาะรูปร่างแบบที่ 1)"},
    {"A122", "{0} needs {1} greater than zero (its depth of cut or number of passes)",
     "{0} ต้องกำหนดค่า {1} ให้มากกว่าศูนย์ (ระยะป้อนลึกหรือจำนวนเที่ยวของวัฏจักร)"},
    {"A123", "{0} cannot run under nose radius compensation (G41/G42); cancel it with G40 first",
     "{0} ใช้ร่วมกับการชดเชยรัศมีจมูกมีด (G41/G42) ไม่ได้ ต้องยกเลิกด้วย G40 ก่อน"},
    {"A124", "{0}: the first profile block must move along {1} only (type I profile)",
     "{0}: บล็อกแรกของรูปร่างชิ้นงานต้องเคลื่อนที่ตามแกน {1} เท่านั้น (รูปร่างแบบที่ 1)"},
    {"A125", "{0}: the profile N{1} to N{2} has no moves to follow",
     "{0}: รูปร่างชิ้นงานตั้งแต่ N{1} ถึง N{2} ไม่มีการเคลื่อนที่ให้ตาม"},
    {"A126", "{0} needs both P and Q: the sequence numbers of the first and last profile blocks",
     "{0} ต้องกำหนดทั้ง P และ Q: หมายเลขลำดับ (N) ของบล็อกแรกและบล็อกสุดท้ายของรูปร่างชิ้นงาน"},
    {"A127", "{0} would make {1} passes (depth of cut {2}); more than 10000 passes is refused",
     "{0} จะต้องกลึง {1} เที่ยว (ระยะป้อนลึก {2}) ซึ่งเกิน 10000 เที่ยว จึงไม่ทำงาน"},
};
}  // namespace

std::span<const MessageText> machineMessages() { return kMessages; }

}  // namespace klueng::core::catalog
