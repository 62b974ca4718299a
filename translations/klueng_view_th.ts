<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="th_TH">
<context>
    <name>klueng::gui::AboutDialog</name>
    <message>
        <location filename="../src/gui/about_dialog.cpp" line="30"/>
        <source>About Klueng</source>
        <translation>เกี่ยวกับโปรแกรมกลึง (Klueng)</translation>
    </message>
    <message>
        <location filename="../src/gui/about_dialog.cpp" line="31"/>
        <source>Klueng %1</source>
        <translation>กลึง (Klueng) %1</translation>
    </message>
    <message>
        <location filename="../src/gui/about_dialog.cpp" line="33"/>
        <source>&lt;p&gt;A CNC lathe simulator for students and instructors: write a Fanuc-style lathe program, see every mistake explained, and watch bitmap tools cut the stock, block by block.&lt;/p&gt;&lt;p&gt;Klueng descends from the 1999 Thai thesis program “Rook.IE Lathe”.&lt;/p&gt;&lt;p&gt;Built with Qt %1, Eigen, fmt and libpng.&lt;/p&gt;</source>
        <translation>&lt;p&gt;โปรแกรมจำลองการทำงานของเครื่องกลึงซีเอ็นซีสำหรับนักศึกษาและผู้สอน: เขียนชุดรหัสสั่งการทำงานแบบ Fanuc ดูคำอธิบายข้อผิดพลาดทุกจุด และดูมีดตัดจากภาพบิตแมปตัดเฉือนชิ้นงานทีละบล็อก&lt;/p&gt;&lt;p&gt;Klueng พัฒนาต่อจากโปรแกรมวิทยานิพนธ์ไทยปี 2542 “Rook.IE Lathe”&lt;/p&gt;&lt;p&gt;สร้างด้วย Qt %1, Eigen, fmt และ libpng&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>klueng::gui::JobDetailsDialog</name>
    <message>
        <location filename="../src/gui/job_details_dialog.cpp" line="84"/>
        <source>Job Details</source>
        <translation>รายละเอียดงาน</translation>
    </message>
    <message>
        <location filename="../src/gui/job_details_dialog.cpp" line="85"/>
        <source>Project:</source>
        <translation>ชื่องาน:</translation>
    </message>
    <message>
        <location filename="../src/gui/job_details_dialog.cpp" line="85"/>
        <source>Part:</source>
        <translation>ชิ้นงาน:</translation>
    </message>
    <message>
        <location filename="../src/gui/job_details_dialog.cpp" line="85"/>
        <source>Material:</source>
        <translation>วัสดุ:</translation>
    </message>
    <message>
        <location filename="../src/gui/job_details_dialog.cpp" line="85"/>
        <source>Stock diameter:</source>
        <translation>เส้นผ่านศูนย์กลางชิ้นงาน:</translation>
    </message>
    <message>
        <location filename="../src/gui/job_details_dialog.cpp" line="85"/>
        <source>Stock length:</source>
        <translation>ความยาวชิ้นงาน:</translation>
    </message>
    <message>
        <location filename="../src/gui/job_details_dialog.cpp" line="85"/>
        <source>Programmer:</source>
        <translation>ผู้เขียนโปรแกรม:</translation>
    </message>
    <message>
        <location filename="../src/gui/job_details_dialog.cpp" line="89"/>
        <source>mm</source>
        <translation>มม.</translation>
    </message>
    <message>
        <location filename="../src/gui/job_details_dialog.cpp" line="90"/>
        <source>inch</source>
        <translation>นิ้ว</translation>
    </message>
    <message>
        <location filename="../src/gui/job_details_dialog.cpp" line="108"/>
        <source>Bore diameter (tube; 0 = solid bar):</source>
        <translation>เส้นผ่านศูนย์กลางรูใน (ชิ้นงานท่อ; 0 = เพลาตัน):</translation>
    </message>
    <message>
        <location filename="../src/gui/job_details_dialog.cpp" line="94"/>
        <source>The bore (%1) must be smaller than the stock diameter (%2).</source>
        <translation>รูใน (%1) ต้องเล็กกว่าเส้นผ่านศูนย์กลางชิ้นงาน (%2)</translation>
    </message>
    <message>
        <location filename="../src/gui/job_details_dialog.cpp" line="119"/>
        <source>Tube stock: the diameter of the hole through it. 0 = a solid bar.</source>
        <translation>ชิ้นงานท่อ: เส้นผ่านศูนย์กลางของรูที่ทะลุตลอดชิ้นงาน 0 = เพลาตัน</translation>
    </message>
    <message>
        <source>Lengths without a decimal point:</source>
        <translation>ความยาวที่ไม่มีจุดทศนิยม:</translation>
    </message>
    <message>
        <source>As the program&apos;s numbers show</source>
        <translation>ตามตัวเลขในชุดรหัสสั่งการทำงาน</translation>
    </message>
    <message>
        <source>Whole (X30 = 30 mm)</source>
        <translation>เต็มหน่วย (X30 = 30 มม.)</translation>
    </message>
    <message>
        <source>Least input increments (X30 = 0.030 mm)</source>
        <translation>หน่วยป้อนค่าที่เล็กที่สุด (X30 = 0.030 มม.)</translation>
    </message>
    <message>
        <source>How X30 or G71 U1250 is read. Whole: X30 = 30 mm (calculator-type input). Least input increments: X30 = 0.030 mm, 0.0030 in under G20, as a standard Fanuc or Haas reads it. As the program&apos;s numbers show: a plain program&apos;s own numbers decide (G71 U1250 only makes sense in increments), else the machine setting (machine.cfg calculator_input).</source>
        <translation>วิธีอ่าน X30 หรือ G71 U1250 เต็มหน่วย: X30 = 30 มม. (การป้อนค่าแบบเครื่องคิดเลข) หน่วยป้อนค่าที่เล็กที่สุด: X30 = 0.030 มม. (0.0030 นิ้วเมื่อใช้ G20) แบบที่เครื่อง Fanuc หรือ Haas ทั่วไปอ่าน ตามตัวเลขในชุดรหัสสั่งการทำงาน: ตัวเลขในชุดรหัสสั่งการทำงานที่ไม่มีส่วนหัวเป็นตัวตัดสิน (G71 U1250 มีความหมายเฉพาะเมื่ออ่านเป็นหน่วยป้อนค่าที่เล็กที่สุด) ถ้าตัดสินไม่ได้ใช้ค่าที่ตั้งไว้ที่เครื่อง (machine.cfg calculator_input)</translation>
    </message>
    <message>
        <source>Tool side:</source>
        <translation>ด้านของมีดตัด:</translation>
    </message>
    <message>
        <source>Machine:</source>
        <translation>เครื่อง:</translation>
    </message>
    <message>
        <source>Not named (the window&apos;s machine)</source>
        <translation>ไม่ระบุ (ใช้เครื่องที่เลือกในหน้าต่าง)</translation>
    </message>
    <message>
        <source>The machine this program is written for. The program names it in a comment at its head, (MACHINE: romi-gl240m): opening the file selects that machine, and klueng-cli checks it on that machine unless --machine or --dialect is given.</source>
        <translation>เครื่องที่เขียนชุดรหัสสั่งการทำงานนี้ไว้ใช้ ชุดรหัสสั่งการทำงานระบุชื่อเครื่องไว้ในหมายเหตุที่ส่วนต้น (MACHINE: romi-gl240m): เมื่อเปิดไฟล์จะเลือกเครื่องนั้นให้ และ klueng-cli จะตรวจกับเครื่องนั้น เว้นแต่จะกำหนด --machine หรือ --dialect</translation>
    </message>
    <message>
        <source>As the program&apos;s moves show</source>
        <translation>ตามการเคลื่อนที่ในชุดรหัสสั่งการทำงาน</translation>
    </message>
    <message>
        <source>In front of the centre line</source>
        <translation>ด้านหน้าแนวศูนย์กลาง</translation>
    </message>
    <message>
        <source>Beyond the centre line (rear tool post, X &lt; 0)</source>
        <translation>เลยแนวศูนย์กลาง (ป้อมมีดด้านหลัง X &lt; 0)</translation>
    </message>
    <message>
        <source>Where the tools work. Beyond the centre line: a rear tool post or a lathe programmed in negative X; the tools are drawn and cut mirrored onto the front. As the program&apos;s moves show: a plain program that cuts at X &lt; 0 has its tools there, else the machine setting (machine.cfg tools_beyond_centre).</source>
        <translation>ตำแหน่งที่มีดตัดทำงาน เลยแนวศูนย์กลาง: ป้อมมีดด้านหลังหรือเครื่องกลึงที่เขียนโปรแกรมด้วยค่า X ติดลบ มีดตัดจะถูกวาดและกลึงแบบกลับด้านมาด้านหน้า ตามการเคลื่อนที่ในชุดรหัสสั่งการทำงาน: ชุดรหัสสั่งการทำงานที่ไม่มีส่วนหัวซึ่งกลึงที่ X &lt; 0 มีมีดตัดอยู่ด้านนั้น ถ้าไม่เช่นนั้นใช้ค่าที่ตั้งไว้ที่เครื่อง (machine.cfg tools_beyond_centre)</translation>
    </message>
