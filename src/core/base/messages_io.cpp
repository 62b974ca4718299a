// Catalog part for the io module: code, English, Thai. Keep codes sorted.
// Every io diagnostic carries the file name as {0}; texts about a field whose
// place (line and column) already says which file leave it out.
#include "catalog_parts.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::catalog {

namespace {
constexpr MessageText kIoMessages[] = {
    // SPEC 5 rule 13 lives here because the stock size comes from the program header.
    {codes::kStockSizeTooLarge, "{0}: stock size {1} is larger than any lathe holds; write at most {2}",
     "{0}: ขนาดชิ้นงาน {1} ใหญ่เกินกว่าที่เครื่องกลึงใดจะจับได้ ให้เขียนไม่เกิน {2}"},
    {codes::kStockSizeNotPositive,
     "stock diameter and length must be greater than 0, not {1} (written '{2}': unit digit, then the size)",
     "เส้นผ่านศูนย์กลางและความยาวของชิ้นงานต้องมากกว่า 0 ไม่ใช่ {1} (เขียนไว้ว่า '{2}': หลักหน่วยตามด้วยขนาด)"},

    // Whole files.
    {codes::kNoSuchFile, "{0}: no such file", "{0}: ไม่พบไฟล์"},
    {codes::kNotAnOrdinaryFile, "{0}: this is {1}, not an ordinary file, so it is not opened",
     "{0}: นี่คือ{2} ไม่ใช่ไฟล์ธรรมดา จึงไม่เปิด"},
    {codes::kPathTooLong,
     "{0}: the path is too long for the system to open ({1} characters; a path may have at most 4095, and each "
     "folder or file name in it 255): run the command from a folder nearer to the file, or shorten the names",
     "{0}: พาธยาวเกินกว่าที่ระบบจะเปิดได้ ({1} ตัวอักษร พาธยาวได้ไม่เกิน 4095 และชื่อโฟลเดอร์หรือชื่อไฟล์แต่ละชื่อยาวได้ไม่เกิน 255) "
     "ให้สั่งงานจากโฟลเดอร์ที่อยู่ใกล้ไฟล์กว่านี้ หรือย่อชื่อให้สั้นลง"},
    {codes::kOutsideFolder, "{0}: refused: points outside the folder, so it is not read",
     "{0}: ไม่รับ: ลิงก์นี้ชี้ออกไปนอกโฟลเดอร์ จึงไม่อ่าน"},
    {codes::kNotAProgram, "{0}: this is not a G-code program ({1}), so its text is not shown",
     "{0}: ไฟล์นี้ไม่ใช่โปรแกรม G-code ({2}) จึงไม่แสดงข้อความในไฟล์"},
    {codes::kCannotReadFile, "{0}: cannot read the file (it is a folder, or access is denied)",
     "{0}: อ่านไฟล์ไม่ได้ (เป็นโฟลเดอร์ หรือไม่มีสิทธิ์เข้าถึง)"},
    {codes::kFileTooLarge, "{0}: the file is {1} bytes; files over {2} are refused",
     "{0}: ไฟล์มีขนาด {1} ไบต์ ไม่รับไฟล์ที่ใหญ่กว่า {2}"},
    {codes::kBinaryFile, "{0}: this is a binary file (it contains a NUL byte), not text",
     "{0}: ไฟล์นี้เป็นไฟล์ไบนารี (มีไบต์ NUL) ไม่ใช่ไฟล์ข้อความ"},
    {codes::kEmptyFile, "{0}: the file is empty", "{0}: ไฟล์ว่างเปล่า"},
    {codes::kLineTooLong, "{0}: the line is too long ({1} characters, at most {2}); it is ignored",
     "{0}: บรรทัดยาวเกินไป ({1} ตัวอักษร ยาวได้ไม่เกิน {2}) จึงไม่นำบรรทัดนี้มาใช้"},
    {codes::kLinesIgnored, "{0}: lines after line {1} are ignored", "{0}: บรรทัดที่อยู่หลังบรรทัดที่ {1} จะไม่ถูกนำมาใช้"},
    // Writing (io/file_write.h): an existing file of that name always keeps its bytes.
    {codes::kCannotWriteFile, "{0}: cannot write the file ({1}); an existing file of that name is left unchanged",
     "{0}: บันทึกไฟล์ไม่ได้ ({2}) ถ้ามีไฟล์ชื่อนี้อยู่แล้ว ไฟล์นั้นยังคงเดิม"},
    {codes::kNoSpaceToWrite,
     "{0}: cannot write the file: there is no space for it (the disk is full, or the file is over the size "
     "allowed); an existing file of that name is left unchanged",
     "{0}: บันทึกไฟล์ไม่ได้ เพราะไม่มีที่ว่างพอ (ดิสก์เต็ม หรือไฟล์ใหญ่เกินขนาดที่อนุญาต) "
     "ถ้ามีไฟล์ชื่อนี้อยู่แล้ว ไฟล์นั้นยังคงเดิม"},

    // Program header (SPEC 2).
    {codes::kHeaderTooShort,
     "{0}: the job header needs 6 lines (project, part, material, diameter, length, programmer) "
     "but the file has only {1}",
     "{0}: ส่วนหัวของงานต้องมี 6 บรรทัด (ชื่องาน ชิ้นงาน วัสดุ เส้นผ่านศูนย์กลาง ความยาว ผู้เขียน) "
     "แต่ไฟล์มีเพียง {1} บรรทัด"},
    {codes::kDiameterUnitDigit, "stock diameter: the unit digit must be 0 (inch) or 1 (mm), not '{1}'",
     "เส้นผ่านศูนย์กลางของชิ้นงาน: หลักแรกต้องเป็นหน่วย 0 (นิ้ว) หรือ 1 (มม.) ไม่ใช่ '{1}'"},
    {codes::kDiameterNotNumber, "stock diameter: '{1}' is not a number", "เส้นผ่านศูนย์กลางของชิ้นงาน: '{1}' ไม่ใช่ตัวเลข"},
    {codes::kLengthUnitDigit, "stock length: the unit digit must be 0 (inch) or 1 (mm), not '{1}'",
     "ความยาวของชิ้นงาน: หลักแรกต้องเป็นหน่วย 0 (นิ้ว) หรือ 1 (มม.) ไม่ใช่ '{1}'"},
    {codes::kLengthNotNumber, "stock length: '{1}' is not a number", "ความยาวของชิ้นงาน: '{1}' ไม่ใช่ตัวเลข"},
    {codes::kDiameterMissing, "stock diameter is missing: line 4 must hold a unit digit and a number, e.g. 150 = 50 mm",
     "ไม่มีเส้นผ่านศูนย์กลางของชิ้นงาน: บรรทัดที่ 4 ต้องมีหลักหน่วยตามด้วยตัวเลข เช่น 150 = 50 มม."},
    {codes::kLengthMissing, "stock length is missing: line 5 must hold a unit digit and a number, e.g. 1100 = 100 mm",
     "ไม่มีความยาวของชิ้นงาน: บรรทัดที่ 5 ต้องมีหลักหน่วยตามด้วยตัวเลข เช่น 1100 = 100 มม."},
    {codes::kPlainGcodeFile,
     "{0}: read as a plain G-code file without a job header: line {2} ('{1}') is not a stock size "
     "(a unit digit 0 = inch or 1 = mm, then the size, e.g. 150 = 50 mm)",
     "{0}: อ่านเป็นไฟล์รหัสจีล้วนที่ไม่มีส่วนหัวของงาน: บรรทัดที่ {2} ('{1}') ไม่ใช่ขนาดชิ้นงาน "
     "(หลักหน่วย 0 = นิ้ว หรือ 1 = มม. ตามด้วยขนาด เช่น 150 = 50 มม.)"},
    {codes::kBadBore, "stock bore: '{1}' must be a number greater than 0 and less than the diameter {2}",
     "รูในของชิ้นงานท่อ: '{1}' ต้องเป็นตัวเลขที่มากกว่า 0 และน้อยกว่าเส้นผ่านศูนย์กลาง {2}"},
    {codes::kFileReadOnly,
     "{0}: the file is read-only, so it was not replaced; write to another file, or make it writable first",
     "{0}: ไฟล์นี้เป็นแบบอ่านอย่างเดียว จึงไม่ได้เขียนทับ ให้บันทึกเป็นไฟล์อื่น หรือเปลี่ยนให้เขียนได้ก่อน"},

    // tools.cfg (SPEC 11).
    {codes::kToolTableShort,
     "{0}: the tool table needs 8 lines (bitmaps of tools 01 to 08) but has {1}; tools {2} to 08 have no bitmap",
     "{0}: ตารางมีดตัดต้องมี 8 บรรทัด (ภาพของมีดตัด 01 ถึง 08) แต่มีเพียง {1} บรรทัด มีดตัด {2} ถึง 08 จึงไม่มีภาพ"},
    {codes::kBitmapMissing, "{0}: tool {1}: the bitmap '{2}' does not exist", "{0}: มีดตัด {1}: ไม่พบไฟล์ภาพ '{2}'"},
    {codes::kNotBitmapName, "{0}: tool {1}: '{2}' is not a .bmp or .png file name",
     "{0}: มีดตัด {1}: '{2}' ไม่ใช่ชื่อไฟล์ภาพ .bmp หรือ .png"},
    {codes::kNotInToolLibrary, "{0}: tool {1}: the tool library has no tool '{2}' (it has: {3})",
     "{0}: มีดตัด {1}: ไม่มีมีดตัด '{2}' ในคลังมีดตัด (ที่มี: {3})"},
    {codes::kBitmapIsFolder, "{0}: tool {1}: '{2}' is a folder, not a bitmap file",
     "{0}: มีดตัด {1}: '{2}' เป็นโฟลเดอร์ ไม่ใช่ไฟล์ภาพ"},
    {codes::kBitmapNotAFile, "{0}: tool {1}: '{2}' is {3}, not a bitmap file",
     "{0}: มีดตัด {1}: '{2}' เป็น{4} ไม่ใช่ไฟล์ภาพ"},
    {codes::kToolBitmapTooLarge,
     "{0}: tool {1}: the bitmap '{2}' is {3} x {4} pixels; a tool bitmap may be at most {5} x {5} pixels "
     "(500 mm each way at {6} pixels per mm)",
     "{0}: มีดตัด {1}: ภาพ '{2}' มีขนาด {3} x {4} พิกเซล ภาพมีดตัดต้องไม่เกิน {5} x {5} พิกเซล "
     "(ด้านละ 500 มม. ที่ {6} พิกเซลต่อมม.)"},
    {codes::kTooManyConfigProblems, "{0}: more than {1} problems; the rest of the file is not read",
     "{0}: พบปัญหามากกว่า {1} รายการ จึงไม่อ่านส่วนที่เหลือของไฟล์"},

    // Writing files (io/file_write.h).
    {codes::kFolderNotWritable, "{0}: cannot create the file: the folder {1} does not exist or cannot be written to",
     "{0}: สร้างไฟล์ไม่ได้ เพราะไม่มีโฟลเดอร์ {1} หรือไม่มีสิทธิ์เขียนลงในโฟลเดอร์นี้"},
    {codes::kOutputIsInput,
     "{0}: this output is the input file {1}; writing it would destroy that file, so choose another name",
     "{0}: ไฟล์ผลลัพธ์นี้คือไฟล์ขาเข้า {1} ถ้าเขียนลงไปไฟล์นั้นจะหายไป จึงให้ตั้งชื่อไฟล์อื่น"},
    {codes::kOutputIsFolder, "{0}: this is a folder, not a file", "{0}: นี่คือโฟลเดอร์ ไม่ใช่ไฟล์"},

    // offset.cfg (SPEC 11).
    {codes::kOffsetTableShort,
     "{0}: the offset table needs 16 lines (X Z R T of offsets 01 to 16) but has {1}; offsets {2} to 16 are set to 0 0 "
     "0 0",
     "{0}: ตารางค่าออฟเซตต้องมี 16 บรรทัด (X Z R T ของออฟเซต 01 ถึง 16) แต่มีเพียง {1} บรรทัด ออฟเซต {2} ถึง 16 จึงเป็น 0 0 0 0"},
    {codes::kOffsetEmpty, "{0}: offset {1} is empty; it needs four numbers X Z R T",
     "{0}: ออฟเซต {1} ว่างอยู่ ต้องมีตัวเลขสี่ค่า X Z R T"},
    {codes::kOffsetFieldCount, "{0}: offset {1} needs four numbers X Z R T but has {2}",
     "{0}: ออฟเซต {1} ต้องมีตัวเลขสี่ค่า X Z R T แต่มี {2} ค่า"},
    {codes::kOffsetNotNumber, "{0}: offset {1}: '{2}' is not a number", "{0}: ออฟเซต {1}: '{2}' ไม่ใช่ตัวเลข"},
    {codes::kNegativeNoseRadius, "{0}: offset {1}: the nose radius R must not be negative ({2})",
     "{0}: ออฟเซต {1}: รัศมีจมูกมีด R ต้องไม่ติดลบ ({2})"},
    {codes::kBadTipNumber, "{0}: offset {1}: the tip number must be a whole number from 0 to 9, not '{2}'",
     "{0}: ออฟเซต {1}: หมายเลขปลายมีดต้องเป็นจำนวนเต็มตั้งแต่ 0 ถึง 9 ไม่ใช่ '{2}'"},
    {codes::kOffsetBeyondLathe,
     "{0}: offset {1}: '{2}' is beyond any lathe's offset (at most {3} mm); the row is set to 0 0 0 0",
     "{0}: ออฟเซต {1}: '{2}' เกินค่าออฟเซตของเครื่องกลึงทั่วไป (ไม่เกิน {3} มม.) จึงตั้งแถวนี้เป็น 0 0 0 0"},

    // machine.cfg.
    {codes::kNoMachineParameters, "{0}: sets no machine parameter: every parameter keeps its default (SPEC 1)",
     "{0}: ไม่ได้กำหนดค่าพารามิเตอร์ของเครื่องไว้เลย จึงใช้ค่าเริ่มต้นทุกค่า (ตาม SPEC 1)"},
    {codes::kNotKeyValue, "{0}: expected 'key = value'", "{0}: ต้องเขียนในรูปแบบ 'ชื่อค่า = ค่า'"},
    {codes::kUnknownParameter, "{0}: unknown machine parameter '{1}'", "{0}: ไม่รู้จักค่าพารามิเตอร์ของเครื่อง '{1}'"},
    {codes::kParameterNotNumber, "{0}: {1}: '{2}' is not a number", "{0}: {1}: '{2}' ไม่ใช่ตัวเลข"},
    {codes::kParameterNotPositive, "{0}: {1} must be greater than 0 ({2})", "{0}: {1} ต้องมากกว่า 0 ({2})"},
    {codes::kParameterNegative, "{0}: {1} must not be negative ({2})", "{0}: {1} ต้องไม่ติดลบ ({2})"},
    {codes::kParameterTwice, "{0}: {1} is given twice; the later value is used",
     "{0}: มีการกำหนด {1} ซ้ำสองครั้ง จะใช้ค่าหลัง"},
    {codes::kTravelLimitsReversed, "{0}: travel limits: {1} must be less than {2}",
     "{0}: ระยะเคลื่อนที่สูงสุดของเครื่อง: {1} ต้องน้อยกว่า {2}"},
    {codes::kParameterNotWhole, "{0}: {1} must be a whole number from {3} to {4}, not {2}",
     "{0}: {1} ต้องเป็นจำนวนเต็มตั้งแต่ {3} ถึง {4} ไม่ใช่ {2}"},
    {codes::kParameterOutOfRange, "{0}: {1} = {2} is outside what a lathe can have ({3} to {4}); the default is used",
     "{0}: {1} = {2} อยู่นอกช่วงที่เครื่องกลึงจะมีได้ ({5} ถึง {4}) จึงใช้ค่าเริ่มต้นแทน"},
    {codes::kStartOutsideTravel, "{0}: the tool start {1} = {2} is outside the travel limits {3} to {4}",
     "{0}: ตำแหน่งเริ่มต้นของมีด {1} = {2} อยู่นอกระยะเคลื่อนที่ {3} ถึง {4}"},

    // Tool bitmaps (SPEC 11).
    {codes::kNotAnImage, "{0}: not a BMP or PNG image", "{0}: ไม่ใช่ไฟล์ภาพ BMP หรือ PNG"},
    {codes::kImageTruncated, "{0}: the image data ends too early (truncated file)",
     "{0}: ข้อมูลภาพสิ้นสุดก่อนกำหนด (ไฟล์ไม่สมบูรณ์)"},
    {codes::kImageSizeRefused, "{0}: image size {1} × {2} pixels is not allowed (1 to 4096 pixels each way)",
     "{0}: ขนาดภาพ {1} × {2} พิกเซลใช้ไม่ได้ (ด้านละ 1 ถึง 4096 พิกเซล)"},
    {codes::kUnsupportedBmp, "{0}: unsupported BMP format ({1} bits per pixel, compression {2})",
     "{0}: ไม่รองรับรูปแบบ BMP นี้ ({1} บิตต่อพิกเซล การบีบอัดแบบ {2})"},
    {codes::kBmpHeaderDamaged, "{0}: the BMP header is damaged ({1})", "{0}: ส่วนหัวของไฟล์ BMP เสียหาย ({1})"},
    {codes::kPngDamaged, "{0}: the PNG data is damaged ({1})", "{0}: ข้อมูล PNG เสียหาย ({1})"},
    {codes::kColourOutsidePalette, "{0}: a pixel uses colour {1}, but the palette has only {2} colours",
     "{0}: มีพิกเซลที่ใช้สีหมายเลข {1} แต่จานสีมีเพียง {2} สี"},

    // Where a job's stock came from (SPEC 2 ext): notes, never errors. {0} is
    // the stock as stockSizeText() writes it ("Ø50 x 100 mm", "Ø118/Ø90 x 80 mm").
    {codes::kStockFromCommandLine, "stock {0} from the command line (--stock)", "ชิ้นงาน {0} จากบรรทัดคำสั่ง (--stock)"},
    {codes::kStockFromJobDetails, "stock {0} from Job details set for this file",
     "ชิ้นงาน {0} จากรายละเอียดงานที่ตั้งไว้สำหรับไฟล์นี้"},
    {codes::kStockFromFirstApproach, "stock {0} inferred from {1} (first approach)",
     "ชิ้นงาน {0} ประมาณจาก {1} (ตำแหน่งเข้าหาชิ้นงานครั้งแรก)"},
    {codes::kStockFromComment, "stock {0} from the program's comment {1}", "ชิ้นงาน {0} ตามหมายเหตุในโปรแกรม {1}"},
    {codes::kStockFromCycleStart, "stock {0} inferred from {1} (cycle start)", "ชิ้นงาน {0} ประมาณจาก {1} (จุดเริ่มวัฏจักร)"},
    {codes::kBoreInferred, "bore Ø{0} inferred from {1} (work inside without drilling first: tube stock)",
     "รูใน Ø{0} ประมาณจาก {1} (กลึงด้านในโดยไม่เจาะก่อน: ชิ้นงานท่อ)"},
    {codes::kStockDefault,
     "stock {0} is the default: the program has no approach to infer it from; set it in Job details or with --stock",
     "ชิ้นงาน {0} เป็นค่าเริ่มต้น: โปรแกรมไม่มีตำแหน่งเข้าหาชิ้นงานให้ประมาณได้ ตั้งค่าได้ที่รายละเอียดงานหรือ --stock"},
    {codes::kStockFromHeader, "stock {0} from the file's job header", "ชิ้นงาน {0} จากส่วนหัวของงานในไฟล์"},
    {codes::kStockInferredFromBore,
     "stock {0} inferred: the program works only inside a bore, so the bar is a size above its largest cut Ø{1} with a "
     "wall around it",
     "ชิ้นงาน {0} ประมาณจากงานกลึงด้านในเท่านั้น: ใช้ขนาดเหล็กเพลาที่โตกว่าเส้นผ่าศก. ใหญ่สุดที่ตัด Ø{1} โดยเผื่อความหนาผนัง"},
    {codes::kStockFromLargestTurned, "stock {0} inferred from {1} (the largest diameter it turns)",
     "ชิ้นงาน {0} ประมาณจาก {1} (เส้นผ่านศูนย์กลางใหญ่สุดที่กลึงด้านนอก)"},
    {codes::kStockLengthFromDeepestCut,
     "stock length {0}: the deepest cut Z{1} ({2}) + {3} for the cut-off + {4} held in the chuck",
     "ความยาวชิ้นงาน {0}: ตัดลึกสุดที่ Z{1} ({2}) + {3} สำหรับการตัดขาด + {4} ส่วนที่หัวจับยึด"},
    {codes::kStockLengthForTools,
     "stock length {0}, not {1}: T{2} reaches Z-{3} here, so the bar sticks out far enough for it to clear the "
     "chuck's jaws",
     "ความยาวชิ้นงาน {0} ไม่ใช่ {1}: มีด T{2} ยื่นไปถึง Z-{3} ตรงนี้ จึงให้ชิ้นงานยื่นออกจากหัวจับพอให้มีดไม่ชนปากจับ"},
    // The tool library, library.cfg (docs/tools.md).
    {codes::kLibraryLineFields,
     "{0}: a library line needs 9 fields separated by '|' (id | kind | px/mm | R | tip | size | bitmap | "
     "English name | Thai name), and may have a 10th (material=..., edge=...), but has {1}",
     "{0}: บรรทัดของคลังมีดตัดต้องมี 9 ช่องคั่นด้วย '|' (รหัส | ชนิด | พิกเซล/มม. | R | ปลายมีด | ขนาด | "
     "ไฟล์ภาพ | ชื่อภาษาอังกฤษ | ชื่อภาษาไทย) และมีช่องที่ 10 ได้ (material=..., edge=...) แต่มี {1} ช่อง"},
    {codes::kBadToolId, "{0}: '{1}' is not a tool id (lowercase letters, digits, '-', '.' and '_')",
     "{0}: '{1}' ไม่ใช่รหัสมีดตัด (ใช้ได้เฉพาะอักษรอังกฤษตัวเล็ก ตัวเลข '-' '.' และ '_')"},
    {codes::kDuplicateToolId, "{0}: the tool id '{1}' is already used on line {2}",
     "{0}: รหัสมีดตัด '{1}' ถูกใช้แล้วในบรรทัดที่ {2}"},
    {codes::kBadToolKind, "{0}: '{1}' is not a tool kind (one of: {2})", "{0}: '{1}' ไม่ใช่ชนิดของมีดตัด (ใช้ได้: {2})"},
    {codes::kBadPixelsPerMm, "{0}: pixels per mm must be a number from 1 to 100, not '{1}'",
     "{0}: จำนวนพิกเซลต่อมม. ต้องเป็นตัวเลข 1 ถึง 100 ไม่ใช่ '{1}'"},
    {codes::kLibraryNumberNegative, "{0}: {1} must be a number of 0 or more, not '{2}'",
     "{0}: {1} ต้องเป็นตัวเลขตั้งแต่ 0 ขึ้นไป ไม่ใช่ '{2}'"},
    {codes::kLibraryBadTip, "{0}: the tip number must be 0 to 9, not '{1}'",
     "{0}: หมายเลขปลายมีดต้องเป็น 0 ถึง 9 ไม่ใช่ '{1}'"},
    {codes::kLibraryNotBitmapName, "{0}: '{1}' is not a .bmp or .png file name",
     "{0}: '{1}' ไม่ใช่ชื่อไฟล์ภาพ .bmp หรือ .png"},
    {codes::kToolNeedsNames, "{0}: the tool needs an English and a Thai name", "{0}: มีดตัดต้องมีชื่อภาษาอังกฤษและชื่อภาษาไทย"},
    {codes::kLibraryBitmapMissing, "{0}: tool '{1}': the bitmap '{2}' does not exist",
     "{0}: มีดตัด '{1}': ไม่พบไฟล์ภาพ '{2}'"},
    {codes::kNotVariableLine, "{0}: '{1}' is not a macro variable line; write #500 = 12.5",
     "{0}: '{1}' ไม่ใช่บรรทัดตัวแปรมาโคร ต้องเขียนเป็น #500 = 12.5"},
    {codes::kVariableNotKept, "{0}: #{1} is not kept between runs; only #500 to #999 are",
     "{0}: #{1} ไม่ถูกเก็บไว้ระหว่างการทำงานแต่ละครั้ง เก็บได้เฉพาะ #500 ถึง #999"},
    {codes::kLibraryBadOption,
     "{0}: '{1}' is not a tool option (material=hss, material=carbide, material=coated-carbide, edge=MM)",
     "{0}: '{1}' ไม่ใช่ตัวเลือกของมีดตัด (material=hss, material=carbide, material=coated-carbide, edge=มม.)"},
    {codes::kMaterialLineFields,
     "{0}: a material line needs 9 fields separated by '|' (id | names | English | Thai | HSS Vc | carbide Vc | "
     "kc1.1 | mc | source) but has {1}",
     "{0}: บรรทัดของวัสดุต้องมี 9 ช่องคั่นด้วย '|' (รหัส | ชื่อ | ชื่ออังกฤษ | ชื่อไทย | Vc มีดไฮสปีด | Vc มีดคาร์ไบด์ | "
     "kc1.1 | mc | แหล่งที่มา) แต่มี {1} ช่อง"},
    {codes::kToolLineBadOption,
     "{0}: tool {1}: '{2}' is not a station option (after '|': material=hss, material=carbide or "
     "material=coated-carbide)",
     "{0}: มีดตัด {1}: '{2}' ไม่ใช่ตัวเลือกของสถานีมีด (หลัง '|': material=hss, material=carbide หรือ "
     "material=coated-carbide)"},
    {codes::kMaterialBadNumber, "{0}: {1} must be a number of 0 or more (a range: MIN-MAX), not '{2}'",
     "{0}: {1} ต้องเป็นตัวเลขตั้งแต่ 0 ขึ้นไป (ช่วง: ต่ำสุด-สูงสุด) ไม่ใช่ '{2}'"},

    // Machine files (resources/machines/*.machine, docs/dialects.md "Machine files").
    {codes::kMachineValueBad, "{0}: {1} = '{2}': must be {3}", "{0}: {1} = '{2}': ต้องเป็น{4}"},
    {codes::kMachineKeyMissing,
     "{0}: '{1}' is missing; write it, or start the file with base = fanuc (or another machine) and write only what "
     "differs",
     "{0}: ไม่มี '{1}' ให้เขียนเพิ่ม หรือขึ้นต้นไฟล์ด้วย base = fanuc (หรือเครื่องอื่น) แล้วเขียนเฉพาะค่าที่ต่างกัน"},
    {codes::kMachineUnknownBase, "{0}: base '{1}' is no machine; the machines are: {2}",
     "{0}: base '{1}' ไม่ใช่เครื่องที่มีอยู่ เครื่องที่มี: {2}"},
    {codes::kUnknownMachine, "{0}: no such machine or machine file; the machines are: {1}",
     "{0}: ไม่มีเครื่องหรือไฟล์เครื่องนี้ เครื่องที่มี: {1}"},
    {codes::kNotAMachineFile, "{0}: a machine file's name ends in .machine", "{0}: ชื่อไฟล์เครื่องต้องลงท้ายด้วย .machine"},
    {codes::kProgramMachineUnknown,
     "the program names the machine '{0}', which is not loaded: it is checked on the chosen machine; the machines are: "
     "{1}",
     "โปรแกรมระบุเครื่อง '{0}' ซึ่งไม่มีอยู่: จึงตรวจกับเครื่องที่เลือกไว้ เครื่องที่มี: {1}"},

    // Tools chosen from the program (core/infer/tool_inference.h): notes, never errors.
    // {0} station (2 digits), {1} library id, {2} what was seen, {3} file line.
    {codes::kToolFromComment, "T{0} = {1} (comment \"{2}\" on line {3})", "T{0} = {1} (หมายเหตุ \"{2}\" ในบรรทัดที่ {3})"},
    {codes::kToolForThreading, "T{0} = {1} (threading, {2} on line {3})", "T{0} = {1} (กลึงเกลียว {2} ในบรรทัดที่ {3})"},
    {codes::kToolForInsideThreading, "T{0} = {1} (threading inside a bore, {2} on line {3})",
     "T{0} = {1} (กลึงเกลียวใน {2} ในบรรทัดที่ {3})"},
    {codes::kToolForGrooving, "T{0} = {1} (grooving cycle {2} on line {3})",
     "T{0} = {1} (วัฏจักรกลึงร่อง {2} ในบรรทัดที่ {3})"},
    {codes::kToolForDrilling, "T{0} = {1} (drilling on the centre line, {2} on line {3})",
     "T{0} = {1} (เจาะรูตามแนวศูนย์กลาง {2} ในบรรทัดที่ {3})"},
    {codes::kToolForBoring, "T{0} = {1} (cutting inside a bore, {2} on line {3})",
     "T{0} = {1} (กลึงภายในรู (คว้าน) {2} ในบรรทัดที่ {3})"},
    {codes::kToolForParting, "T{0} = {1} (plunge to {2} near the end of the program on line {3})",
     "T{0} = {1} (ป้อนตัดลงถึง {2} ใกล้ท้ายโปรแกรม (ตัดขาด) ในบรรทัดที่ {3})"},
    {codes::kToolForTurning, "T{0} = {1} (outside turning, {2} on line {3})", "T{0} = {1} (กลึงผิวนอก {2} ในบรรทัดที่ {3})"},
    {codes::kToolSetForJob, "T{0} = {1} (set for this job)", "T{0} = {1} (กำหนดไว้สำหรับงานนี้)"},
    {codes::kOffsetFromLibrary, "offset {0} was 0 0 0 0: nose radius {1} and tip {2} of {3} are used",
     "ออฟเซต {0} เป็น 0 0 0 0: ใช้รัศมีจมูกมีด {1} และหมายเลขปลายมีด {2} ของ {3}"},
    {codes::kToolsBeyondCentre,
     "the program cuts at X < 0 (from line {0}): its tools work beyond the centre line, as on a rear tool post, and "
     "are mirrored there",
     "โปรแกรมกลึงที่ X < 0 (ตั้งแต่บรรทัดที่ {0}): มีดทำงานอีกฝั่งของแนวศูนย์กลาง เหมือนป้อมมีดด้านหลัง จึงกลับด้านมีดไปฝั่งนั้น"},
    {codes::kGuessReplacedStock, "T{0}: {1} instead of {2}: the first guess touched the stock at line {3}",
     "T{0}: ใช้ {1} แทน {2}: มีดที่เดาไว้ตอนแรกแตะชิ้นงานที่บรรทัดที่ {3}"},
    {codes::kNoseRadiusFromComment, "T{0}: nose radius {1} mm, as its comment says, is used for its offsets",
     "T{0}: ใช้รัศมีจมูกมีด {1} มม. ตามที่หมายเหตุของมีดระบุ สำหรับออฟเซตของมีดนี้"},
    {codes::kBladeOnItsRightCorner,
     "T{0}: the {1} mm blade is taken as set on its right (+Z) corner: set on its left corner, as the library's "
     "blade is, it would cut into what the other tools turned beside its plunge; choose it in Tool Select if the "
     "shop sets it otherwise",
     "T{0}: ใบมีดกว้าง {1} มม. ถือว่าตั้งค่าที่มุมขวา (ด้าน +Z) เพราะถ้าตั้งที่มุมซ้ายแบบใบมีดในคลัง "
     "จะตัดเข้าไปในส่วนที่มีดอื่นกลึงไว้ข้างตำแหน่งที่ป้อนตัด: ถ้าโรงงานตั้งค่าแบบอื่นให้เลือกที่ เลือกมีดตัด"},
    {codes::kGuessReplacedChuck, "T{0}: {1} instead of {2}: the first guess touched the chuck at line {3}",
     "T{0}: ใช้ {1} แทน {2}: มีดที่เดาไว้ตอนแรกแตะหัวจับที่บรรทัดที่ {3}"},
    // {4} {5}: the row's own radius and tip, set for the tool the table had at that station.
    {codes::kOffsetReplacedByLibrary,
     "offset {0} held R{4} tip {5} for the table's tool: nose radius {1} and tip {2} of {3} are used",
     "ออฟเซต {0} เก็บ R{4} ปลายมีด {5} ของมีดในตาราง: ใช้รัศมีจมูกมีด {1} และหมายเลขปลายมีด {2} ของ {3} แทน"},
};
}  // namespace

std::span<const MessageText> ioMessages() { return kIoMessages; }

}  // namespace klueng::core::catalog
