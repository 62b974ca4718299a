<?xml version='1.0' encoding='utf-8'?>
<!DOCTYPE TS>
<TS version="2.1" language="th_TH">
<context>
    <name>klueng::gui::OperatorPanel</name>
    <message>
        <source>Operator panel</source>
        <translation>แผงควบคุมเครื่อง</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>ปุ่มควบคุม</translation>
    </message>
    <message>
        <source>Offsets</source>
        <translation>ค่าออฟเซต</translation>
    </message>
    <message>
        <source>EDIT: the program is edited in the editor</source>
        <translation>EDIT: แก้ไขโปรแกรมในหน้าต่างแก้ไขโปรแกรม</translation>
    </message>
    <message>
        <source>MEMORY: cycle start runs the job's program</source>
        <translation>MEMORY: กด CYCLE START เพื่อรันโปรแกรมของงาน</translation>
    </message>
    <message>
        <source>MDI: type blocks on the MDI page and press cycle start (Alt+Enter)</source>
        <translation>MDI: พิมพ์บล็อกในหน้า MDI แล้วกด CYCLE START (Alt+Enter)</translation>
    </message>
    <message>
        <source>JOG: hold -X +X -Z +Z (Alt+arrows) to move at the jog feed, with RAPID at the rapid rate</source>
        <translation>JOG: กดค้างปุ่ม -X +X -Z +Z (Alt+ลูกศร) เพื่อเลื่อนด้วยอัตราป้อนแบบจ็อก หรือกด RAPID เพื่อเคลื่อนที่เร็ว</translation>
    </message>
    <message>
        <source>HANDLE: the handwheel moves the chosen axis one step a click (Alt+Page Up/Down)</source>
        <translation>HANDLE: หมุนมือหมุน (แฮนด์วีล) แกนที่เลือกจะเลื่อนหนึ่งระยะต่อหนึ่งคลิก (Alt+Page Up/Down)</translation>
    </message>
    <message>
        <source>ZERO RETURN: +X and +Z bring each axis to the reference point; until then cycle start is refused</source>
        <translation>ZERO RETURN: กด +X และ +Z เพื่อให้แต่ละแกนกลับสู่จุดอ้างอิง ก่อนทำขั้นตอนนี้เครื่องจะไม่ยอมให้กด CYCLE START</translation>
    </message>
    <message>
        <source>Jog the turret; in ZERO RETURN mode +X / +Z return the axis</source>
        <translation>เลื่อนป้อมมีด ในโหมด ZERO RETURN ปุ่ม +X / +Z จะพาแกนกลับสู่จุดอ้างอิง</translation>
    </message>
    <message>
        <source>Jog at the rapid rate (times the rapid override): a rapid into the bar is a crash</source>
        <translation>เลื่อนด้วยการเคลื่อนที่เร็ว (คูณค่าปรับอัตราเคลื่อนที่เร็ว) ถ้าเคลื่อนที่เร็วเข้าชนชิ้นงานถือว่าชน</translation>
    </message>
    <message>
        <source>0.001 mm a click (X in diameter)</source>
        <translation>0.001 มม. ต่อคลิก (แกน X เป็นขนาดโต)</translation>
    </message>
    <message>
        <source>0.01 mm a click (X in diameter)</source>
        <translation>0.01 มม. ต่อคลิก (แกน X เป็นขนาดโต)</translation>
    </message>
    <message>
        <source>0.1 mm a click (X in diameter)</source>
        <translation>0.1 มม. ต่อคลิก (แกน X เป็นขนาดโต)</translation>
    </message>
    <message>
        <source>The handwheel (manual pulse generator): turn it, or Alt+Page Up / Page Down</source>
        <translation>มือหมุน (แฮนด์วีล): หมุนด้วยเมาส์ หรือกด Alt+Page Up / Page Down</translation>
    </message>
    <message>
        <source>Spindle forward (M03) at the S speed</source>
        <translation>เพลาจับงานหมุนตามเข็มนาฬิกา (M03) ด้วยความเร็วรอบ S</translation>
    </message>
    <message>
        <source>Spindle stop (M05): never touch the bar with the spindle stopped</source>
        <translation>เพลาจับงานหยุดหมุน (M05): ห้ามแตะมีดกับชิ้นงานขณะเพลาจับงานหยุดหมุน</translation>
    </message>
    <message>
        <source>Spindle reverse (M04) at the S speed</source>
        <translation>เพลาจับงานหมุนทวนเข็มนาฬิกา (M04) ด้วยความเร็วรอบ S</translation>
    </message>
    <message>
        <source>Spindle speed for the spindle keys, rpm</source>
        <translation>ความเร็วรอบของปุ่มเพลาจับงาน (รอบ/นาที)</translation>
    </message>
    <message>
        <source>Coolant on / off (M08 / M09)</source>
        <translation>เปิด / ปิดสารหล่อเย็น (M08 / M09)</translation>
    </message>
    <message>
        <source>Feed override: 0 to 150 % in steps of 10 %; it does not act while threading</source>
        <translation>ปรับอัตราป้อน: 0 ถึง 150 % ทีละ 10 % ไม่มีผลขณะกลึงเกลียว</translation>
    </message>
    <message>
        <source>Rapid override: F0 (Haas: 5 %), 25, 50 or 100 % of the rapid rate</source>
        <translation>ปรับอัตราเคลื่อนที่เร็ว: F0 (Haas: 5 %), 25, 50 หรือ 100 % ของอัตราเคลื่อนที่เร็ว</translation>
    </message>
    <message>
        <source>Spindle override: 50 to 120 % of the programmed speed</source>
        <translation>ปรับความเร็วรอบ: 50 ถึง 120 % ของความเร็วรอบในโปรแกรม</translation>
    </message>
    <message>
        <source>Single block: the program stops after each block</source>
        <translation>ทีละบล็อก: โปรแกรมหยุดหลังจบแต่ละบล็อก</translation>
    </message>
    <message>
        <source>Optional stop: M01 stops the program</source>
        <translation>หยุดตามเลือก: M01 จะหยุดโปรแกรม</translation>
    </message>
    <message>
        <source>Block delete: blocks starting with / are skipped</source>
        <translation>ข้ามบล็อก: บล็อกที่ขึ้นต้นด้วย / จะถูกข้าม</translation>
    </message>
    <message>
        <source>Dry run: feed moves at the jog feed, to try a program in the air</source>
        <translation>ทดลองเดินเปล่า (Dry run): การป้อนตัดใช้อัตราป้อนแบบจ็อก เพื่อทดลองโปรแกรมโดยไม่ตัดจริง</translation>
    </message>
    <message>
        <source>Cycle start (Alt+Enter): MDI runs the typed blocks, MEMORY runs the program</source>
        <translation>เริ่มทำงาน (Alt+Enter): โหมด MDI รันบล็อกที่พิมพ์ โหมด MEMORY รันโปรแกรม</translation>
    </message>
    <message>
        <source>Reset (Alt+Backspace): clears the alarm</source>
        <translation>รีเซ็ต (Alt+Backspace): ล้างสัญญาณเตือน</translation>
    </message>
    <message>
        <source>Power on again: a new bar, the turret short of the reference point, the offsets as the job has them</source>
        <translation>เปิดเครื่องใหม่: ชิ้นงานใหม่ ป้อมมีดอยู่ก่อนถึงจุดอ้างอิง ค่าออฟเซตตามงาน</translation>
    </message>
    <message>
        <source>Close-up of the tool tip: 8 mm across, to see each handwheel click</source>
        <translation>ขยายที่ปลายมีด กว้าง 8 มม. เพื่อดูการเลื่อนของแต่ละคลิกของมือหมุน</translation>
    </message>
    <message>
        <source>Type Z0 with the tool on the face, or X and the measured diameter after a cut, then MEASURE: the geometry offset of the selected row is computed from the machine position</source>
        <translation>พิมพ์ Z0 เมื่อมีดแตะผิวหน้า หรือพิมพ์ X ตามด้วยขนาดโตที่วัดได้หลังกลึง แล้วกด MEASURE: เครื่องคำนวณค่าออฟเซตรูปทรงของแถวที่เลือกจากตำแหน่งเครื่อง</translation>
    </message>
    <message>
        <source>Type X or Z and a correction (X-0.04), then +INPUT: it is added to the wear of the selected row</source>
        <translation>พิมพ์ X หรือ Z ตามด้วยค่าแก้ (X-0.04) แล้วกด +INPUT: ค่าจะถูกบวกเข้ากับค่าสึกหรอของแถวที่เลือก</translation>
    </message>
    <message>
        <source>Type Z0 with the tool on the face: the work shift Z is set from the selected tool's geometry</source>
        <translation>พิมพ์ Z0 เมื่อมีดแตะผิวหน้า: ค่าเลื่อนศูนย์งาน Z คำนวณจากค่าออฟเซตรูปทรงของมีดที่เลือก</translation>
    </message>
    <message>
        <source>Measure the bar's diameter at this Z with the micrometer</source>
        <translation>วัดขนาดโตของชิ้นงานที่ตำแหน่ง Z นี้ด้วยไมโครมิเตอร์</translation>
    </message>
    <message>
        <source>Micrometer</source>
        <translation>ไมโครมิเตอร์</translation>
    </message>
    <message>
        <source>Touch off: spindle on, touch the face, type Z0, MEASURE; skim a diameter, back off in Z only, stop the spindle, measure it, type X and the diameter, MEASURE. Row = the station (T0101).</source>
        <translation>การตั้งศูนย์มีด: เปิดเพลาจับงาน แตะผิวหน้า พิมพ์ Z0 กด MEASURE; กลึงผิวขนาดโตบาง ๆ ถอยออกทางแกน Z เท่านั้น หยุดเพลาจับงาน วัดขนาดโต พิมพ์ X ตามด้วยขนาดโต กด MEASURE แถว = หมายเลขสถานีมีด (T0101)</translation>
    </message>
    <message>
        <source>MDI mode: type one or more blocks, then CYCLE START. They run with the same check, interpreter and cut as a program; the modal state carries on to the next blocks.</source>
        <translation>โหมด MDI: พิมพ์หนึ่งบล็อกหรือมากกว่า แล้วกด CYCLE START บล็อกจะถูกตรวจ แปลคำสั่ง และจำลองการตัดแบบเดียวกับโปรแกรม สถานะโมดอลจะคงอยู่ต่อไปยังบล็อกถัดไป</translation>
    </message>
    <message>
        <source>Geometry and wear offsets, X as a diameter; the selected row takes MEASURE and +INPUT</source>
        <translation>ค่าออฟเซตรูปทรงและค่าสึกหรอ แกน X เป็นขนาดโต แถวที่เลือกจะรับค่าจาก MEASURE และ +INPUT</translation>
    </message>
    <message>
        <source> (MDI line %1, column %2)</source>
        <translation> (MDI บรรทัด %1 คอลัมน์ %2)</translation>
    </message>
    <message>
        <source>Not returned to the reference point yet</source>
        <translation>ยังไม่ได้กลับสู่จุดอ้างอิง</translation>
    </message>
    <message>
        <source>Cycle time at these overrides: %1 (at 100 %: %2)</source>
        <translation>เวลาทำงานเมื่อปรับค่าแบบนี้: %1 (ที่ 100 %: %2)</translation>
    </message>
    <message>
        <source>Run the program once to see its cycle time at these overrides.</source>
        <translation>รันโปรแกรมหนึ่งครั้งเพื่อดูเวลาทำงานเมื่อปรับค่าแบบนี้</translation>
    </message>
    <message>
        <source>Exercise: the offsets are unknown</source>
        <translation>แบบฝึกหัด: ไม่รู้ค่าออฟเซต</translation>
    </message>
    <message>
        <source>Every geometry offset starts at 0: each tool the program uses must be touched off before cycle start, and cycle start then says how far the entries are from the true tools and saves them beside the program for grading. A job file with (OFFSETS: UNKNOWN) at its head starts in the exercise.</source>
        <translation>ค่าออฟเซตรูปทรงทุกแถวเริ่มที่ 0: ต้องตั้งศูนย์มีดทุกตัวที่โปรแกรมใช้ก่อนกด CYCLE START แล้วเครื่องจะบอกว่าค่าที่ป้อนคลาดจากมีดจริงเท่าใด และบันทึกค่าไว้ข้างไฟล์โปรแกรมเพื่อให้ครูตรวจ ไฟล์งานที่มี (OFFSETS: UNKNOWN) ที่หัวโปรแกรมจะเริ่มในแบบฝึกหัดนี้ทันที</translation>
    </message>
    <message>
        <source>CHIPS</source>
        <translation>มีเศษตัด</translation>
    </message>
    <message>
        <source>Touch-off saved for grading: %1</source>
        <translation>บันทึกค่าตั้งศูนย์มีดไว้ให้ตรวจแล้ว: %1</translation>
    </message>
    <message>
        <source>Touch-off not saved (%1): %2</source>
        <translation>บันทึกค่าตั้งศูนย์มีดไม่ได้ (%1): %2</translation>
    </message>
    <message>
        <source>FEED HOLD: the axes stop, the spindle keeps turning; CYCLE START in MEM resumes</source>
        <translation>FEED HOLD: แกนหยุดเคลื่อนที่ เพลาจับงานยังหมุนอยู่ กด CYCLE START ในโหมด MEM เพื่อทำงานต่อ</translation>
    </message>
    <message>
        <source>FEED HOLD: no program is moving</source>
        <translation>FEED HOLD: ไม่มีโปรแกรมที่กำลังเคลื่อนที่</translation>
    </message>
    <message>
        <source>Feed hold: a running program's axes decelerate and stop, the spindle keeps turning; CYCLE START resumes</source>
        <translation>หยุดป้อนชั่วคราว: แกนของโปรแกรมที่กำลังทำงานจะลดความเร็วจนหยุด เพลาจับงานยังหมุนอยู่ กด CYCLE START เพื่อทำงานต่อ</translation>
    </message>
</context>
</TS>