</context>
<context>
    <name>klueng::gui::OffsetDefineDialog</name>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="92"/>
        <source>the tip number must be a whole number from 0 to 9</source>
        <translation>หมายเลขปลายมีดต้องเป็นจำนวนเต็มตั้งแต่ 0 ถึง 9</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="95"/>
        <source>&apos;%1&apos; is not a number</source>
        <translation>&apos;%1&apos; ไม่ใช่ตัวเลข</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="98"/>
        <source>at most 3 decimals</source>
        <translation>ทศนิยมได้ไม่เกิน 3 ตำแหน่ง</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="99"/>
        <source>must lie between -9999.999 and 9999.999</source>
        <translation>ต้องอยู่ระหว่าง -9999.999 ถึง 9999.999</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="100"/>
        <source>the nose radius must not be negative</source>
        <translation>รัศมีจมูกมีดต้องไม่ติดลบ</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="111"/>
        <source>Offset %1, %2: %3</source>
        <translation>ออฟเซต %1, %2: %3</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="136"/>
        <source>All offsets are valid.</source>
        <translation>ค่าออฟเซตทุกค่าถูกต้อง</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="178"/>
        <source>Offset Define</source>
        <translation>กำหนดค่าออฟเซต</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="179"/>
        <source>Offsets 01–64: X offset (diameter, mm), Z offset (mm), nose radius R (mm) and the imaginary tool tip number T (0–9). Use offset nn with T..nn, e.g. T0101. Rows 17–64 that stay 0 0 0 0 are not written; a tool chosen from the program fills an empty row with its own R and tip.</source>
        <translation>ออฟเซต 01–64: ค่าออฟเซต X (เส้นผ่านศูนย์กลาง, มม.), ค่าออฟเซต Z (มม.), รัศมีจมูกมีด R (มม.) และหมายเลขปลายมีด T (0–9) เรียกใช้ออฟเซต nn ด้วย T..nn เช่น T0101 แถว 17–64 ที่เป็น 0 0 0 0 จะไม่ถูกบันทึก มีดตัดที่เลือกจากชุดรหัสสั่งการทำงานจะเติมรัศมีจมูกมีดและหมายเลขปลายมีดของตนลงในแถวที่ว่าง</translation>
    </message>
    <message>
        <source>Offsets 01–16: X offset (diameter, mm), Z offset (mm), nose radius R (mm) and the imaginary tool tip number T (0–9). Use offset nn with T..nn, e.g. T0101.</source>
        <translation type="vanished">ออฟเซต 01–16: ค่าออฟเซต X (เส้นผ่านศูนย์กลาง, มม.), ค่าออฟเซต Z (มม.), รัศมีจมูกมีด R (มม.) และหมายเลขปลายมีด T (0–9) เรียกใช้ออฟเซต nn ด้วย T..nn เช่น T0101</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="182"/>
        <source>X (dia.)</source>
        <translation>X (เส้นผ่าศก.)</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="182"/>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="182"/>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="182"/>
        <source>Tip T</source>
        <translation>ปลายมีด T</translation>
    </message>
    <message>
        <location filename="../src/gui/offset_define_dialog.cpp" line="182"/>
        <source>Tip</source>
        <translation>ปลายมีด</translation>
    </message>
