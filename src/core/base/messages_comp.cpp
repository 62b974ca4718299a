// Catalog part for the comp module: code, English, Thai. Keep codes sorted.
#include "catalog_parts.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kCompMessages[] = {
    {codes::kConcaveArcTooSmall,
     "Nose radius compensation interference: the concave arc's radius {0} mm is smaller than the tool nose "
     "radius {1} mm, so the nose cannot follow it",
     "การชดเชยรัศมีจมูกมีดขัดกัน: รัศมีส่วนโค้งเว้า {0} มม. เล็กกว่ารัศมีจมูกมีด {1} มม. "
     "จมูกมีดจึงเคลื่อนที่ตามส่วนโค้งนี้ไม่ได้"},
    {codes::kNoseDoesNotFit,
     "Nose radius compensation interference: the tool nose (radius {0} mm) does not fit here; its offset path "
     "would run against the programmed direction and cut into the part",
     "การชดเชยรัศมีจมูกมีดขัดกัน: จมูกมีด (รัศมี {0} มม.) เข้าไม่ได้ในช่วงนี้ "
     "เส้นทางที่ชดเชยแล้วจะเคลื่อนที่ย้อนทิศทางที่โปรแกรมไว้และตัดเกินชิ้นงาน"},
    {codes::kGuessedNoseTooBig,
     "T{0}'s nose radius R{1} mm is a guess, not your shop's: with it the compensated path does not fit at line {2} "
     "(the real control would stop there, alarm {4}); the run uses R{3} mm, the largest common insert radius that "
     "fits: set the real insert's radius in the offsets",
     "รัศมีจมูกมีดของ T{0} คือ R{1} มม. เป็นค่าที่เดาไว้ ไม่ใช่ของโรงงานจริง: ด้วยค่านี้เส้นทางที่ชดเชยแล้วเข้าไม่ได้ที่บรรทัดที่ {2} "
     "(เครื่องจริงจะหยุดที่นั่นด้วยสัญญาณเตือน {4}) การจำลองจึงใช้ R{3} มม. ซึ่งเป็นรัศมีเม็ดมีดมาตรฐานที่ใหญ่ที่สุดที่เข้าได้: "
     "ให้ตั้งรัศมีของเม็ดมีดจริงในตารางออฟเซต"},
    {codes::kCompStartOrCancelOnArc,
     "Nose radius compensation cannot start (G41/G42) or be cancelled (G40) on an arc; use a G00 or G01 move",
     "ไม่สามารถเริ่ม (G41/G42) หรือยกเลิก (G40) การชดเชยรัศมีจมูกมีดบนการเคลื่อนที่เป็นส่วนโค้งได้ "
     "ให้ใช้การเคลื่อนที่ G00 หรือ G01"},
};
}  // namespace

std::span<const MessageText> compMessages() { return kCompMessages; }

}  // namespace klueng::core::catalog
