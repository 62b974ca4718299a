// Catalog part for klueng-cli's own texts (issue 29 item 10): the usage of each
// command and what it says about its command line, in English and Thai, so
// that `--lang th` (or a Thai locale) speaks Thai from the first line. The
// option names and values stay as typed; only the words around them change.
#include "catalog_parts.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kCliMessages[] = {
    // Usage texts (printed whole, they end with a newline).
    {codes::kCliUsage,
     "usage: klueng-cli check FILE... [--lang en|th] [--dialect fanuc|haas|classic] [--json]\n"
     "                               [--stock DxL[xBORE][in]] [--units mm|inch] [--tool N=ID]...\n"
     "       klueng-cli simulate FILE [--trace out.csv] [--cycle-time] [--config DIR]\n"
     "                               [--lang en|th] [--dialect fanuc|haas|classic]\n"
     "                               [--stock DxL[xBORE][in]] [--units mm|inch] [--tool N=ID]...\n"
     "       klueng-cli class DIR --reference REF.nc [--tolerance 0.05] [--csv OUT.csv]\n"
     "                               [--dialect fanuc|haas|classic] [--config DIR]\n"
     "       klueng-cli print FILE --pdf OUT.pdf [--sheet program|drawing|both] [--lang en|th]\n"
     "                               [--dialect ...] [--stock ...] [--units ...] [--config DIR]\n"
     "       klueng-cli generate PART.json|PART.dxf -o OUT.nc [--dialect ...] [--material M]\n"
     "                               [--tool-material hss|carbide] [--layer NAME] [--stock DxL[xBORE][in]]\n"
     "       klueng-cli --version\n"
     "  --dialect  fanuc (Fanuc 0i-TF, default), haas (Haas ST lathe), classic (1999 rules)\n"
     "  --machine ID|FILE  a machine file (resources/machines, DIR/machines, your data folder), e.g.\n"
     "           romi-gl240m (Fanuc in G-code system B); wins over --dialect (check, simulate, print, class)\n"
     "  --stock  50x100 (mm), 2.1x4in, 118x80x90 (tube: bore 90); without it the file's\n"
     "           header, else the stock inferred from the program (a note says which)\n"
     "  --units  power-on units before any G20/G21: mm or inch\n"
     "  --decimal-point whole|increments  (check, simulate, print) a length without a decimal point:\n"
     "           X30 = 30 mm, or 0.030 mm as a standard Fanuc/Haas; default: the program's numbers\n"
     "  --tool N=ID   library tool ID at turret station N for this run (e.g. --tool 12=parting-3mm);\n"
     "                see resources/tools/library/library.cfg and docs/tools.md for the IDs\n",
     "วิธีใช้: klueng-cli check FILE... [--lang en|th] [--dialect fanuc|haas|classic] [--json]\n"
     "                               [--stock DxL[xBORE][in]] [--units mm|inch] [--tool N=ID]...\n"
     "       klueng-cli simulate FILE [--trace out.csv] [--cycle-time] [--config DIR]\n"
     "                               [--lang en|th] [--dialect fanuc|haas|classic]\n"
     "                               [--stock DxL[xBORE][in]] [--units mm|inch] [--tool N=ID]...\n"
     "       klueng-cli class DIR --reference REF.nc [--tolerance 0.05] [--csv OUT.csv]\n"
     "                               [--dialect fanuc|haas|classic] [--config DIR]\n"
     "       klueng-cli print FILE --pdf OUT.pdf [--sheet program|drawing|both] [--lang en|th]\n"
     "                               [--dialect ...] [--stock ...] [--units ...] [--config DIR]\n"
     "       klueng-cli generate PART.json|PART.dxf -o OUT.nc [--dialect ...] [--material M]\n"
     "                               [--tool-material hss|carbide] [--layer NAME] [--stock DxL[xBORE][in]]\n"
     "       klueng-cli --version\n"
     "  --dialect  fanuc (Fanuc 0i-TF ค่าเริ่มต้น), haas (เครื่องกลึง Haas ST), classic (กฎปี 1999)\n"
     "  --machine ID|FILE  ไฟล์เครื่อง (resources/machines, DIR/machines, โฟลเดอร์ข้อมูลของผู้ใช้) เช่น\n"
     "           romi-gl240m (Fanuc ระบบรหัส G แบบ B) ใช้แทน --dialect (check, simulate, print, class)\n"
     "  --stock  50x100 (มม.), 2.1x4in, 118x80x90 (ท่อ: รูใน 90) ถ้าไม่ระบุ ใช้ส่วนหัวของไฟล์\n"
     "           หรือขนาดชิ้นงานที่อนุมานจากโปรแกรม (มีหมายเหตุบอกว่ามาจากที่ใด)\n"
     "  --units  หน่วยเมื่อเปิดเครื่อง ก่อน G20/G21 ใด ๆ: mm หรือ inch\n"
     "  --decimal-point whole|increments  (check, simulate, print) ความยาวที่ไม่มีจุดทศนิยม:\n"
     "           X30 = 30 มม. หรือ 0.030 มม. แบบ Fanuc/Haas มาตรฐาน ค่าเริ่มต้น: ตามตัวเลขในโปรแกรม\n"
     "  --tool N=ID   ใช้มีดตัด ID จากคลังมีดตัดที่ป้อมมีดสถานี N สำหรับการรันนี้ (เช่น --tool 12=parting-3mm)\n"
     "                ดู ID ได้ที่ resources/tools/library/library.cfg และ docs/tools.md\n"},
    {codes::kCliCheckUsage,
     "usage: klueng-cli check FILE|FOLDER... [--lang en|th] [--dialect fanuc|haas|classic] [--json]\n"
     "                                       [--config DIR] [--summary]\n"
     "                                       [--stock DxL[xBORE][in]] [--units mm|inch] [--tool N=ID]...\n"
     "                                       [--design PART.json|PART.dxf]\n"
     "  --dialect     machine profile: fanuc (Fanuc 0i-TF, default), haas (Haas ST lathe), classic (1999 rules)\n"
     "  --stock       stock for every FILE, before its header: 50x100 (mm), 2.1x4in, 118x80x90 (tube, bore 90)\n"
     "  --units       power-on units before any G20/G21: mm or inch\n"
     "  --decimal-point whole|increments  a length without a decimal point: X30 = 30 mm (whole) or 0.030 mm\n"
     "                (increments, a standard Fanuc/Haas); default: the program's numbers, else machine.cfg\n"
     "  --tool N=ID   use library tool ID at station N for this run (repeatable), e.g. --tool 12=parting-3mm\n"
     "  --design PART.json  the part's roughness marks for the finishing-feed warning W332 (else Ra 3.2 um)\n",
     "วิธีใช้: klueng-cli check FILE|FOLDER... [--lang en|th] [--dialect fanuc|haas|classic] [--json]\n"
     "                                       [--config DIR] [--summary]\n"
     "                                       [--stock DxL[xBORE][in]] [--units mm|inch] [--tool N=ID]...\n"
     "                                       [--design PART.json|PART.dxf]\n"
     "  --dialect     รุ่นของเครื่อง: fanuc (Fanuc 0i-TF ค่าเริ่มต้น), haas (เครื่องกลึง Haas ST), classic (กฎปี 1999)\n"
     "  --stock       ขนาดชิ้นงานของทุก FILE ใช้ก่อนส่วนหัวของไฟล์: 50x100 (มม.), 2.1x4in, 118x80x90 (ท่อ รูใน 90)\n"
     "  --units       หน่วยเมื่อเปิดเครื่อง ก่อน G20/G21 ใด ๆ: mm หรือ inch\n"
     "  --decimal-point whole|increments  ความยาวที่ไม่มีจุดทศนิยม: X30 = 30 มม. (whole) หรือ 0.030 มม.\n"
     "                (increments แบบ Fanuc/Haas มาตรฐาน) ค่าเริ่มต้น: ตามตัวเลขในโปรแกรม ไม่เช่นนั้นตาม machine.cfg\n"
     "  --tool N=ID   ใช้มีดตัด ID จากคลังมีดตัดที่สถานี N สำหรับการรันนี้ (ใส่ได้หลายครั้ง) เช่น --tool 12=parting-3mm\n"
     "  --design PART.json  ค่าความหยาบผิวในแบบชิ้นงาน สำหรับคำเตือนอัตราป้อนกลึงละเอียด W332 (ไม่เช่นนั้น Ra 3.2 ไมครอน)\n"},
    {codes::kCliSimulateUsage,
     "usage: klueng-cli simulate FILE [--trace out.csv] [--cycle-time] [--config DIR]\n"
     "                              [--lang en|th] [--dialect fanuc|haas|classic]\n"
     "                              [--optional-stop] [--block-skip] [--no-persist]\n"
     "                              [--png out.png] [--profile out.csv] [--json summary.json]\n"
     "                              [--svg out.svg] [--dxf out.dxf] [--features] [--resolution MM] [--no-stock]\n"
     "                              [--part-check] [--part-tolerance MM] [--compare-compensation none|sharp]\n"
     "                              [--stock DxL[xBORE][in]] [--units mm|inch] [--tool N=ID]...\n"
     "                              [--decimal-point whole|increments] [--show-units auto|mm|inch]\n"
     "                              [--cutting-data out.csv] [--design PART.json|PART.dxf]\n"
     "  --cutting-data  per block: cutting speed, feed, depth, roughness, power (docs/cutting-data.md),\n"
     "                  and the cutting-data warnings (W330-W336)\n"
     "  --design  the part's roughness marks for the finishing-feed warning W332 (else Ra 3.2 um)\n"
     "  --dialect  fanuc (Fanuc 0i-TF, default), haas (Haas ST lathe), classic (1999 rules)\n"
     "  --stock   stock before the file's header: 50x100 (mm), 2.1x4in, 118x80x90 (tube, bore 90)\n"
     "  --units   power-on units before any G20/G21: mm or inch\n"
     "  --show-units  the unit --features and --part-check write in: auto (the program's, G20 = inch,\n"
     "                default), mm or inch\n"
     "  --decimal-point  a length without a decimal point: X30 = 30 mm (whole) or 0.030 mm (increments,\n"
     "                   a standard Fanuc/Haas); default: the program's numbers, else machine.cfg\n"
     "  --tool N=ID   library tool ID at station N for this run, e.g. 12=parting-3mm\n"
     "  --no-persist  do not write macro variables #500-#999 back to macro_variables.cfg (kept in the\n"
     "                --config folder, else in the user's data folder)\n",
     "วิธีใช้: klueng-cli simulate FILE [--trace out.csv] [--cycle-time] [--config DIR]\n"
     "                              [--lang en|th] [--dialect fanuc|haas|classic]\n"
     "                              [--optional-stop] [--block-skip] [--no-persist]\n"
     "                              [--png out.png] [--profile out.csv] [--json summary.json]\n"
     "                              [--svg out.svg] [--dxf out.dxf] [--features] [--resolution MM] [--no-stock]\n"
     "                              [--part-check] [--part-tolerance MM] [--compare-compensation none|sharp]\n"
     "                              [--stock DxL[xBORE][in]] [--units mm|inch] [--tool N=ID]...\n"
     "                              [--decimal-point whole|increments] [--show-units auto|mm|inch]\n"
     "                              [--cutting-data out.csv] [--design PART.json|PART.dxf]\n"
     "  --cutting-data  ข้อมูลการตัดทีละบล็อก: ความเร็วตัด อัตราป้อน ความลึก ความหยาบผิว กำลังตัด\n"
     "                  (docs/cutting-data.md) และคำเตือนข้อมูลการตัด (W330-W336)\n"
     "  --design  ค่าความหยาบผิวในแบบชิ้นงาน สำหรับคำเตือนอัตราป้อนกลึงละเอียด W332 (ไม่เช่นนั้น Ra 3.2 ไมครอน)\n"
     "  --dialect  fanuc (Fanuc 0i-TF ค่าเริ่มต้น), haas (เครื่องกลึง Haas ST), classic (กฎปี 1999)\n"
     "  --stock   ขนาดชิ้นงาน ใช้ก่อนส่วนหัวของไฟล์: 50x100 (มม.), 2.1x4in, 118x80x90 (ท่อ รูใน 90)\n"
     "  --units   หน่วยเมื่อเปิดเครื่อง ก่อน G20/G21 ใด ๆ: mm หรือ inch\n"
     "  --show-units  หน่วยที่ --features และ --part-check ใช้แสดงผล: auto (ตามโปรแกรม G20 = นิ้ว\n"
     "                ค่าเริ่มต้น), mm หรือ inch\n"
     "  --decimal-point  ความยาวที่ไม่มีจุดทศนิยม: X30 = 30 มม. (whole) หรือ 0.030 มม. (increments\n"
     "                   แบบ Fanuc/Haas มาตรฐาน) ค่าเริ่มต้น: ตามตัวเลขในโปรแกรม ไม่เช่นนั้นตาม machine.cfg\n"
     "  --tool N=ID   ใช้มีดตัด ID จากคลังมีดตัดที่สถานี N สำหรับการรันนี้ เช่น 12=parting-3mm\n"
     "  --no-persist  ไม่บันทึกตัวแปรมาโคร #500-#999 กลับลง macro_variables.cfg (ซึ่งอยู่ในโฟลเดอร์\n"
     "                ของ --config หรือในโฟลเดอร์ข้อมูลของผู้ใช้)\n"},
    {codes::kCliClassUsage,
     "usage: klueng-cli class DIR --reference REF.nc [--tolerance 0.05] [--csv OUT.csv]\n"
     "                            [--drawing PART.json|PART.dxf [--layer NAME] [--general-tolerance f|m|c|v]]\n"
     "                            [--pdf OUT.pdf [--sheets]] [--dialect fanuc|haas|classic]\n"
     "                            [--config DIR] [--lang en|th]\n"
     "  every program in DIR against REF.nc: errors, alarm, cycle time, the largest leftover\n"
     "  and gouge on the diameter (mm), pass when both are within --tolerance (mm);\n"
     "  --drawing: (instead of or besides --reference) each toleranced diameter and length of the\n"
     "  teacher's drawing measured to 0.001 mm, in or out (a value at a limit is in, one not on the\n"
     "  part is out); --general-tolerance: ISO 2768-1 for the sizes without their own\n"
     "  --pdf: the same table as a page (Thai with --lang th), --sheets: then every\n"
     "  student's program sheet and drawing in the same PDF\n",
     "วิธีใช้: klueng-cli class DIR --reference REF.nc [--tolerance 0.05] [--csv OUT.csv]\n"
     "                            [--drawing PART.json|PART.dxf [--layer NAME] [--general-tolerance f|m|c|v]]\n"
     "                            [--pdf OUT.pdf [--sheets]] [--dialect fanuc|haas|classic]\n"
     "                            [--config DIR] [--lang en|th]\n"
     "  ตรวจทุกโปรแกรมใน DIR เทียบกับ REF.nc: ข้อผิดพลาด สัญญาณเตือน เวลาทำงาน เนื้อที่เหลือมากที่สุด\n"
     "  และที่กินเกินมากที่สุดบนเส้นผ่านศูนย์กลาง (มม.) ผ่านเมื่อทั้งสองค่าไม่เกิน --tolerance (มม.)\n"
     "  --drawing: (แทนหรือร่วมกับ --reference) วัดทุกเส้นผ่านศูนย์กลางและความยาวที่มีพิกัดความเผื่อในแบบงาน\n"
     "  ของครู ละเอียด 0.001 มม. ว่าอยู่ในพิกัดหรือไม่ (ค่าที่เท่ากับขอบเขตพอดีถือว่าอยู่ในพิกัด ขนาดที่ไม่มี\n"
     "  บนชิ้นงานถือว่าไม่ผ่าน); --general-tolerance: ISO 2768-1 สำหรับขนาดที่ไม่ได้กำหนดพิกัดเอง\n"
     "  --pdf: ตารางเดียวกันเป็นหน้ากระดาษ (ภาษาไทยเมื่อใช้ --lang th), --sheets: ต่อด้วยใบโปรแกรม\n"
     "  และแบบงานของนักเรียนทุกคนใน PDF เดียวกัน\n"},
    {codes::kCliPrintUsage,
     "usage: klueng-cli print FILE --pdf OUT.pdf [--sheet program|drawing|both] [--lang en|th]\n"
     "                             [--dialect fanuc|haas|classic] [--stock DxL[xBORE][in]] [--units mm|inch]\n"
     "                             [--config DIR] [--tool N=ID]... [--decimal-point whole|increments]\n"
     "  --sheet  program (the listing, portrait), drawing (the dimensioned part, landscape) or both (default)\n"
     "  --design PART.json|PART.dxf  the part design the program was made from: its tolerances (h7, ±0.05)\n"
     "           are written after the drawing's diameters\n",
     "วิธีใช้: klueng-cli print FILE --pdf OUT.pdf [--sheet program|drawing|both] [--lang en|th]\n"
     "                             [--dialect fanuc|haas|classic] [--stock DxL[xBORE][in]] [--units mm|inch]\n"
     "                             [--config DIR] [--tool N=ID]... [--decimal-point whole|increments]\n"
     "  --sheet  program (รายการโปรแกรม แนวตั้ง), drawing (แบบชิ้นงานพร้อมขนาด แนวนอน) หรือ both (ค่าเริ่มต้น)\n"
     "  --design PART.json|PART.dxf  แบบชิ้นงานที่ใช้สร้างโปรแกรมนี้: เขียนพิกัดความเผื่อ (h7, ±0.05)\n"
     "           ต่อท้ายขนาดเส้นผ่าศูนย์กลางในแบบงาน\n"},
    {codes::kCliGenerateUsage,
     "usage: klueng-cli generate PART.json|PART.dxf -o OUT.nc [--dialect fanuc|haas|classic] [--material NAME]\n"
     "                           [--tool-material hss|carbide] [--layer NAME] [--stock DxL[xBORE][in]]\n"
     "                           [--machine NAME|FILE] [--lang en|th] [--config DIR]\n"
     "  the part file's format and DXF drawings: docs/parts.md; cutting speeds: resources/parts/cutting_speeds.cfg\n",
     "วิธีใช้: klueng-cli generate PART.json|PART.dxf -o OUT.nc [--dialect fanuc|haas|classic] [--material NAME]\n"
     "                           [--tool-material hss|carbide] [--layer NAME] [--stock DxL[xBORE][in]]\n"
     "                           [--machine NAME|FILE] [--lang en|th] [--config DIR]\n"
     "  รูปแบบไฟล์ชิ้นงานและแบบ DXF: docs/parts.md ความเร็วตัด: resources/parts/cutting_speeds.cfg\n"},

    // What a command says about its command line and its run ({0}... as each says).
    {codes::kCliUnknownCommand, "unknown command '{0}'", "ไม่รู้จักคำสั่ง '{0}'"},
    {codes::kCliUnknownOption, "unknown option '{0}'", "ไม่รู้จักตัวเลือก '{0}'"},
    {codes::kCliNeedsValue, "{0} needs a value", "{0} ต้องมีค่าตามหลัง"},
    {codes::kCliBadValue, "bad value '{0}' for {1}; allowed: {2}", "ค่า '{0}' ใช้กับ {1} ไม่ได้ ค่าที่ใช้ได้: {2}"},
    {codes::kCliBadValueAnyOf, "bad value '{0}' for {1}", "ค่า '{0}' ใช้กับ {1} ไม่ได้"},
    {codes::kCliNoFile, "no FILE given", "ไม่ได้ระบุ FILE"},
    {codes::kCliOneFile, "only one FILE (got '{0}' and '{1}')", "ระบุ FILE ได้ไฟล์เดียว (ได้รับ '{0}' และ '{1}')"},
    {codes::kCliNotAFolder, "{0} is not a folder", "{0} ไม่ใช่โฟลเดอร์"},
    {codes::kCliReferenceFails, "the reference {0} does not run to its end ({1})",
     "โปรแกรมต้นแบบ {0} ทำงานไม่ถึงจุดจบ ({1})"},
    {codes::kCliClassNeeds, "needs a folder DIR and --reference REF.nc or --drawing PART.json",
     "ต้องระบุโฟลเดอร์ DIR และ --reference REF.nc หรือ --drawing PART.json"},
    {codes::kCliDrawingNoTolerances,
     "the drawing {0} has no toleranced dimension: give tolerances in a part file (JSON; a DXF drawing's "
     "dimension texts are not read) or a general tolerance with --general-tolerance f|m|c|v (ISO 2768-1)",
     "แบบงาน {0} ไม่มีขนาดที่กำหนดพิกัดความเผื่อ: ให้กำหนดพิกัดความเผื่อในไฟล์ชิ้นงาน (JSON; ข้อความบอกขนาดในแบบ DXF "
     "ไม่ถูกอ่าน) หรือกำหนดพิกัดความเผื่อทั่วไปด้วย --general-tolerance f|m|c|v (ISO 2768-1)"},
    {codes::kCliClassTotals, "{0} programs: {1} pass, {2} fail", "{0} โปรแกรม: ผ่าน {1} ไม่ผ่าน {2}"},
    {codes::kCliPrintNeeds, "needs a FILE and --pdf OUT.pdf", "ต้องระบุ FILE และ --pdf OUT.pdf"},
    {codes::kCliGenerateNeeds, "needs a PART.json or PART.dxf and -o OUT.nc",
     "ต้องระบุ PART.json หรือ PART.dxf และ -o OUT.nc"},
    {codes::kCliToolForm,
     "--tool wants N=ID (a station and a library tool, e.g. 3=threading-60), not '{0}'; library tools: {1}",
     "--tool ต้องเป็น N=ID (หมายเลขป้อมมีดและมีดในคลังมีด เช่น 3=threading-60) ไม่ใช่ '{0}' มีดในคลังมีด: {1}"},
    {codes::kCliToolStation, "--tool {0}: station {1} is not on the turret (1 to {2})",
     "--tool {0}: ป้อมมีดไม่มีตำแหน่ง {1} (มี 1 ถึง {2})"},
    {codes::kCliToolUnknown, "--tool {0}: no library tool '{1}'; library tools: {2}",
     "--tool {0}: ไม่มีมีด '{1}' ในคลังมีด มีดในคลังมีด: {2}"},

    // What the options allow, for the texts above.
    {codes::kCliAllowedLang, "en or th", "en หรือ th"},
    {codes::kCliAllowedDialect, "fanuc, haas or classic", "fanuc, haas หรือ classic"},
    {codes::kCliAllowedStock,
     "DxL[xBORE][in] with 0 < D, L <= 9999.999 and 0 < BORE < D, e.g. 50x100, 2.1x4in, 118x80x90",
     "DxL[xBORE][in] โดย 0 < D, L <= 9999.999 และ 0 < BORE < D เช่น 50x100, 2.1x4in, 118x80x90"},
    {codes::kCliAllowedUnits, "mm or inch", "mm หรือ inch"},
    {codes::kCliAllowedDecimalPoint, "whole or increments", "whole หรือ increments"},
    {codes::kCliAllowedSheet, "program, drawing or both", "program, drawing หรือ both"},
    {codes::kCliAllowedMillimetres, "a number from 0.001 to 5 (mm)", "ตัวเลขตั้งแต่ 0.001 ถึง 5 (มม.)"},
    {codes::kCliAllowedShowUnits, "auto, mm or inch", "auto, mm หรือ inch"},
    {codes::kCliAllowedCompare, "none or sharp", "none หรือ sharp"},
    {codes::kCliAllowedToolMaterial, "hss or carbide", "hss หรือ carbide"},
    {codes::kCliAllowedTolerance, "a number from 0 to 100 (mm)", "ตัวเลขตั้งแต่ 0 ถึง 100 (มม.)"},
    {codes::kCliAllowedGeneralTolerance, "f, m, c or v (ISO 2768-1: fine, medium, coarse, very coarse)",
     "f, m, c หรือ v (ISO 2768-1: ละเอียด ปานกลาง หยาบ หยาบมาก)"},

    // Why a picture or a PDF was not made (the reasons F108 gives in both languages).
    {codes::kCliNoOwnFolder, "cannot find the program's own folder: {0}", "หาโฟลเดอร์ของโปรแกรมไม่พบ: {0}"},
    {codes::kCliModuleNotOpened, "cannot open the picture module: {0}", "เปิดโมดูลวาดภาพ klueng-png.so ไม่ได้: {0}"},
    {codes::kCliModuleMissing, "the picture module klueng-png.so is not installed beside {0}",
     "ไม่ได้ติดตั้งโมดูลวาดภาพ klueng-png.so ไว้คู่กับ {0}"},
    {codes::kCliModuleNoEntry, "klueng-png.so has no {0}: not Klueng's picture module",
     "klueng-png.so ไม่มี {0}: ไม่ใช่โมดูลวาดภาพของ Klueng"},
    {codes::kCliPictureNotDrawn, "the picture could not be drawn", "วาดภาพไม่ได้"},

    // check --summary.
    {codes::kCliSummaryFile, "file", "ไฟล์"},
    {codes::kCliSummaryErrors, "errors", "ข้อผิดพลาด"},
    {codes::kCliSummaryWarnings, "warnings", "คำเตือน"},
    {codes::kCliSummaryResult, "result", "ผล"},
    {codes::kCliSummaryUnreadable, "unreadable", "อ่านไม่ได้"},
    {codes::kCliSummaryFail, "FAIL", "ไม่ผ่าน"},
    {codes::kCliSummaryOk, "ok", "ผ่าน"},
};
}  // namespace

std::span<const MessageText> cliMessages() { return kCliMessages; }

}  // namespace klueng::core::catalog