</context>
<context>
    <name>klueng::gui::OutputView</name>
    <message>
        <location filename="../src/gui/output_view.cpp" line="297"/>
        <source>Output screen: wheel to zoom, drag to pan, double-click to fit</source>
        <translation>จอแสดงผล: หมุนล้อเมาส์เพื่อย่อ/ขยาย ลากเพื่อเลื่อน ดับเบิลคลิกเพื่อแสดงทั้งหมด</translation>
    </message>
</context>
<context>
    <name>klueng::gui::RunSpeedControl</name>
    <message>
        <location filename="../src/gui/run_speed_control.cpp" line="64"/>
        <source>Speed</source>
        <translation>ความเร็ว</translation>
    </message>
    <message>
        <location filename="../src/gui/run_speed_control.cpp" line="66"/>
        <source>fastest</source>
        <translation>เร็วที่สุด</translation>
    </message>
    <message>
        <location filename="../src/gui/run_speed_control.cpp" line="66"/>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <location filename="../src/gui/run_speed_control.cpp" line="67"/>
        <source>Animation speed: 1× is real machine time; slower is slow motion; &quot;fastest&quot; cuts to the next stop at once</source>
        <translation>ความเร็วการจำลองการทำงาน: 1× เท่ากับเวลาจริงของเครื่อง ช้ากว่านั้นเป็นภาพช้า &quot;เร็วที่สุด&quot; ตัดเฉือนไปถึงจุดหยุดถัดไปทันที</translation>
    </message>
