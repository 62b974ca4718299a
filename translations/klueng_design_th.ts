<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="th_TH">
<context>
    <name>klueng::gui::PartDesignerDialog</name>
    <message>
        <source>%1 cannot be used:</source>
        <translation>ใช้ %1 ไม่ได้:</translation>
    </message>
    <message>
        <source>%1 is drawn for a bar %2.</source>
        <translation>%1 ออกแบบไว้สำหรับชิ้นงานดิบ %2</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>เพิ่ม%1</translation>
    </message>
    <message>
        <source>Bar from Job details: %1, %2</source>
        <translation>ชิ้นงานดิบจากรายละเอียดงาน: %1, %2</translation>
    </message>
    <message>
        <source>Cannot read %1</source>
        <translation>อ่าน %1 ไม่ได้</translation>
    </message>
    <message>
        <source>Cannot save %1: %2</source>
        <translation>บันทึก %1 ไม่ได้: %2</translation>
    </message>
    <message>
        <source>Import DXF</source>
        <translation>นำเข้าแบบ DXF</translation>
    </message>
    <message>
        <source>Move down</source>
        <translation>เลื่อนลง</translation>
    </message>
    <message>
        <source>Move up</source>
        <translation>เลื่อนขึ้น</translation>
    </message>
    <message>
        <source>Open %1</source>
        <translation>เปิด %1</translation>
    </message>
    <message>
        <source>Open a part</source>
        <translation>เปิดแบบชิ้นงาน</translation>
    </message>
    <message>
        <source>Part designer</source>
        <translation>ออกแบบชิ้นงาน</translation>
    </message>
    <message>
        <source>Part files (*.json)</source>
        <translation>ไฟล์แบบชิ้นงาน (*.json)</translation>
    </message>
    <message>
        <source>Parts and drawings (*.json *.dxf);;All files (*)</source>
        <translation>แบบชิ้นงานและแบบ DXF (*.json *.dxf);;ทุกไฟล์ (*)</translation>
    </message>
    <message>
        <source>Remove %1</source>
        <translation>ลบ%1</translation>
    </message>
    <message>
        <source>Save the part</source>
        <translation>บันทึกแบบชิ้นงาน</translation>
    </message>
    <message>
        <source>The cut part differs from the drawing:</source>
        <translation>ชิ้นงานที่กลึงได้ไม่ตรงตามแบบ:</translation>
    </message>
    <message>
        <source>The cut part matches the drawing within 0.01 mm.</source>
        <translation>ชิ้นงานที่กลึงได้ตรงตามแบบภายใน 0.01 มม.</translation>
    </message>
    <message>
        <source>The generated program does not run:</source>
        <translation>โปรแกรมที่สร้างขึ้นทำงานไม่ได้:</translation>
    </message>
    <message>
        <source>The layer of the part's outline:</source>
        <translation>เลเยอร์ที่เป็นรูปร่างของชิ้นงาน:</translation>
    </message>
    <message>
        <source>This part cannot be turned this way:</source>
        <translation>ชิ้นงานนี้กลึงแบบนี้ไม่ได้:</translation>
    </message>
    <message>
        <source>no material given</source>
        <translation>ไม่ได้ระบุวัสดุ</translation>
    </message>
    <message>
        <source>3D</source>
        <translation>3 มิติ</translation>
    </message>
    <message>
        <source>Add a feature: a cylinder, taper or arc outside, a bore step, a groove or a thread</source>
        <translation>เพิ่มรูปร่าง: ทรงกระบอก เรียว หรือส่วนโค้งด้านนอก ขั้นรูคว้าน ร่อง หรือเกลียว</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>เพิ่ม</translation>
    </message>
    <message>
        <source>Aluminium</source>
        <translation>อะลูมิเนียม</translation>
    </message>
    <message>
        <source>Brass</source>
        <translation>ทองเหลือง</translation>
    </message>
    <message>
        <source>Carbide</source>
        <translation>คาร์ไบด์</translation>
    </message>
    <message>
        <source>Cast iron</source>
        <translation>เหล็กหล่อ</translation>
    </message>
    <message>
        <source>Classic (1999)</source>
        <translation>แบบดั้งเดิม (1999)</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>ปิด</translation>
    </message>
    <message>
        <source>Create program</source>
        <translation>สร้างโปรแกรม</translation>
    </message>
    <message>
        <source>Dialect:</source>
        <translation>ภาษาเครื่อง:</translation>
    </message>
    <message>
        <source>Drag to turn, right-drag to move, wheel to zoom, double-click for the first view</source>
        <translation>ลากเพื่อหมุน ลากปุ่มขวาเพื่อเลื่อน หมุนล้อเพื่อซูม ดับเบิลคลิกเพื่อกลับมุมมองแรก</translation>
    </message>
    <message>
        <source>Drawing</source>
        <translation>แบบ</translation>
    </message>
    <message>
        <source>HSS</source>
        <translation>ไฮสปีด (HSS)</translation>
    </message>
    <message>
        <source>Job details...</source>
        <translation>รายละเอียดงาน...</translation>
    </message>
    <message>
        <source>Material:</source>
        <translation>วัสดุ:</translation>
    </message>
    <message>
        <source>Move the feature toward the chuck</source>
        <translation>เลื่อนรูปร่างไปทางหัวจับ</translation>
    </message>
    <message>
        <source>Move the feature toward the face</source>
        <translation>เลื่อนรูปร่างไปทางหน้างาน</translation>
    </message>
    <message>
        <source>Open a part file (JSON) or import a DXF drawing of the half section</source>
        <translation>เปิดไฟล์แบบชิ้นงาน (JSON) หรือนำเข้าแบบ DXF ของรูปตัดครึ่ง</translation>
    </message>
    <message>
        <source>Open the generated program in the editor as a new file</source>
        <translation>เปิดโปรแกรมที่สร้างในหน้าต่างแก้ไขเป็นไฟล์ใหม่</translation>
    </message>
    <message>
        <source>Open...</source>
        <translation>เปิด...</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>ทำซ้ำ</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>ลบ</translation>
    </message>
    <message>
        <source>Save the part as a part file (JSON)</source>
        <translation>บันทึกเป็นไฟล์แบบชิ้นงาน (JSON)</translation>
    </message>
    <message>
        <source>Save...</source>
        <translation>บันทึก...</translation>
    </message>
    <message>
        <source>Steel</source>
        <translation>เหล็ก</translation>
    </message>
    <message>
        <source>Tool:</source>
        <translation>มีด:</translation>
    </message>
    <message>
        <source>Undo the last change to the part</source>
        <translation>เลิกทำการแก้ไขแบบชิ้นงานครั้งล่าสุด</translation>
    </message>
    <message>
        <source>Part off</source>
        <translation>ตัดขาด</translation>
    </message>
    <message>
        <source>Cut the part off the bar at its left end with the parting tool (T07)</source>
        <translation>ตัดชิ้นงานออกจากชิ้นงานดิบที่ปลายด้านซ้ายด้วยมีดตัดขาด (T07)</translation>
    </message>
    <message>
        <source>Use this bar</source>
        <translation>ใช้ชิ้นงานดิบนี้</translation>
    </message>
