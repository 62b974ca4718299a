// Catalog part for the printed sheets' own words (render/: the program sheet,
// the drawing sheet, the class grades; issue 30 item 5): headings, notes,
// dates and durations, in English and Thai (SPEC 12, GLOSSARY.md). The GUI's
// Export PDF and klueng-cli print/class draw the same sheets, so their words
// live here once rather than in tr() (the CLI loads no Qt translator).
#include "catalog_parts.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kRenderMessages[] = {
    // The title blocks of the program and drawing sheets (SPEC 12).
    {codes::kReportProgramTitle, "CNC Program Sheet", "ชุดรหัสสั่งการทำงาน"},
    {codes::kReportPage, "Page {0}", "หน้าที่ {0}"},
    {codes::kReportProject, "Project", "ชื่องาน"},
    {codes::kReportMaterial, "Material", "วัสดุ"},
    {codes::kReportPart, "Part", "ชิ้นงาน"},
    {codes::kReportDiameter, "Diameter (mm.)", "เส้นผ่าศก. (มม.)"},
    {codes::kReportProgrammer, "Programmer", "ผู้เขียน"},
    {codes::kReportLength, "Length (mm.)", "ความยาว (มม.)"},
    {codes::kReportDrawingTitle, "Part Drawing", "เอกสารแสดงภาพชิ้นงาน"},
    {codes::kReportDate, "Date", "วันที่"},
    {codes::kReportFileName, "Program", "ไฟล์โปรแกรม"},
    {codes::kReportVersion, "Version", "รุ่นโปรแกรม"},
    {codes::kReportScale, "Scale", "มาตราส่วน"},
    {codes::kReportUntitled, "Untitled", "ไม่มีชื่อ"},
    {codes::kReportCycleTime, "Cycle time", "เวลาทำงาน"},
    {codes::kReportToAlarm, "up to the alarm", "ถึงจุดที่เกิดสัญญาณเตือน"},
    // Dates and durations: the caller gives the numbers (a Thai year in the Buddhist era).
    {codes::kReportDateLong, "{1} {0}, {2}", "{0} {1} พ.ศ. {2}"},
    {codes::kReportDateShort, "{1} {0}, {2}", "{0} {1} {2}"},
    {codes::kReportMinutes, "{0} min {1} s", "{0} นาที {1} วินาที"},
    {codes::kReportSeconds, "{0} s", "{0} วินาที"},
    // Why the drawing shows less than the finished part.
    {codes::kReportBadStock, "The stock size is not valid.", "ขนาดชิ้นงานไม่ถูกต้อง"},
    {codes::kReportProgramErrors, "The program has errors: the drawing shows the uncut bar.",
     "โปรแกรมมีข้อผิดพลาด: ภาพนี้แสดงชิ้นงานก่อนกลึง"},
    {codes::kReportStoppedOnAlarm, "The program stopped on an alarm: the drawing shows the part up to it.",
     "โปรแกรมหยุดด้วยสัญญาณเตือน: ภาพนี้แสดงชิ้นงานจนถึงจุดที่หยุด"},
    // The drawing's labels.
    {codes::kReportInside, "{0} (inside)", "{0} (ใน)"},
    {codes::kReportNoseCorners, "Inside corners: tool nose R{0}", "มุมด้านในเป็นรัศมีจมูกมีด R{0}"},
    // The roughness each finished surface got from its last cut (issue 39): theoretical, Ra = f²/(32·r).
    {codes::kReportFinishTitle, "Roughness the cuts leave (theoretical, Ra = f²/32r)",
     "ความหยาบผิวที่ได้จากการตัด (ตามทฤษฎี Ra = f²/32r)"},
    {codes::kReportFinishRow, "{0}: Ra {1} µm (Rz {2}), line {3}, f {4}, R{5}",
     "{0}: Ra {1} ไมครอน (Rz {2}) บรรทัด {3} ป้อน {4} R{5}"},
    {codes::kReportFinishMore, "… and {0} more surfaces", "… และอีก {0} ผิว"},
    // The class grades (the totals line is the CLI's kCliClassTotals: one text for both).
    {codes::kReportClassTitle, "Class grades", "ผลการตรวจงานทั้งชั้นเรียน"},
    {codes::kReportAgainstReference, "Against {0} · tolerance {1} mm on the diameter · {2}",
     "เทียบกับ {0} · พิกัดความเผื่อ {1} มม. บนเส้นผ่าศูนย์กลาง · {2}"},
    {codes::kReportAlsoDrawing, "and against the drawing {0} ({1} toleranced dimensions)",
     "และเทียบกับแบบงาน {0} ({1} ขนาดที่มีพิกัดความเผื่อ)"},
    {codes::kReportAgainstDrawing, "Against the drawing {0} ({1} toleranced dimensions) · {2}",
     "เทียบกับแบบงาน {0} ({1} ขนาดที่มีพิกัดความเผื่อ) · {2}"},
    {codes::kReportColumnProgram, "Program", "โปรแกรม"},
    {codes::kReportColumnResult, "Result", "ผล"},
    {codes::kReportColumnErrors, "Errors", "ข้อผิดพลาด"},
    {codes::kReportColumnAlarm, "Alarm", "สัญญาณเตือน"},
    {codes::kReportColumnSeconds, "Cycle time (s)", "เวลา (วินาที)"},
    {codes::kReportColumnLeftover, "Leftover (mm)", "เนื้อเหลือ (มม.)"},
    {codes::kReportColumnGouge, "Gouge (mm)", "กินเนื้อเกิน (มม.)"},
    {codes::kReportColumnInTolerance, "In tolerance", "ขนาดในพิกัด"},
    {codes::kReportColumnCutting, "Cutting data", "ข้อมูลการตัด"},
    {codes::kReportPass, "pass", "ผ่าน"},
    {codes::kReportFail, "fail", "ไม่ผ่าน"},
    {codes::kReportInspectionTitle, "Inspection against {0}", "ตรวจวัดเทียบกับแบบงาน {0}"},
    {codes::kReportInspectionRule,
     "Measured to 0.001 mm; a value exactly at a limit is in; a dimension not on the part is out.",
     "วัดละเอียด 0.001 มม. ค่าที่เท่ากับขอบเขตพอดีถือว่าอยู่ในพิกัด ขนาดที่ไม่มีบนชิ้นงานถือว่าไม่ผ่าน"},
    {codes::kReportColumnDimension, "Dimension", "ขนาด"},
    {codes::kReportColumnTolerance, "Tolerance", "พิกัดความเผื่อ"},
    {codes::kReportColumnLimits, "Limits (mm)", "ขอบเขต (มม.)"},
    {codes::kReportColumnMeasured, "Measured (mm)", "วัดได้ (มม.)"},
    {codes::kReportInCount, "{0} of {1} in", "อยู่ในพิกัด {0} จาก {1}"},
    // Why the picture module made no PDF.
    {codes::kReportNothingToWrite, "nothing to write to", "ไม่มีที่ให้เขียนผลลัพธ์"},
    {codes::kReportNoSheet, "no sheet asked for", "ไม่ได้เลือกเอกสารที่จะพิมพ์"},
    {codes::kReportPdfNotStarted, "the PDF could not be started", "เริ่มสร้างไฟล์ PDF ไม่ได้"},
    {codes::kReportPdfNotFinished, "the PDF could not be finished", "สร้างไฟล์ PDF ไม่เสร็จ"},
    {codes::kReportPdfEmpty, "the PDF is empty", "ไฟล์ PDF ที่ได้ว่างเปล่า"},
};
}  // namespace

std::span<const MessageText> renderMessages() { return kRenderMessages; }

}  // namespace klueng::core::catalog