</context>
<context>
    <name>klueng::gui::StatusFields</name>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="68"/>
        <source>%1 mm/rev</source>
        <translation>%1 มม./รอบ</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="68"/>
        <source>%1 mm/min</source>
        <translation>%1 มม./นาที</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="70"/>
        <source>%1 rpm</source>
        <translation>%1 รอบ/นาที</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="81"/>
        <source>Tool X</source>
        <translation>มีดตัด X</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="81"/>
        <source>Tool Z</source>
        <translation>มีดตัด Z</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="81"/>
        <source>Feed</source>
        <translation>อัตราป้อน</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="81"/>
        <source>Spindle</source>
        <translation>รอบเพลา</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="81"/>
        <source>X offset</source>
        <translation>ออฟเซต X</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="82"/>
        <source>Z offset</source>
        <translation>ออฟเซต Z</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="82"/>
        <source>Nose R</source>
        <translation>รัศมีจมูกมีด</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="82"/>
        <source>Tip</source>
        <translation>ปลายมีด</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="82"/>
        <source>Tool</source>
        <translation>มีดตัด</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="82"/>
        <source>Date</source>
        <translation>วันที่</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>เวลา</translation>
    </message>
    <message>
        <source>T%1: %2</source>
        <translation>T%1: %2</translation>
    </message>
    <message>
        <source>Machine time: elapsed / cycle time of the whole program (min:s)</source>
        <translation>เวลาเครื่อง: เวลาที่ผ่านไป / เวลาทำงานของทั้งโปรแกรม (นาที:วินาที)</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="83"/>
        <source>Tool position X (diameter, mm)</source>
        <translation>ตำแหน่งมีดตัด X (เส้นผ่านศูนย์กลาง, มม.)</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="83"/>
        <source>Tool position Z (mm)</source>
        <translation>ตำแหน่งมีดตัด Z (มม.)</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="83"/>
        <source>Feed rate as programmed</source>
        <translation>อัตราการป้อนตัดตามชุดรหัสสั่งการทำงาน</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="84"/>
        <source>Spindle speed (rpm)</source>
        <translation>ความเร็วรอบ (รอบ/นาที)</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="84"/>
        <source>X offset of the active tool offset (diameter, mm)</source>
        <translation>ค่าออฟเซต X ของมีดตัดที่ใช้อยู่ (เส้นผ่านศูนย์กลาง, มม.)</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="85"/>
        <source>Z offset of the active tool offset (mm)</source>
        <translation>ค่าออฟเซต Z ของมีดตัดที่ใช้อยู่ (มม.)</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="85"/>
        <source>Nose radius of the active offset (mm)</source>
        <translation>รัศมีจมูกมีดของออฟเซตที่ใช้อยู่ (มม.)</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="86"/>
        <source>Imaginary tool tip number of the active offset</source>
        <translation>หมายเลขปลายมีดของออฟเซตที่ใช้อยู่</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="86"/>
        <source>Tool number and offset number</source>
        <translation>หมายเลขมีดตัดและหมายเลขออฟเซต</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="87"/>
        <source>Today&apos;s date</source>
        <translation>วันที่วันนี้</translation>
    </message>
    <message>
        <source>%1 in/rev</source>
        <translation>%1 นิ้ว/รอบ</translation>
    </message>
    <message>
        <source>%1 in/min</source>
        <translation>%1 นิ้ว/นาที</translation>
    </message>
    <message>
        <source>Tool position X (diameter, inches)</source>
        <translation>ตำแหน่งมีดตัด X (เส้นผ่านศูนย์กลาง, นิ้ว)</translation>
    </message>
    <message>
        <source>Tool position Z (inches)</source>
        <translation>ตำแหน่งมีดตัด Z (นิ้ว)</translation>
    </message>
    <message>
        <source>X offset of the active tool offset (diameter, inches)</source>
        <translation>ค่าออฟเซต X ของมีดตัดที่ใช้อยู่ (เส้นผ่านศูนย์กลาง, นิ้ว)</translation>
    </message>
    <message>
        <source>Z offset of the active tool offset (inches)</source>
        <translation>ค่าออฟเซต Z ของมีดตัดที่ใช้อยู่ (นิ้ว)</translation>
    </message>
    <message>
        <source>Nose radius of the active offset (inches)</source>
        <translation>รัศมีจมูกมีดของออฟเซตที่ใช้อยู่ (นิ้ว)</translation>
    </message>
    <message>
        <source>FEED HOLD</source>
        <translation>หยุดป้อน</translation>
    </message>