</context>
<context>
    <name>klueng::gui::DesignTableModel</name>
    <message>
        <source>A thread's pitch, mm (ISO metric)</source>
        <translation>ระยะพิตช์ของเกลียว มม. (เกลียวเมตริก ISO)</translation>
    </message>
    <message>
        <source>An arc's radius, mm: positive bulges out of the part, negative is hollow</source>
        <translation>รัศมีส่วนโค้ง มม.: ค่าบวกโค้งนูนออก ค่าลบโค้งเว้า</translation>
    </message>
    <message>
        <source>Arc R</source>
        <translation>รัศมีโค้ง R</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>ส่วนโค้ง</translation>
    </message>
    <message>
        <source>Bore taper</source>
        <translation>รูคว้านเรียว</translation>
    </message>
    <message>
        <source>Bore</source>
        <translation>รูคว้าน</translation>
    </message>
    <message>
        <source>Corner</source>
        <translation>มุม</translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation>ทรงกระบอก</translation>
    </message>
    <message>
        <source>Diameter, mm (a taper's or arc's at its left end; a groove's at its bottom)</source>
        <translation>เส้นผ่านศูนย์กลาง มม. (เรียวหรือส่วนโค้ง: ที่ปลายด้านซ้าย ร่อง: ที่ก้นร่อง)</translation>
    </message>
    <message>
        <source>Edit %1 %2</source>
        <translation>แก้ไข%1 %2</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>รูปร่าง</translation>
    </message>
    <message>
        <source>Groove</source>
        <translation>ร่อง</translation>
    </message>
    <message>
        <source>Length along Z, mm (a groove's width)</source>
        <translation>ความยาวตามแกน Z มม. (ร่อง: ความกว้าง)</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>ความยาว</translation>
    </message>
    <message>
        <source>Pitch</source>
        <translation>พิตช์</translation>
    </message>
    <message>
        <source>Taper</source>
        <translation>เรียว</translation>
    </message>
    <message>
        <source>The arc's radius; negative for a hollow arc</source>
        <translation>รัศมีส่วนโค้ง ค่าลบสำหรับโค้งเว้า</translation>
    </message>
    <message>
        <source>The right-hand corner: C3 is a 45° chamfer of 3 mm, R2 a round of 2 mm; empty for a sharp corner</source>
        <translation>มุมด้านขวา: C3 คือลบมุม 45° ขนาด 3 มม. R2 คือมุมโค้งรัศมี 2 มม. เว้นว่างสำหรับมุมคม</translation>
    </message>
    <message>
        <source>Thread</source>
        <translation>เกลียว</translation>
    </message>
    <message>
        <source>Z of a groove's right wall or a thread's right end; the steps' Z are worked out</source>
        <translation>Z ของผนังขวาของร่องหรือปลายขวาของเกลียว ส่วน Z ของขั้นคำนวณให้</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>Ø mm</source>
        <translation>Ø มม.</translation>
    </message>
</context>
<context>
    <name>klueng::gui::MainWindow</name>
    <message>
        <source>Part &amp;Designer...</source>
        <translation>&amp;ออกแบบชิ้นงาน...</translation>
    </message>
    <message>
        <source>Draw a turned part and get its program, checked by cutting it</source>
        <translation>ออกแบบชิ้นงานกลึงแล้วได้โปรแกรมที่ตรวจสอบด้วยการจำลองกลึงแล้ว</translation>
    </message>
</context>
</TS>