</context>
<context>
    <name>klueng::gui::StatusLamps</name>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="183"/>
        <source>Spindle CW</source>
        <translation>หมุนตามเข็มนาฬิกา</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="184"/>
        <source>Spindle CCW</source>
        <translation>หมุนทวนเข็มนาฬิกา</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="185"/>
        <source>Spindle stop</source>
        <translation>หยุดหมุน</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="186"/>
        <source>Spindle direction: green clockwise (M03), amber counter-clockwise (M04), grey stopped (M05)</source>
        <translation>ทิศทางการหมุน: สีเขียว หมุนตามเข็มนาฬิกา (M03) สีส้ม หมุนทวนเข็มนาฬิกา (M04) สีเทา หยุดหมุน (M05)</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="187"/>
        <source>Optional stop</source>
        <translation>หยุดเลือกได้</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="188"/>
        <source>Optional Stop switch: M01 stops the program when lit</source>
        <translation>สวิตช์ทางเลือกการหยุด: เมื่อไฟติด M01 จะหยุดโปรแกรม</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="189"/>
        <source>Coolant</source>
        <translation>สารหล่อเย็น</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="190"/>
        <source>Coolant on (M08) / off (M09)</source>
        <translation>เปิด (M08) / ปิด (M09) สารหล่อเย็น</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="191"/>
        <source>Position check</source>
        <translation>ตรวจสอบตำแหน่ง</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="192"/>
        <source>Lit when G27 found the tool at the reference point</source>
        <translation>ไฟติดเมื่อ G27 พบว่ามีดตัดอยู่ที่จุดอ้างอิง</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="193"/>
        <source>Brake</source>
        <translation>เบรก</translation>
    </message>
    <message>
        <location filename="../src/gui/status_panel.cpp" line="194"/>
        <source>Spindle brake on (M86) / off (M87)</source>
        <translation>เบรกเพลาหมุน เปิด (M86) / ปิด (M87)</translation>
    </message>
</context>
<context>
    <name>klueng::gui::ToolSelectDialog</name>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="229"/>
        <source>Tool bitmap</source>
        <translation>ภาพบิตแมปของมีดตัด</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="229"/>
        <source>Tool bitmaps (*.bmp *.png)</source>
        <translation>ภาพบิตแมปของมีดตัด (*.bmp *.png)</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="250"/>
        <source>tip %1, nose radius %2 mm</source>
        <translation>ปลายมีด %1, รัศมีจมูกมีด %2 มม.</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="252"/>
        <source>Tool %1 has no bitmap.</source>
        <translation>มีดตัด %1 ยังไม่มีภาพบิตแมป</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="258"/>
        <source>cannot read the bitmap</source>
        <translation>อ่านภาพบิตแมปไม่ได้</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="266"/>
        <source>No cutting-edge pixels: every pixel is black (holder) or white (empty).</source>
        <translation>ไม่มีจุดภาพของคมตัด: ทุกจุดเป็นสีดำ (ด้ามจับมีด) หรือสีขาว (ว่าง)</translation>
    </message>
    <message>
        <source>%1 × %2 pixels = %3 × %4 mm; red cross = controlled point for tip %5</source>
        <translation type="vanished">%1 × %2 จุดภาพ = %3 × %4 มม. กากบาทสีแดง = จุดควบคุมของปลายมีด %5</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="267"/>
        <source>%1 × %2 pixels at %3 px/mm = %4 × %5 mm; red cross = controlled point for tip %6</source>
        <translation>%1 × %2 จุดภาพ ที่ %3 จุดภาพ/มม. = %4 × %5 มม. กากบาทสีแดง = จุดควบคุมของปลายมีด %6</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="321"/>
        <source>Set for this program only: %1 (tools.cfg has: %2)</source>
        <translation>กำหนดไว้สำหรับชุดรหัสสั่งการทำงานนี้เท่านั้น: %1 (ใน tools.cfg คือ: %2)</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="326"/>
        <source>Chosen from the program: %1</source>
        <translation>เลือกจากชุดรหัสสั่งการทำงาน: %1</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="377"/>
        <source>Tool %1: %2 is not in the tool library</source>
        <translation>มีดตัด %1: ไม่มี %2 ในคลังมีดตัด</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="382"/>
        <location filename="../src/gui/tool_select_dialog.cpp" line="444"/>
        <source>Tool %1: %2</source>
        <translation>มีดตัด %1: %2</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="426"/>
        <source>Tool Select</source>
        <translation>เลือกมีดตัด</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="427"/>
        <source>Bitmap file:</source>
        <translation>ไฟล์ภาพบิตแมป:</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="428"/>
        <source>Browse...</source>
        <translation>เลือกไฟล์...</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="429"/>
        <source>Preview with offset:</source>
        <translation>แสดงตัวอย่างกับออฟเซต:</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="430"/>
        <source>e.g. resources/tools/turning.bmp</source>
        <translation>เช่น resources/tools/turning.bmp</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="431"/>
        <source>Library tool:</source>
        <translation>มีดตัดจากคลัง:</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="432"/>
        <source>Only for this program (tools.cfg is not changed)</source>
        <translation>เฉพาะชุดรหัสสั่งการทำงานนี้ (ไม่เปลี่ยน tools.cfg)</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="433"/>
        <source>(a bitmap file, below)</source>
        <translation>(ไฟล์ภาพบิตแมป ด้านล่าง)</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="445"/>
        <source> (this program)</source>
        <translation> (เฉพาะงานนี้)</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="446"/>
        <source> (from the program)</source>
        <translation> (เลือกจากชุดรหัส)</translation>
    </message>
    <message>
        <location filename="../src/gui/tool_select_dialog.cpp" line="323"/>
        <location filename="../src/gui/tool_select_dialog.cpp" line="442"/>
        <source>(none)</source>
        <translation>(ไม่มี)</translation>
    </message>
    <message>
        <source>Tool material:</source>
        <translation>วัสดุมีดตัด:</translation>
    </message>
    <message>
        <source>(the library tool&apos;s, else not known)</source>
        <translation>(ตามมีดในคลัง ถ้าไม่มีถือว่าไม่ทราบ)</translation>
    </message>
    <message>
        <source>HSS (high-speed steel)</source>
        <translation>HSS (เหล็กกล้ารอบสูง ไฮสปีด)</translation>
    </message>
    <message>
        <source>Carbide</source>
        <translation>คาร์ไบด์</translation>
    </message>
    <message>
        <source>Coated carbide</source>
        <translation>คาร์ไบด์เคลือบผิว</translation>
    </message>
</context>
<context>
    <name>klueng::gui::PartPanel</name>
    <message>
        <source>The program changed: check the part again.</source>
        <translation>โปรแกรมถูกแก้ไขแล้ว: ตรวจชิ้นงานอีกครั้ง</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>ชิ้นงาน</translation>
    </message>
    <message>
        <source>Check part</source>
        <translation>ตรวจชิ้นงาน</translation>
    </message>
    <message>
        <source>Cut the program and list the finished part&apos;s features, gouges and leftovers</source>
        <translation>จำลองการตัดตามโปรแกรม แล้วแสดงรูปร่างของชิ้นงานสำเร็จ ส่วนที่มีดกินเกินแบบ และเนื้อที่เหลือเกินแบบ</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>วัดขนาด</translation>
    </message>
    <message>
        <source>Click two points on the output screen: ΔZ, ΔØ, distance and angle</source>
        <translation>คลิกสองจุดบนจอแสดงผล: ΔZ, ΔØ, ระยะห่าง และมุม</translation>
    </message>
    <message>
        <source>No comparison</source>
        <translation>ไม่เปรียบเทียบ</translation>
    </message>
    <message>
        <source>Compare: without G41/G42</source>
        <translation>เปรียบเทียบ: ไม่ชดเชยรัศมีจมูกมีด (ไม่มี G41/G42)</translation>
    </message>
    <message>
        <source>Compare: sharp nose (R 0)</source>
        <translation>เปรียบเทียบ: จมูกมีดแหลม (R 0)</translation>
    </message>
    <message>
        <source>Feature / finding</source>
        <translation>รูปร่าง / สิ่งที่พบ</translation>
    </message>
    <message>
        <source>Ra (µm)</source>
        <translation>Ra (ไมครอน)</translation>
    </message>
    <message>
        <source>Ra %1 µm, Rz %2 µm: the theoretical roughness of line %3&apos;s cut (feed %4, nose R%5)</source>
        <translation>Ra %1 ไมครอน, Rz %2 ไมครอน: ความหยาบผิวตามทฤษฎีของการตัดในบรรทัด %3 (อัตราป้อน %4 รัศมีจมูกมีด R%5)</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>ตำแหน่ง</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>บรรทัด</translation>
    </message>
    <message>
        <source>Features</source>
        <translation>รูปร่างชิ้นงาน</translation>
    </message>
    <message>
        <source>Part check</source>
        <translation>การตรวจชิ้นงาน</translation>
    </message>
    <message>
        <source>Compensation</source>
        <translation>การชดเชยรัศมีจมูกมีด</translation>
    </message>
    <message>
        <source>The program has errors: correct them, then check the part.</source>
        <translation>โปรแกรมมีข้อผิดพลาด: แก้ไขก่อน แล้วจึงตรวจชิ้นงาน</translation>
    </message>
    <message>
        <source>The cut part is the part the program describes: no gouge, no leftover.</source>
        <translation>ชิ้นงานที่ตัดได้ตรงกับแบบที่โปรแกรมกำหนด: ไม่มีส่วนที่กินเกิน ไม่มีเนื้อเหลือ</translation>
    </message>
    <message>
        <source>The program has no G41/G42 moves.</source>
        <translation>โปรแกรมนี้ไม่มีการเคลื่อนที่แบบ G41/G42</translation>
    </message>
    <message numerus="yes">
        <source>%n finding(s): see Part check.</source>
        <translation>
            <numerusform>พบ %n รายการ: ดูที่การตรวจชิ้นงาน</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>klueng::gui::Part3DDock</name>
    <message>
        <source>3D view</source>
        <translation>ภาพสามมิติ</translation>
    </message>
    <message>
        <source>Drag to turn, right-drag to move, wheel to zoom, double-click for the first view</source>
        <translation>ลากเพื่อหมุน ลากด้วยปุ่มขวาเพื่อเลื่อน หมุนล้อเมาส์เพื่อย่อขยาย ดับเบิลคลิกเพื่อกลับสู่มุมมองแรก</translation>
    </message>
</context>
<context>
    <name>klueng::gui::HeaderStrip</name>
    <message>
        <source>Lines 1–6: job header — %1, %2, %3 (click to edit)</source>
        <translation>บรรทัด 1–6: ส่วนหัวของงาน — %1, %2, %3 (คลิกเพื่อแก้ไข)</translation>
    </message>
    <message>
        <source>no project</source>
        <translation>ไม่มีชื่องาน</translation>
    </message>
    <message>
        <source>no part</source>
        <translation>ไม่มีชื่อชิ้นงาน</translation>
    </message>
    <message>
        <source>Ø%1 × %2 mm</source>
        <translation>Ø%1 × %2 มม.</translation>
    </message>
    <message>
        <source>Ø%1 × %2 in</source>
        <translation>Ø%1 × %2 นิ้ว</translation>
    </message>
    <message>
        <source>The file&apos;s first six lines hold the project, part, material, stock diameter, stock length and programmer; the program starts on line 7. File &gt; Job Details edits them.</source>
        <translation>หกบรรทัดแรกของไฟล์เก็บชื่องาน ชิ้นงาน วัสดุ เส้นผ่าศก. ชิ้นงานดิบ ความยาวชิ้นงานดิบ และผู้เขียน ชุดรหัสสั่งการทำงานเริ่มที่บรรทัด 7 แก้ไขได้ที่ แฟ้ม &gt; รายละเอียดงาน</translation>
    </message>
</context>
<context>
    <name>klueng::gui::SetupStrip</name>
    <message>
        <source>Click to change the stock (Job details).</source>
        <translation>คลิกเพื่อเปลี่ยนชิ้นงานดิบ (รายละเอียดงาน)</translation>
    </message>
    <message>
        <source>T%1  %2 — %3</source>
        <translation>T%1  %2 — %3</translation>
    </message>
    <message>
        <source>Click to choose another tool for this station (Tool Select).</source>
        <translation>คลิกเพื่อเลือกมีดตัดอื่นให้ตำแหน่งมีดนี้ (เลือกมีดตัด)</translation>
    </message>
    <message>
        <source>no tool</source>
        <translation>ไม่มีมีดตัด</translation>
    </message>
    <message>
        <source>T%1  %2 — kept from the tool table (tools.cfg): nothing in the program asks for another tool</source>
        <translation>T%1  %2 — ใช้มีดตัดเดิมจากตารางมีด (tools.cfg): ชุดรหัสสั่งการทำงานไม่ได้ต้องการมีดตัดอื่น</translation>
    </message>
    <message>
        <source>Tools beyond the centre line, drawn mirrored: %1</source>
        <translation>มีดตัดอยู่เลยแนวศูนย์กลาง วาดกลับด้าน: %1</translation>
    </message>
    <message>
        <source>Setup guessed from the program — check it before you run; click a line to change it</source>
        <translation>การตั้งเครื่องที่เดาจากชุดรหัสสั่งการทำงาน — ตรวจสอบก่อนเริ่มทำงาน คลิกที่บรรทัดเพื่อเปลี่ยน</translation>
    </message>
    <message>
        <source>Setup for this program — click a line to change it</source>
        <translation>การตั้งเครื่องสำหรับชุดรหัสสั่งการทำงานนี้ — คลิกที่บรรทัดเพื่อเปลี่ยน</translation>
    </message>
    <message>
        <source>Lengths without a decimal point: whole millimetres/inches — %1 on line %2 = %3 (calculator-type input)</source>
        <translation>ความยาวที่ไม่มีจุดทศนิยม: อ่านเป็นมิลลิเมตร/นิ้วเต็มหน่วย — %1 ในบรรทัดที่ %2 = %3 (การป้อนค่าแบบเครื่องคิดเลข)</translation>
    </message>
    <message>
        <source>Lengths without a decimal point: least input increments — %1 on line %2 = %3 (as a standard Fanuc/Haas)</source>
        <translation>ความยาวที่ไม่มีจุดทศนิยม: อ่านเป็นหน่วยป้อนค่าที่เล็กที่สุด — %1 ในบรรทัดที่ %2 = %3 (แบบเครื่อง Fanuc/Haas ทั่วไป)</translation>
    </message>
    <message>
        <source>Lengths without a decimal point: whole millimetres/inches, as chosen in Job details (X30 = 30 mm)</source>
        <translation>ความยาวที่ไม่มีจุดทศนิยม: อ่านเป็นมิลลิเมตร/นิ้วเต็มหน่วย ตามที่เลือกในรายละเอียดงาน (X30 = 30 มม.)</translation>
    </message>
    <message>
        <source>Lengths without a decimal point: least input increments, as chosen in Job details (X30 = 0.030 mm)</source>
        <translation>ความยาวที่ไม่มีจุดทศนิยม: อ่านเป็นหน่วยป้อนค่าที่เล็กที่สุด ตามที่เลือกในรายละเอียดงาน (X30 = 0.030 มม.)</translation>
    </message>
    <message>
        <source>Lengths without a decimal point: least input increments, as the machine is set (machine.cfg; X30 = 0.030 mm)</source>
        <translation>ความยาวที่ไม่มีจุดทศนิยม: อ่านเป็นหน่วยป้อนค่าที่เล็กที่สุด ตามที่ตั้งไว้ที่เครื่อง (machine.cfg; X30 = 0.030 มม.)</translation>
    </message>
    <message>
        <source>A length written without a decimal point is read whole (X30 = 30 mm, calculator-type input) or in least input increments (X30 = 0.030 mm, 0.0030 in under G20), as a standard Fanuc or Haas reads it.</source>
        <translation>ความยาวที่เขียนโดยไม่มีจุดทศนิยมอ่านได้สองแบบ: เต็มหน่วย (X30 = 30 มม. การป้อนค่าแบบเครื่องคิดเลข) หรือเป็นหน่วยป้อนค่าที่เล็กที่สุด (X30 = 0.030 มม., 0.0030 นิ้วเมื่อใช้ G20) แบบที่เครื่อง Fanuc หรือ Haas ทั่วไปอ่าน</translation>
    </message>
    <message>
        <source>Click to change it for this file (Job details).</source>
        <translation>คลิกเพื่อเปลี่ยนการอ่านสำหรับไฟล์นี้ (รายละเอียดงาน)</translation>
    </message>
    <message>
        <source>Tools beyond the centre line (a rear tool post), drawn mirrored, as chosen in Job details</source>
        <translation>มีดตัดอยู่เลยแนวศูนย์กลาง (ป้อมมีดด้านหลัง) วาดกลับด้าน ตามที่เลือกไว้ในรายละเอียดงาน</translation>
    </message>
    <message>
        <source>Tools in front of the centre line, as chosen in Job details</source>
        <translation>มีดตัดอยู่ด้านหน้าแนวศูนย์กลาง ตามที่เลือกไว้ในรายละเอียดงาน</translation>
    </message>
    <message>
        <source>Tools beyond the centre line (a rear tool post), drawn mirrored, as the machine is set (machine.cfg)</source>
        <translation>มีดตัดอยู่เลยแนวศูนย์กลาง (ป้อมมีดด้านหลัง) วาดกลับด้าน ตามที่ตั้งไว้ที่เครื่อง (machine.cfg)</translation>
    </message>
    <message>
        <source>Click to change the tool side for this file (Job details).</source>
        <translation>คลิกเพื่อเปลี่ยนด้านของมีดตัดสำหรับไฟล์นี้ (รายละเอียดงาน)</translation>
    </message>
</context>
<context>
    <name>klueng::gui::CuttingPlot</name>
    <message>
        <source>power (kW, max %1)</source>
        <translation>กำลังตัด (กิโลวัตต์ สูงสุด %1)</translation>
    </message>
    <message>
        <source>, spindle %1 kW</source>
        <translation>, เพลาจับงาน %1 กิโลวัตต์</translation>
    </message>
    <message>
        <source>Vc (ft/min, max %1)</source>
        <translation>ความเร็วตัด Vc (ฟุต/นาที สูงสุด %1)</translation>
    </message>
    <message>
        <source>Vc (m/min, max %1)</source>
        <translation>ความเร็วตัด Vc (ม./นาที สูงสุด %1)</translation>
    </message>
</context>
</TS>
