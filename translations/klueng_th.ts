<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="th_TH">
<context>
    <name>klueng::gui::CodeEditor</name>
    <message>
        <source>(the last time this line ran)</source>
        <translation>(ค่าเมื่อบรรทัดนี้ทำงานครั้งล่าสุด)</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="278" />
        <source>&lt;b&gt;%1&lt;/b&gt;: not a code of this dialect</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: ไม่มีรหัสนี้ในภาษาจีโค้ดแบบที่เลือก</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="287" />
        <source>X position (diameter)</source>
        <translation>ตำแหน่งแกน X (เส้นผ่านศูนย์กลาง)</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="288" />
        <source>Z position</source>
        <translation>ตำแหน่งแกน Z</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="289" />
        <source>incremental X move (diameter)</source>
        <translation>ระยะเคลื่อนที่แกน X แบบสัมพัทธ์ (เส้นผ่านศูนย์กลาง)</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="290" />
        <source>incremental Z move</source>
        <translation>ระยะเคลื่อนที่แกน Z แบบสัมพัทธ์</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="291" />
        <source>arc centre in X from the start point (radius)</source>
        <translation>จุดศูนย์กลางส่วนโค้งในแนวแกน X วัดจากจุดเริ่ม (รัศมี)</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="292" />
        <source>arc centre in Z from the start point</source>
        <translation>จุดศูนย์กลางส่วนโค้งในแนวแกน Z วัดจากจุดเริ่ม</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="293" />
        <source>arc radius or cycle value</source>
        <translation>รัศมีส่วนโค้ง หรือค่าของวัฏจักรการกลึง</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="294" />
        <source>feed rate (mm/rev under G99, mm/min under G98, lead for G32)</source>
        <translation>อัตราป้อน (มม./รอบ เมื่อใช้ G99, มม./นาที เมื่อใช้ G98, ระยะพิตช์เกลียวสำหรับ G32)</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="295" />
        <source>spindle speed (rpm under G97, m/min under G96)</source>
        <translation>ความเร็วรอบ (รอบ/นาที เมื่อใช้ G97, ม./นาที เมื่อใช้ G96)</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="296" />
        <source>tool number (first two digits) and offset number (last two)</source>
        <translation>หมายเลขมีดตัด (สองหลักแรก) และหมายเลขค่าออฟเซต (สองหลักหลัง)</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="297" />
        <source>sequence (block) number</source>
        <translation>หมายเลขบล็อก</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="298" />
        <source>program number</source>
        <translation>หมายเลขโปรแกรม</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="299" />
        <source>spindle angle in C-axis mode (absolute, degrees)</source>
        <translation>มุมของเพลาหัวจับในโหมดควบคุมการเคลื่อนที่ของแกน C (ค่าสัมบูรณ์, องศา)</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="300" />
        <source>spindle angle in C-axis mode (incremental, degrees)</source>
        <translation>มุมของเพลาหัวจับในโหมดควบคุมการเคลื่อนที่ของแกน C (ค่าสัมพัทธ์, องศา)</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="301" />
        <source>dwell time in ms, or a cycle/subprogram parameter</source>
        <translation>เวลาหยุดรอ (มิลลิวินาที) หรือค่าพารามิเตอร์ของวัฏจักร/โปรแกรมย่อย</translation>
    </message>
    <message>
        <location filename="../src/gui/code_editor.cpp" line="302" />
        <source>cycle parameter</source>
        <translation>ค่าพารามิเตอร์ของวัฏจักรการกลึง</translation>
    </message>
</context>
<context>
    <name>klueng::gui::DiagnosticsModel</name>
    <message>
        <location filename="../src/gui/diagnostics_panel.cpp" line="60" />
        <source>Kind</source>
        <translation>ประเภท</translation>
    </message>
    <message>
        <location filename="../src/gui/diagnostics_panel.cpp" line="61" />
        <source>Code</source>
        <translation>รหัส</translation>
    </message>
    <message>
        <location filename="../src/gui/diagnostics_panel.cpp" line="62" />
        <source>Line</source>
        <translation>บรรทัด</translation>
    </message>
    <message>
        <location filename="../src/gui/diagnostics_panel.cpp" line="63" />
        <source>Column</source>
        <translation>คอลัมน์</translation>
    </message>
    <message>
        <location filename="../src/gui/diagnostics_panel.cpp" line="64" />
        <source>Message</source>
        <translation>ข้อความ</translation>
    </message>
</context>
<context>
    <name>klueng::gui::DiagnosticsPanel</name>
    <message>
        <location filename="../src/gui/diagnostics_panel.cpp" line="116" />
        <source>Diagnostics: no errors</source>
        <translation>การตรวจสอบไวยากรณ์: ไม่มีข้อผิดพลาด</translation>
    </message>
    <message>
        <location filename="../src/gui/diagnostics_panel.cpp" line="117" />
        <source>Diagnostics: %1 errors, %2 warnings</source>
        <translation>การตรวจสอบไวยากรณ์: ข้อผิดพลาด %1 รายการ, คำเตือน %2 รายการ</translation>
    </message>
    <message>
        <source>Diagnostics: %1, %2</source>
        <translation>การตรวจสอบไวยากรณ์: %1, %2</translation>
    </message>
    <message>
        <source>1 error</source>
        <translation>ข้อผิดพลาด 1 รายการ</translation>
    </message>
    <message>
        <source>%1 errors</source>
        <translation>ข้อผิดพลาด %1 รายการ</translation>
    </message>
    <message>
        <source>1 warning</source>
        <translation>คำเตือน 1 รายการ</translation>
    </message>
    <message>
        <source>%1 warnings</source>
        <translation>คำเตือน %1 รายการ</translation>
    </message>
</context>
<context>
    <name>klueng::gui::Document</name>
    <message>
        <location filename="../src/gui/document.cpp" line="66" />
        <source>untitled.txt</source>
        <translation>ไม่มีชื่อ.txt</translation>
    </message>
</context>
<context>
    <name>klueng::gui::FindDialog</name>
    <message>
        <location filename="../src/gui/find_dialog.cpp" line="87" />
        <source>"%1" was not found.</source>
        <translation>ไม่พบ "%1"</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/gui/find_dialog.cpp" line="119" />
        <source>%n replacement(s) made.</source>
        <translation><numerusform>แทนที่แล้ว %n ตำแหน่ง</numerusform></translation>
    </message>
    <message>
        <location filename="../src/gui/find_dialog.cpp" line="124" />
        <source>Find and Replace</source>
        <translation>ค้นหาและแทนที่</translation>
    </message>
    <message>
        <location filename="../src/gui/find_dialog.cpp" line="125" />
        <source>&amp;Find:</source>
        <translation>ค้นหา (&amp;F):</translation>
    </message>
    <message>
        <location filename="../src/gui/find_dialog.cpp" line="126" />
        <source>Replace &amp;with:</source>
        <translation>แทนที่ด้วย (&amp;W):</translation>
    </message>
    <message>
        <location filename="../src/gui/find_dialog.cpp" line="127" />
        <source>Match &amp;case</source>
        <translation>ตรงตามตัวพิมพ์ใหญ่-เล็ก (&amp;C)</translation>
    </message>
    <message>
        <location filename="../src/gui/find_dialog.cpp" line="128" />
        <source>Whole &amp;words</source>
        <translation>ทั้งคำ (&amp;W)</translation>
    </message>
    <message>
        <location filename="../src/gui/find_dialog.cpp" line="129" />
        <source>Find &amp;Next</source>
        <translation>ค้นหาถัดไป (&amp;N)</translation>
    </message>
    <message>
        <location filename="../src/gui/find_dialog.cpp" line="130" />
        <source>Find &amp;Previous</source>
        <translation>ค้นหาก่อนหน้า (&amp;P)</translation>
    </message>
    <message>
        <location filename="../src/gui/find_dialog.cpp" line="131" />
        <source>&amp;Replace</source>
        <translation>แทนที่ (&amp;R)</translation>
    </message>
    <message>
        <location filename="../src/gui/find_dialog.cpp" line="132" />
        <source>Replace &amp;All</source>
        <translation>แทนที่ทั้งหมด (&amp;A)</translation>
    </message>
    <message>
        <location filename="../src/gui/find_dialog.cpp" line="133" />
        <source>Close</source>
        <translation>ปิด</translation>
    </message>
</context>
<context>
    <name>klueng::gui::HelpContents</name>
    <message>
        <source>+X up, +Z right; red dot = imaginary tip</source>
        <translation>+X ขึ้น, +Z ขวา; จุดแดง = ปลายมีดสมมติ</translation>
    </message>
    <message>
        <source>Imaginary tool tip numbers 0-9</source>
        <translation>หมายเลขปลายมีดสมมติ 0-9</translation>
    </message>
    <message>
        <source>Offset define gives each tool nose its tip number T: where the imaginary tip lies from the nose centre. Nose radius compensation (G41/G42) needs it: an outside turning tool is 3, a boring bar 2.</source>
        <translation>ในหน้ากำหนดออฟเซต จมูกมีดแต่ละตัวมีหมายเลขปลายมีด T บอกว่าปลายมีดสมมติอยู่ทางไหนของจุดศูนย์กลางจมูกมีด การชดเชยรัศมีจมูกมีด (G41/G42) ต้องใช้ค่านี้: มีดกลึงปอกด้านนอกเป็น 3 มีดคว้านเป็น 2</translation>
    </message>
    <message>
        <source>Red: cutting moves; blue dashes: rapids; grey: the bar.</source>
        <translation>เส้นแดง: การเคลื่อนที่ตัดเฉือน เส้นประสีน้ำเงิน: การเคลื่อนที่เร็ว สีเทา: ชิ้นงาน</translation>
    </message>
    <message>
        <source>Worked example</source>
        <translation>ตัวอย่างโปรแกรม</translation>
    </message>
    <message>
        <source>Worked examples</source>
        <translation>ตัวอย่างโปรแกรมที่ใช้งานได้จริง</translation>
    </message>
    <message>
        <source>Each program runs as it is on a bar of 50 x 100 mm with the shipped tools: copy it into the editor and press Go.</source>
        <translation>ทุกโปรแกรมรันได้ทันทีกับชิ้นงานขนาด 50 x 100 มม. และมีดตัดที่ติดมากับโปรแกรม: คัดลอกไปวางในหน้าแก้ไขแล้วกด Go</translation>
    </message>
    <message>
        <source>Search: G71, roughing, กลึงปอกหยาบ ...</source>
        <translation>ค้นหา: G71, กลึงปอกหยาบ, roughing ...</translation>
    </message>
    <message>
        <source>Nothing found</source>
        <translation>ไม่พบรายการที่ค้นหา</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="39" />
        <source>Klueng help: the G and M codes</source>
        <translation>ระบบช่วยเหลือของกลึง: รหัส G และรหัส M</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="41" />
        <source>A program file starts with six lines: project name, part name, material, stock diameter, stock length and programmer. Diameter and length begin with a unit digit (0 = inch, 1 = mm): &lt;tt&gt;150&lt;/tt&gt; is 50 mm. From line 7 on comes the G-code, one block per line.</source>
        <translation>แฟ้มชุดรหัสสั่งการทำงานเริ่มด้วยหกบรรทัด: ชื่องาน, ชื่อชิ้นงาน, วัสดุ, เส้นผ่านศูนย์กลางชิ้นงาน, ความยาวชิ้นงาน และผู้เขียนโปรแกรม เส้นผ่านศูนย์กลางและความยาวขึ้นต้นด้วยเลขบอกหน่วย (0 = นิ้ว, 1 = มม.): &lt;tt&gt;150&lt;/tt&gt; คือ 50 มม. ตั้งแต่บรรทัดที่ 7 เป็นต้นไปคือโปรแกรมจีโค้ด บรรทัดละหนึ่งบล็อก</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="45" />
        <source>A word is a letter followed at once by a number: &lt;tt&gt;X25.4&lt;/tt&gt;, &lt;tt&gt;G1&lt;/tt&gt;, &lt;tt&gt;Z-3&lt;/tt&gt;. X is a diameter. Comments are written in ( ) or after ;. A / at the start of a block skips it when the Block Skip switch is on. A length without a decimal point is whole millimetres (&lt;tt&gt;X30&lt;/tt&gt; = 30 mm) in Klueng's own programs; a program from the shop may be read in least input increments (&lt;tt&gt;X30&lt;/tt&gt; = 0.030 mm) as a standard Fanuc or Haas reads it: the setup strip says which, and Job details changes it.</source>
        <translation>คำสั่งหนึ่งคำคืออักขระตามด้วยตัวเลขทันที: &lt;tt&gt;X25.4&lt;/tt&gt;, &lt;tt&gt;G1&lt;/tt&gt;, &lt;tt&gt;Z-3&lt;/tt&gt; ค่า X เป็นเส้นผ่านศูนย์กลาง หมายเหตุเขียนไว้ใน ( ) หรือหลังเครื่องหมาย ; เครื่องหมาย / หน้าบล็อกจะข้ามบล็อกนั้นเมื่อเปิดสวิตช์ข้ามบล็อก ความยาวที่ไม่มีจุดทศนิยมในโปรแกรมของ Klueng เองมีหน่วยเป็นมิลลิเมตรเต็มหน่วย (&lt;tt&gt;X30&lt;/tt&gt; = 30 มม.) ส่วนโปรแกรมที่นำมาจากโรงงานอาจอ่านเป็นหน่วยป้อนค่าที่เล็กที่สุด (&lt;tt&gt;X30&lt;/tt&gt; = 0.030 มม.) แบบที่เครื่อง Fanuc หรือ Haas ทั่วไปอ่าน แถบการตั้งเครื่องบอกว่าอ่านแบบใด และเปลี่ยนได้ที่รายละเอียดงาน</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="49" />
        <source>Dialect:</source>
        <translation>ภาษาจีโค้ด:</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="49" />
        <source>Fanuc 0i-TF</source>
        <translation>Fanuc 0i-TF</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="49" />
        <source>Rook classic</source>
        <translation>Rook แบบดั้งเดิม</translation>
    </message>
    <message>
        <source>Haas ST (NGC)</source>
        <translation>เครื่องกลึง Haas ST (NGC)</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="52" />
        <source>G codes (preparatory functions)</source>
        <translation>รหัส G (คำสั่งเตรียมการ)</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="53" />
        <source>M codes (miscellaneous functions)</source>
        <translation>รหัส M (คำสั่งช่วย)</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="56" />
        <source>Code</source>
        <translation>รหัส</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="56" />
        <source>Meaning</source>
        <translation>ความหมาย</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="56" />
        <source>Example</source>
        <translation>ตัวอย่าง</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="66" />
        <source>not in this dialect</source>
        <translation>ไม่มีในภาษาจีโค้ดแบบนี้</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="75" />
        <source>Running a program</source>
        <translation>การจำลองการทำงานของชุดรหัสสั่งการทำงาน</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="76" />
        <source>F5 Go runs the program, F10 Step runs one block, Pause waits after the current step, Stop resets. F9 sets a breakpoint on the cursor's line; Run to cursor stops at the cursor's block. Every error is underlined in the editor and listed below it; click one to jump to it.</source>
        <translation>F5 เริ่มทำงานจนจบ, F10 ทำงานทีละบรรทัด, หยุดชั่วคราวจะรอหลังบล็อกปัจจุบัน, หยุดจะยกเลิกและเริ่มใหม่ F9 ตั้งจุดหยุดที่บรรทัดของเคอร์เซอร์ ทำงานถึงเคอร์เซอร์จะหยุดที่บล็อกของเคอร์เซอร์ ข้อผิดพลาดทุกรายการมีเส้นขีดใต้ในหน้าต่างแก้ไขและแสดงในรายการด้านล่าง คลิกเพื่อไปยังตำแหน่งนั้น</translation>
    </message>
    <message>
        <location filename="../src/gui/help_contents.cpp" line="85" />
        <source>Help Contents</source>
        <translation>เนื้อหาระบบช่วยเหลือ</translation>
    </message>
</context>
<context>
    <name>klueng::gui::MainWindow</name>
    <message>
        <source>Autosave failed: %1</source>
        <translation>บันทึกอัตโนมัติไม่สำเร็จ: %1</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>เลิกทำ %1 (&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>ทำซ้ำ %1 (&amp;R)</translation>
    </message>
    <message>
        <source>Job Details</source>
        <translation>รายละเอียดงาน</translation>
    </message>
    <message>
        <source>Tool Select</source>
        <translation>เลือกมีดตัด</translation>
    </message>
    <message>
        <source>Offset Define</source>
        <translation>กำหนดค่าออฟเซต</translation>
    </message>
    <message>
        <source>The machine setup has errors:</source>
        <translation>ไฟล์ตั้งค่าเครื่องมีข้อผิดพลาด:</translation>
    </message>
    <message>
        <source>Cannot save over this file</source>
        <translation>บันทึกทับไฟล์นี้ไม่ได้</translation>
    </message>
    <message>
        <source>Line %1 of "%2" is too long to edit, so it is not in the editor. Saving over the file would delete it: use Save As to write your version to another file.</source>
        <translation>บรรทัดที่ %1 ของ "%2" ยาวเกินกว่าจะแก้ไขได้ จึงไม่ได้แสดงในหน้าต่างแก้ไข การบันทึกทับไฟล์จะทำให้บรรทัดนั้นหายไป ให้ใช้ "บันทึกเป็น" เพื่อบันทึกเป็นไฟล์ใหม่</translation>
    </message>
    <message>
        <source>vacant (the address was left out)</source>
        <translation>ว่าง (ไม่ได้ใช้ตำแหน่งนี้)</translation>
    </message>
    <message>
        <source>Step &amp;Into</source>
        <translation>ทำงานเข้าไปใน&amp;โปรแกรมย่อย</translation>
    </message>
    <message>
        <source>Step O&amp;ut</source>
        <translation>ทำงานจนออกจาก&amp;โปรแกรมย่อย</translation>
    </message>
    <message>
        <source>Run one block, then wait (a subprogram or macro call runs whole)</source>
        <translation>ทำงานหนึ่งบล็อกแล้วรอ (การเรียกโปรแกรมย่อยหรือมาโครจะทำงานจนจบในครั้งเดียว)</translation>
    </message>
    <message>
        <source>Run one block, into a subprogram or macro it calls</source>
        <translation>ทำงานหนึ่งบล็อก โดยเข้าไปทีละบล็อกในโปรแกรมย่อยหรือมาโครที่ถูกเรียก</translation>
    </message>
    <message>
        <source>Run to the end of this subprogram or macro</source>
        <translation>ทำงานจนจบโปรแกรมย่อยหรือมาโครนี้แล้วกลับไปยังโปรแกรมที่เรียก</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="56" />
        <source>As fast as possible</source>
        <translation>เร็วที่สุด</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="57" />
        <source>1× (real time)</source>
        <translation>1× (เวลาจริงของเครื่อง)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="58" />
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="462" />
        <source>&amp;File</source>
        <translation>แฟ้ม (&amp;F)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="463" />
        <source>&amp;Recent Files</source>
        <translation>แฟ้มที่ใช้ล่าสุด (&amp;R)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="464" />
        <source>&amp;Edit</source>
        <translation>แก้ไข (&amp;E)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="465" />
        <source>&amp;Run</source>
        <translation>การทำงาน (&amp;R)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="466" />
        <source>S&amp;peed</source>
        <translation>ความเร็วการจำลอง (&amp;P)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="467" />
        <source>&amp;Tool setting</source>
        <translation>ตั้งค่ามีดตัด (&amp;T)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="468" />
        <source>G-code &amp;dialect</source>
        <translation>ภาษาจีโค้ด (&amp;D)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="469" />
        <source>&amp;View</source>
        <translation>มุมมอง (&amp;V)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="470" />
        <source>&amp;Help</source>
        <translation>ช่วยเหลือ (&amp;H)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="472" />
        <source>&amp;New</source>
        <translation>สร้างใหม่ (&amp;N)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="472" />
        <source>Start a new program</source>
        <translation>เริ่มชุดรหัสสั่งการทำงานใหม่</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="473" />
        <source>&amp;Open...</source>
        <translation>เปิด... (&amp;O)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="473" />
        <source>Open a program file</source>
        <translation>เปิดแฟ้มชุดรหัสสั่งการทำงาน</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="474" />
        <location filename="../src/gui/main_window.cpp" line="597" />
        <source>&amp;Save</source>
        <translation>บันทึก (&amp;S)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="474" />
        <source>Save the program</source>
        <translation>บันทึกชุดรหัสสั่งการทำงาน</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="475" />
        <source>Save &amp;As...</source>
        <translation>บันทึกเป็น... (&amp;A)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="475" />
        <source>Save the program under a new name</source>
        <translation>บันทึกชุดรหัสสั่งการทำงานด้วยชื่อใหม่</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="476" />
        <source>&amp;Job details...</source>
        <translation>รายละเอียดงาน... (&amp;J)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="476" />
        <source>Project, part, material, stock size and programmer</source>
        <translation>ชื่องาน ชิ้นงาน วัสดุ ขนาดชิ้นงาน และผู้เขียนโปรแกรม</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="477" />
        <source>E&amp;xit</source>
        <translation>ออกจากโปรแกรม (&amp;X)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="478" />
        <source>&amp;Undo</source>
        <translation>เลิกทำ (&amp;U)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="479" />
        <source>&amp;Redo</source>
        <translation>ทำซ้ำ (&amp;R)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="480" />
        <source>Cu&amp;t</source>
        <translation>ตัด (&amp;T)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="481" />
        <source>&amp;Copy</source>
        <translation>คัดลอก (&amp;C)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="482" />
        <source>&amp;Paste</source>
        <translation>วาง (&amp;P)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="483" />
        <source>&amp;Delete</source>
        <translation>ลบ (&amp;D)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="484" />
        <source>Select &amp;All</source>
        <translation>เลือกทั้งหมด (&amp;A)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="485" />
        <source>&amp;Find...</source>
        <translation>ค้นหา... (&amp;F)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="485" />
        <source>Find text in the program</source>
        <translation>ค้นหาข้อความในชุดรหัสสั่งการทำงาน</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="486" />
        <source>R&amp;eplace...</source>
        <translation>แทนที่... (&amp;E)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="486" />
        <source>Find and replace text</source>
        <translation>ค้นหาและแทนที่ข้อความ</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="487" />
        <source>&amp;Go to Line...</source>
        <translation>ไปยังบรรทัด... (&amp;G)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="488" />
        <source>&amp;Go</source>
        <translation>เริ่มทำงาน (&amp;G)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="488" />
        <source>Run the program continuously</source>
        <translation>จำลองการทำงานต่อเนื่องจนจบ</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="489" />
        <source>&amp;Step</source>
        <translation>ทำงานทีละบรรทัด (&amp;S)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="489" />
        <source>Run one block, then wait</source>
        <translation>ทำงานหนึ่งบล็อกแล้วรอ</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="490" />
        <source>&amp;Pause</source>
        <translation>หยุดชั่วคราว (&amp;P)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="490" />
        <source>Stop after the current step; Go or Step resumes</source>
        <translation>หยุดหลังบล็อกปัจจุบัน กดเริ่มทำงานหรือทำงานทีละบรรทัดเพื่อทำต่อ</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="491" />
        <source>S&amp;top</source>
        <translation>หยุด (&amp;T)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="491" />
        <source>Abort the run and reset</source>
        <translation>ยกเลิกการทำงานและเริ่มต้นใหม่</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="492" />
        <source>Step &amp;Back</source>
        <translation>ย้อนกลับหนึ่งบล็อก (&amp;B)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="492" />
        <source>Go back one block</source>
        <translation>ถอยกลับไปหนึ่งบล็อก</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="493" />
        <source>Run to &amp;Cursor</source>
        <translation>ทำงานถึงเคอร์เซอร์ (&amp;C)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="493" />
        <source>Run up to the block at the cursor</source>
        <translation>ทำงานจนถึงบล็อกที่เคอร์เซอร์อยู่</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="494" />
        <source>Toggle &amp;Breakpoint</source>
        <translation>ตั้ง/ยกเลิกจุดหยุด (&amp;B)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="494" />
        <source>Stop the run before this line</source>
        <translation>หยุดการทำงานก่อนบรรทัดนี้</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="495" />
        <source>&amp;Optional Stop</source>
        <translation>ทางเลือกการหยุด (&amp;O)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="495" />
        <source>M01 stops the run when this switch is on</source>
        <translation>M01 จะหยุดการทำงานเมื่อเปิดสวิตช์นี้</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="496" />
        <source>Block S&amp;kip</source>
        <translation>ข้ามบล็อก (&amp;K)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="496" />
        <source>Blocks starting with / are skipped when this switch is on</source>
        <translation>บล็อกที่ขึ้นต้นด้วย / จะถูกข้ามเมื่อเปิดสวิตช์นี้</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="497" />
        <source>Tool &amp;Select...</source>
        <translation>เลือกมีดตัด... (&amp;S)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="497" />
        <source>Choose the bitmap of each tool 01-08</source>
        <translation>เลือกภาพบิตแมปของมีดตัดหมายเลข 01-08</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="498" />
        <source>Offset &amp;Define...</source>
        <translation>กำหนดค่าออฟเซต... (&amp;D)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="498" />
        <source>Edit the 16 tool offsets</source>
        <translation>แก้ไขค่าออฟเซตของมีดตัดทั้ง 16 ชุด</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="499" />
        <source>&amp;Fanuc 0i-TF</source>
        <translation>Fanuc 0i-TF (&amp;F)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="500" />
        <source>&amp;Rook classic (1999 rules)</source>
        <translation>Rook แบบดั้งเดิม (กฎปี 1999) (&amp;R)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="521" />
        <source>&amp;Haas ST lathe (NGC)</source>
        <translation>เครื่องกลึง Haas ST (NGC) (&amp;H)</translation>
    </message>
    <message>
        <source>Power-on units as the &amp;machine (Haas: inch)</source>
        <translation>หน่วยเมื่อเปิดเครื่องตามเครื่องจักร (Haas: นิ้ว) (&amp;M)</translation>
    </message>
    <message>
        <source>&amp;Power-on units: millimetres</source>
        <translation>หน่วยเมื่อเปิดเครื่อง: มิลลิเมตร (&amp;P)</translation>
    </message>
    <message>
        <source>Power-on units: &amp;inches</source>
        <translation>หน่วยเมื่อเปิดเครื่อง: นิ้ว (&amp;I)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="501" />
        <source>&amp;Fit to View</source>
        <translation>พอดีหน้าจอ (&amp;F)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="502" />
        <source>Zoom &amp;In</source>
        <translation>ขยาย (&amp;I)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="503" />
        <source>Zoom &amp;Out</source>
        <translation>ย่อ (&amp;O)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="504" />
        <source>Show Tool &amp;Path</source>
        <translation>แสดงเส้นทางเดินมีด (&amp;P)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="505" />
        <source>&amp;Status Bar</source>
        <translation>แถบแสดงสถานะ (&amp;S)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="506" />
        <source>Status &amp;Lamps</source>
        <translation>ไฟแสดงสถานะ (&amp;L)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="507" />
        <source>&amp;Contents</source>
        <translation>เนื้อหาระบบช่วยเหลือ (&amp;C)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="507" />
        <source>Help for self-learners: every G and M code with an example</source>
        <translation>ระบบช่วยเหลือสำหรับผู้เรียนด้วยตนเอง: รหัส G และ M ทุกตัวพร้อมตัวอย่าง</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="508" />
        <source>Toggle &amp;Language (ไทย/English)</source>
        <translation>เปลี่ยนภาษา (ไทย/English) (&amp;L)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="508" />
        <source>Switch between Thai and English</source>
        <translation>สลับระหว่างภาษาไทยและภาษาอังกฤษ</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="509" />
        <source>&amp;About Klueng</source>
        <translation>เกี่ยวกับโปรแกรมกลึง (&amp;A)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="511" />
        <source>File tool bar</source>
        <translation>แถบเครื่องมือแฟ้ม</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="512" />
        <source>Edit tool bar</source>
        <translation>แถบเครื่องมือแก้ไข</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="513" />
        <source>Run tool bar</source>
        <translation>แถบเครื่องมือการทำงาน</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="514" />
        <source>Help tool bar</source>
        <translation>แถบเครื่องมือช่วยเหลือ</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="585" />
        <source>Klueng : %1[*]</source>
        <translation>Klueng : %1[*]</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="594" />
        <source>Unsaved changes</source>
        <translation>มีการแก้ไขที่ยังไม่บันทึก</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="595" />
        <source>The program "%1" has been changed.</source>
        <translation>ชุดรหัสสั่งการทำงาน "%1" ถูกแก้ไข</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="596" />
        <source>Do you want to save your changes?</source>
        <translation>ต้องการบันทึกการแก้ไขหรือไม่?</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="598" />
        <source>&amp;Discard</source>
        <translation>ไม่บันทึก (&amp;D)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="599" />
        <source>Cancel</source>
        <translation>ยกเลิก</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="636" />
        <source>Open program</source>
        <translation>เปิดชุดรหัสสั่งการทำงาน</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="636" />
        <source>Lathe programs (*.txt *.nc *.tap *.cnc *.gc);;All files (*)</source>
        <translation>ชุดรหัสสั่งการทำงานเครื่องกลึง (*.txt *.nc *.tap *.cnc *.gc);;ทุกแฟ้ม (*)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="672" />
        <source>Cannot open the program</source>
        <translation>เปิดชุดรหัสสั่งการทำงานไม่ได้</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="673" />
        <source>"%1" could not be read.</source>
        <translation>อ่านแฟ้ม "%1" ไม่ได้</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="754" />
        <source>Save program as</source>
        <translation>บันทึกชุดรหัสสั่งการทำงานเป็น</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="755" />
        <source>Lathe programs (*.txt *.nc);;All files (*)</source>
        <translation>ชุดรหัสสั่งการทำงานเครื่องกลึง (*.txt *.nc);;ทุกแฟ้ม (*)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="766" />
        <source>Cannot save the program</source>
        <translation>บันทึกชุดรหัสสั่งการทำงานไม่ได้</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="767" />
        <source>"%1" could not be written:
%2</source>
        <translation>เขียนแฟ้ม "%1" ไม่ได้:
%2</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="776" />
        <source>Saved %1</source>
        <translation>บันทึก %1 แล้ว</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="796" />
        <source>File changed on disk</source>
        <translation>แฟ้มถูกเปลี่ยนแปลงบนดิสก์</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="797" />
        <source>"%1" was changed by another program.</source>
        <translation>แฟ้ม "%1" ถูกแก้ไขโดยโปรแกรมอื่น</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="798" />
        <source>Reload it and lose your changes here?</source>
        <translation>โหลดแฟ้มใหม่และทิ้งการแก้ไขในโปรแกรมนี้หรือไม่?</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="798" />
        <source>Reload it?</source>
        <translation>โหลดแฟ้มใหม่หรือไม่?</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="799" />
        <source>&amp;Reload</source>
        <translation>โหลดใหม่ (&amp;R)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="800" />
        <source>&amp;Keep mine</source>
        <translation>ใช้ของฉัน (&amp;K)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="820" />
        <source>(none)</source>
        <translation>(ไม่มี)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="963" />
        <source>Alarm %1 on line %2: %3</source>
        <translation>สัญญาณเตือน %1 ที่บรรทัด %2: %3</translation>
    </message>
    <message numerus="yes">
        <location filename="../src/gui/main_window.cpp" line="973" />
        <source>The program has %n error(s); fix them before running. Click an error below to go to it.</source>
        <translation><numerusform>ชุดรหัสสั่งการทำงานมีข้อผิดพลาด %n รายการ ต้องแก้ไขก่อนจึงจะเริ่มทำงานได้ คลิกข้อผิดพลาดด้านล่างเพื่อไปยังตำแหน่งนั้น</numerusform></translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="1020" />
        <source>Go to Line</source>
        <translation>ไปยังบรรทัด</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="1020" />
        <source>Line (%1-%2):</source>
        <translation>บรรทัด (%1-%2):</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>&amp;Print Code...</source>
        <translation>พิมพ์ชุดรหัสสั่งการทำงาน... (&amp;P)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Print the program sheet: job details and the numbered program</source>
        <translation>พิมพ์เอกสารชุดรหัสสั่งการทำงาน: รายละเอียดงานและโปรแกรมพร้อมเลขบรรทัด</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Print</source>
        <translation>พิมพ์</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Print the program sheet at once on the default printer</source>
        <translation>พิมพ์เอกสารชุดรหัสสั่งการทำงานทันทีที่เครื่องพิมพ์หลัก</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Print &amp;Drawing...</source>
        <translation>พิมพ์ภาพชิ้นงาน... (&amp;D)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Print the finished part to scale with its title block</source>
        <translation>พิมพ์ภาพชิ้นงานที่กลึงเสร็จตามมาตราส่วน พร้อมตารางรายละเอียดงาน</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Print Pre&amp;view...</source>
        <translation>ดูตัวอย่างก่อนพิมพ์... (&amp;V)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Preview the program sheet and the drawing sheet</source>
        <translation>ดูตัวอย่างเอกสารชุดรหัสสั่งการทำงานและเอกสารแสดงภาพชิ้นงาน</translation>
    </message>
    <message>
        <source>&amp;Grade a class...</source>
        <translation>ตรวจงานทั้งชั้นเรียน... (&amp;G)</translation>
    </message>
    <message>
        <source>Grade every program in a folder against a reference program</source>
        <translation>ตรวจทุกโปรแกรมในโฟลเดอร์เทียบกับโปรแกรมต้นแบบ</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>&amp;Export PDF...</source>
        <translation>ส่งออกเป็น PDF... (&amp;E)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Save the program sheet and the drawing sheet as a PDF file</source>
        <translation>บันทึกเอกสารชุดรหัสสั่งการทำงานและเอกสารแสดงภาพชิ้นงานเป็นไฟล์ PDF</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Print Code</source>
        <translation>พิมพ์ชุดรหัสสั่งการทำงาน</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>No printer is set up: use File &gt; Export PDF to save the sheet.</source>
        <translation>ยังไม่ได้ตั้งค่าเครื่องพิมพ์: ใช้ แฟ้ม &gt; ส่งออกเป็น PDF เพื่อบันทึกเอกสาร</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Program sheet sent to %1</source>
        <translation>ส่งเอกสารชุดรหัสสั่งการทำงานไปที่ %1 แล้ว</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Print Drawing</source>
        <translation>พิมพ์ภาพชิ้นงาน</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Print Preview</source>
        <translation>ดูตัวอย่างก่อนพิมพ์</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Export PDF</source>
        <translation>ส่งออกเป็น PDF</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>PDF files (*.pdf)</source>
        <translation>ไฟล์ PDF (*.pdf)</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Cannot write %1</source>
        <translation>เขียนไฟล์ %1 ไม่ได้</translation>
    </message>
    <message>
        <location filename="../src/gui/main_window.cpp" line="0" />
        <source>Exported %1</source>
        <translation>ส่งออก %1 แล้ว</translation>
    </message>
    <message>
        <source>The program ended. Cycle time: %1.</source>
        <translation>จบโปรแกรมแล้ว เวลาทำงาน (cycle time): %1</translation>
    </message>
    <message>
        <source>There is nothing to run: the program has no blocks. Type the program in the editor or open a file.</source>
        <translation>ไม่มีอะไรให้ทำงาน: โปรแกรมไม่มีบล็อกคำสั่ง พิมพ์โปรแกรมในช่องแก้ไข หรือเปิดไฟล์</translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 นาที %2 วินาที</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 วินาที</translation>
    </message>
    <message>
        <source>Z %1   Ø %2   %3</source>
        <translation>Z %1   Ø %2   %3</translation>
    </message>
    <message>
        <source>in</source>
        <translation>นิ้ว</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>มม.</translation>
    </message>
    <message>
        <source>&amp;Auto: the program's units (G20 inch, G21 mm)</source>
        <translation>อัตโนมัติ: ตามหน่วยของโปรแกรม (G20 นิ้ว, G21 มม.) (&amp;A)</translation>
    </message>
    <message>
        <source>Positions, feeds, rulers, features and the drawing in the units the program is written in</source>
        <translation>แสดงตำแหน่ง อัตราป้อน ไม้บรรทัด ลักษณะชิ้นงาน และแบบงาน ในหน่วยที่โปรแกรมใช้เขียน</translation>
    </message>
    <message>
        <source>&amp;Millimetres</source>
        <translation>มิลลิเมตร (&amp;M)</translation>
    </message>
    <message>
        <source>&amp;Inches</source>
        <translation>นิ้ว (&amp;I)</translation>
    </message>
    <message>
        <source>&amp;Units Shown</source>
        <translation>หน่วยที่แสดง (&amp;U)</translation>
    </message>
</context>
<context>
    <name>klueng::gui::FirstStepsBar</name>
    <message>
        <location filename="../src/gui/first_steps_bar.cpp" line="67" />
        <source>&lt;b&gt;What to do first:&lt;/b&gt; 1. open a sample program (sample 01 turns a step shaft); 2. press &lt;b&gt;Go&lt;/b&gt; (F5) and watch the tool cut the bar; 3. click a line of the program to read what it does.</source>
        <translation>&lt;b&gt;เริ่มต้นอย่างไร:&lt;/b&gt; 1. เปิดโปรแกรมตัวอย่าง (ตัวอย่าง 01 กลึงเพลาขั้นบันได) 2. กด &lt;b&gt;เริ่มทำงาน&lt;/b&gt; (F5) แล้วดูมีดกลึงชิ้นงาน 3. คลิกบรรทัดของโปรแกรมเพื่ออ่านว่าบรรทัดนั้นทำอะไร</translation>
    </message>
    <message>
        <location filename="../src/gui/first_steps_bar.cpp" line="70" />
        <source>Open sample 01</source>
        <translation>เปิดตัวอย่าง 01</translation>
    </message>
    <message>
        <location filename="../src/gui/first_steps_bar.cpp" line="71" />
        <source>All samples…</source>
        <translation>ตัวอย่างทั้งหมด…</translation>
    </message>
</context>
<context>
    <name>klueng::gui::DialectOfferBar</name>
    <message>
        <location filename="../src/gui/dialect_offer_bar.cpp" line="85" />
        <source>Blocks in %1 form that the current dialect refuses: %2. The %1 dialect accepts the whole program.</source>
        <translation>บล็อกที่เป็นรูปแบบของ %1 ซึ่งภาษาเครื่องที่เลือกอยู่ไม่รับ: %2 บล็อก ภาษาเครื่อง %1 รับได้ทั้งโปรแกรม</translation>
    </message>
    <message>
        <location filename="../src/gui/dialect_offer_bar.cpp" line="89" />
        <source>Switch to %1</source>
        <translation>เปลี่ยนเป็น %1</translation>
    </message>
    <message>
        <source>Haas ST (NGC)</source>
        <translation>Haas ST (NGC)</translation>
    </message>
    <message>
        <source>Rook classic (1999 rules)</source>
        <translation>Rook แบบดั้งเดิม (กฎปี 1999)</translation>
    </message>
    <message>
        <source>Fanuc 0i-TF</source>
        <translation>Fanuc 0i-TF</translation>
    </message>
</context>
<context>
    <name>klueng::gui::FlowPanel</name>
    <message>
        <source>Program flow</source>
        <translation>ลำดับการทำงานของโปรแกรม</translation>
    </message>
    <message>
        <source>Call stack</source>
        <translation>ลำดับการเรียกโปรแกรม</translation>
    </message>
    <message>
        <source>Called from</source>
        <translation>เรียกจาก</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>ตัวแปร</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>ค่า</translation>
    </message>
    <message>
        <source>vacant</source>
        <translation>ว่าง</translation>
    </message>
    <message>
        <source>main program</source>
        <translation>โปรแกรมหลัก</translation>
    </message>
    <message>
        <source>subprogram (M98)</source>
        <translation>โปรแกรมย่อย (M98)</translation>
    </message>
    <message>
        <source>local subprogram (M97)</source>
        <translation>โปรแกรมย่อยภายใน (M97)</translation>
    </message>
    <message>
        <source>macro (G65)</source>
        <translation>มาโคร (G65)</translation>
    </message>
    <message>
        <source>modal macro (G66)</source>
        <translation>มาโครแบบโมดอล (G66)</translation>
    </message>
    <message>
        <source>(pass %1 of %2)</source>
        <translation>(รอบที่ %1 จาก %2)</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>บรรทัด %1</translation>
    </message>
    <message>
        <source>Running in %1, line %2</source>
        <translation>กำลังทำงานใน %1 บรรทัด %2</translation>
    </message>
</context>
<context>
    <name>klueng::gui::DocumentManager</name>
    <message>
        <source>Unsaved changes</source>
        <translation>มีการแก้ไขที่ยังไม่บันทึก</translation>
    </message>
    <message>
        <source>The tool or offset tables have been changed.</source>
        <translation>ตารางมีดตัดหรือตารางค่าออฟเซตถูกแก้ไข</translation>
    </message>
    <message>
        <source>The program "%1" and the tool or offset tables have been changed.</source>
        <translation>ชุดรหัสสั่งการทำงาน "%1" และตารางมีดตัดหรือตารางค่าออฟเซตถูกแก้ไข</translation>
    </message>
    <message>
        <source>The program "%1" has been changed.</source>
        <translation>ชุดรหัสสั่งการทำงาน "%1" ถูกแก้ไข</translation>
    </message>
    <message>
        <source>Do you want to save your changes?</source>
        <translation>ต้องการบันทึกการแก้ไขหรือไม่?</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>บันทึก (&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Discard</source>
        <translation>ไม่บันทึก (&amp;D)</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>ยกเลิก</translation>
    </message>
    <message>
        <source>Open program</source>
        <translation>เปิดชุดรหัสสั่งการทำงาน</translation>
    </message>
    <message>
        <source>Lathe programs (*.txt *.nc *.tap *.cnc *.gc);;All files (*)</source>
        <translation>ชุดรหัสสั่งการทำงานเครื่องกลึง (*.txt *.nc *.tap *.cnc *.gc);;ทุกแฟ้ม (*)</translation>
    </message>
    <message>
        <source>Cannot open the program</source>
        <translation>เปิดชุดรหัสสั่งการทำงานไม่ได้</translation>
    </message>
    <message>
        <source>"%1" could not be read.</source>
        <translation>อ่านแฟ้ม "%1" ไม่ได้</translation>
    </message>
    <message>
        <source>Save program as</source>
        <translation>บันทึกชุดรหัสสั่งการทำงานเป็น</translation>
    </message>
    <message>
        <source>Lathe programs (*.txt *.nc);;All files (*)</source>
        <translation>ชุดรหัสสั่งการทำงานเครื่องกลึง (*.txt *.nc);;ทุกแฟ้ม (*)</translation>
    </message>
    <message>
        <source>Cannot save over this file</source>
        <translation>บันทึกทับไฟล์นี้ไม่ได้</translation>
    </message>
    <message>
        <source>Line %1 of "%2" is too long to edit, so it is not in the editor. Saving over the file would delete it: use Save As to write your version to another file.</source>
        <translation>บรรทัดที่ %1 ของ "%2" ยาวเกินกว่าจะแก้ไขได้ จึงไม่ได้แสดงในหน้าต่างแก้ไข การบันทึกทับไฟล์จะทำให้บรรทัดนั้นหายไป ให้ใช้ "บันทึกเป็น" เพื่อบันทึกเป็นไฟล์ใหม่</translation>
    </message>
    <message>
        <source>Read-only file</source>
        <translation>ไฟล์แบบอ่านอย่างเดียว</translation>
    </message>
    <message>
        <source>"%1" is read-only, so Klueng will not write over it.</source>
        <translation>"%1" เป็นไฟล์แบบอ่านอย่างเดียว Klueng จึงจะไม่บันทึกทับไฟล์นี้</translation>
    </message>
    <message>
        <source>Save your program under another name?</source>
        <translation>ต้องการบันทึกชุดรหัสสั่งการทำงานเป็นชื่ออื่นหรือไม่?</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>บันทึกเป็น... (&amp;A)</translation>
    </message>
    <message>
        <source>Cannot save the program</source>
        <translation>บันทึกชุดรหัสสั่งการทำงานไม่ได้</translation>
    </message>
    <message>
        <source>"%1" could not be written:
%2</source>
        <translation>เขียนแฟ้ม "%1" ไม่ได้:
%2</translation>
    </message>
    <message>
        <source>File changed on disk</source>
        <translation>แฟ้มถูกเปลี่ยนแปลงบนดิสก์</translation>
    </message>
    <message>
        <source>"%1" was changed by another program.</source>
        <translation>แฟ้ม "%1" ถูกแก้ไขโดยโปรแกรมอื่น</translation>
    </message>
    <message>
        <source>Reload it and lose your changes here?</source>
        <translation>โหลดแฟ้มใหม่และทิ้งการแก้ไขในโปรแกรมนี้หรือไม่?</translation>
    </message>
    <message>
        <source>Reload it?</source>
        <translation>โหลดแฟ้มใหม่หรือไม่?</translation>
    </message>
    <message>
        <source>&amp;Reload</source>
        <translation>โหลดใหม่ (&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Keep mine</source>
        <translation>ใช้ของฉัน (&amp;K)</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(ไม่มี)</translation>
    </message>
</context>
<context>
    <name>klueng::gui::ReportController</name>
    <message>
        <source>Print Code</source>
        <translation>พิมพ์ชุดรหัสสั่งการทำงาน</translation>
    </message>
    <message>
        <source>No printer is set up: use File &gt; Export PDF to save the sheet.</source>
        <translation>ยังไม่ได้ตั้งค่าเครื่องพิมพ์: ใช้ แฟ้ม &gt; ส่งออกเป็น PDF เพื่อบันทึกเอกสาร</translation>
    </message>
    <message>
        <source>Program sheet sent to %1</source>
        <translation>ส่งเอกสารชุดรหัสสั่งการทำงานไปที่ %1 แล้ว</translation>
    </message>
    <message>
        <source>Print Drawing</source>
        <translation>พิมพ์ภาพชิ้นงาน</translation>
    </message>
    <message>
        <source>Print Preview</source>
        <translation>ดูตัวอย่างก่อนพิมพ์</translation>
    </message>
    <message>
        <source>Export PDF</source>
        <translation>ส่งออกเป็น PDF</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>ไฟล์ PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Cannot write %1</source>
        <translation>เขียนไฟล์ %1 ไม่ได้</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>ส่งออก %1 แล้ว</translation>
    </message>
</context>
<context>
    <name>klueng::gui::SetupCommands</name>
    <message>
        <source>Job Details</source>
        <translation>รายละเอียดงาน</translation>
    </message>
    <message>
        <source>Typing</source>
        <translation>การพิมพ์</translation>
    </message>
</context>
<context>
    <name>klueng::gui::SetupSave</name>
    <message>
        <source>Read-only setup</source>
        <translation>ไฟล์ตั้งค่าแบบอ่านอย่างเดียว</translation>
    </message>
    <message>
        <source>The setup in "%1" is read-only, so Klueng will not write over it.</source>
        <translation>ไฟล์ตั้งค่าใน "%1" เป็นแบบอ่านอย่างเดียว Klueng จึงจะไม่บันทึกทับ</translation>
    </message>
    <message>
        <source>Save the tool and offset tables to your own setup folder instead?</source>
        <translation>ต้องการบันทึกตารางมีดตัดและตารางค่าออฟเซตลงในโฟลเดอร์ตั้งค่าของคุณเองแทนหรือไม่?</translation>
    </message>
    <message>
        <source>Save to &amp;My Setup Folder</source>
        <translation>บันทึกลงโฟลเดอร์ตั้งค่าของฉัน (&amp;M)</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>ยกเลิก</translation>
    </message>
    <message>
        <source>Cannot save the setup</source>
        <translation>บันทึกการตั้งค่าไม่ได้</translation>
    </message>
    <message>
        <source>Cannot save the setup: %1</source>
        <translation>บันทึกการตั้งค่าไม่ได้: %1</translation>
    </message>
    <message>
        <source>Cannot save the tool table: %1</source>
        <translation>บันทึกตารางมีดตัดไม่ได้: %1</translation>
    </message>
    <message>
        <source>Cannot save the offset table: %1</source>
        <translation>บันทึกตารางค่าออฟเซตไม่ได้: %1</translation>
    </message>
</context>
<context>
    <name>klueng::gui::Recovery</name>
    <message>
        <source>permission denied</source>
        <translation>ไม่มีสิทธิ์เขียน</translation>
    </message>
    <message>
        <source>the disk is read-only</source>
        <translation>ดิสก์เป็นแบบอ่านอย่างเดียว</translation>
    </message>
    <message>
        <source>the disk is full</source>
        <translation>ดิสก์เต็ม</translation>
    </message>
    <message>
        <source>%1 is a file, not a folder</source>
        <translation>%1 เป็นไฟล์ ไม่ใช่โฟลเดอร์</translation>
    </message>
    <message>
        <source>cannot create the recovery folder %1: %2</source>
        <translation>สร้างโฟลเดอร์กู้คืน %1 ไม่ได้: %2</translation>
    </message>
    <message>
        <source>cannot lock %1: %2</source>
        <translation>ล็อกไฟล์ %1 ไม่ได้: %2</translation>
    </message>
    <message>
        <source>cannot write %1: the folder cannot be written to, or the disk is full</source>
        <translation>บันทึก %1 ไม่ได้: เขียนลงในโฟลเดอร์ไม่ได้ หรือดิสก์เต็ม</translation>
    </message>
</context>
<context>
    <name>klueng::gui::RecoveryBar</name>
    <message>
        <source>Rest&amp;ore</source>
        <translation>กู้คืน (&amp;O)</translation>
    </message>
    <message>
        <source>Co&amp;mpare</source>
        <translation>เปรียบเทียบ (&amp;M)</translation>
    </message>
    <message>
        <source>Dis&amp;card</source>
        <translation>ทิ้ง (&amp;C)</translation>
    </message>
    <message>
        <source>the same as the file on disk</source>
        <translation>เหมือนกับไฟล์ในดิสก์</translation>
    </message>
    <message>
        <source>Klueng closed without saving "%1" (edited %2): %3.</source>
        <translation>Klueng ปิดไปโดยยังไม่ได้บันทึก "%1" (แก้ไขเมื่อ %2): %3</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>บรรทัด %1</translation>
    </message>
    <message>
        <source>Unsaved work</source>
        <translation>งานที่ยังไม่ได้บันทึก</translation>
    </message>
    <message>
        <source>Lines marked - are in the file; lines marked + are in the unsaved copy.</source>
        <translation>บรรทัดที่ขึ้นต้นด้วย - อยู่ในไฟล์ ส่วนบรรทัดที่ขึ้นต้นด้วย + อยู่ในสำเนาที่ยังไม่ได้บันทึก</translation>
    </message>
    <message numerus="yes">
        <source>%n line(s) of unsaved work</source>
        <translation><numerusform>งานที่ยังไม่ได้บันทึก %n บรรทัด</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>%n line(s) differ from the file, the first at line %1</source>
        <translation><numerusform>ต่างจากไฟล์ %n บรรทัด เริ่มที่บรรทัด %1</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>%n more after this one.</source>
        <translation><numerusform>ยังมีอีก %n รายการ</numerusform></translation>
    </message>
</context>
<context>
    <name>klueng::gui::ClassGradeDialog</name>
    <message>
        <source>Browse...</source>
        <translation>เลือก...</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> มม.</translation>
    </message>
    <message>
        <source>Grade</source>
        <translation>ตรวจงาน</translation>
    </message>
    <message>
        <source>Save CSV...</source>
        <translation>บันทึก CSV...</translation>
    </message>
    <message>
        <source>Students' programs (folder):</source>
        <translation>โปรแกรมของนักเรียน (โฟลเดอร์):</translation>
    </message>
    <message>
        <source>Reference program:</source>
        <translation>โปรแกรมต้นแบบ:</translation>
    </message>
    <message>
        <source>Tolerance on the diameter:</source>
        <translation>พิกัดความเผื่อของเส้นผ่าศูนย์กลาง:</translation>
    </message>
    <message>
        <source>Students' programs</source>
        <translation>โปรแกรมของนักเรียน</translation>
    </message>
    <message>
        <source>Reference program</source>
        <translation>โปรแกรมต้นแบบ</translation>
    </message>
    <message>
        <source>Save the grades</source>
        <translation>บันทึกผลการตรวจ</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>ไฟล์ CSV (*.csv)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; could not be written.</source>
        <translation>เขียนไฟล์ &quot;%1&quot; ไม่ได้</translation>
    </message>
    <message>
        <source>Grade a class</source>
        <translation>ตรวจงานทั้งชั้นเรียน</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>โปรแกรม</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>ผล</translation>
    </message>
    <message>
        <source>Errors</source>
        <translation>ข้อผิดพลาด</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>สัญญาณเตือน</translation>
    </message>
    <message>
        <source>Cycle time (s)</source>
        <translation>เวลาทำงาน (วินาที)</translation>
    </message>
    <message>
        <source>Leftover (mm)</source>
        <translation>เนื้อเหลือ (มม.)</translation>
    </message>
    <message>
        <source>Gouge (mm)</source>
        <translation>กินเนื้อเกิน (มม.)</translation>
    </message>
    <message>
        <source>Grading...</source>
        <translation>กำลังตรวจ...</translation>
    </message>
    <message>
        <source>pass</source>
        <translation>ผ่าน</translation>
    </message>
    <message>
        <source>fail</source>
        <translation>ไม่ผ่าน</translation>
    </message>
    <message>
        <source>No programs graded: is the reference a program that runs to its end?</source>
        <translation>ไม่มีโปรแกรมที่ตรวจได้: โปรแกรมต้นแบบรันได้จนจบหรือไม่?</translation>
    </message>
    <message>
        <source>%1 programs: %2 pass, %3 fail</source>
        <translation>%1 โปรแกรม: ผ่าน %2 ไม่ผ่าน %3</translation>
    </message>
    <message>
        <source>Reference program (optional):</source>
        <translation>โปรแกรมต้นแบบ (ไม่บังคับ):</translation>
    </message>
    <message>
        <source>Drawing with tolerances (JSON/DXF, optional):</source>
        <translation>แบบงานที่มีพิกัดความเผื่อ (JSON/DXF, ไม่บังคับ):</translation>
    </message>
    <message>
        <source>General tolerance (ISO 2768-1):</source>
        <translation>พิกัดความเผื่อทั่วไป (ISO 2768-1):</translation>
    </message>
    <message>
        <source>none: only the drawing's own tolerances</source>
        <translation>ไม่มี: ใช้เฉพาะพิกัดความเผื่อที่กำหนดในแบบ</translation>
    </message>
    <message>
        <source>f (fine)</source>
        <translation>f (ละเอียด)</translation>
    </message>
    <message>
        <source>m (medium)</source>
        <translation>m (ปานกลาง)</translation>
    </message>
    <message>
        <source>c (coarse)</source>
        <translation>c (หยาบ)</translation>
    </message>
    <message>
        <source>v (very coarse)</source>
        <translation>v (หยาบมาก)</translation>
    </message>
    <message>
        <source>The teacher's drawing</source>
        <translation>แบบงานของครู</translation>
    </message>
    <message>
        <source>Parts and drawings (*.json *.dxf);;All files (*)</source>
        <translation>ชิ้นงานและแบบงาน (*.json *.dxf);;ทุกไฟล์ (*)</translation>
    </message>
    <message>
        <source>Save the grades as PDF</source>
        <translation>บันทึกผลการตรวจเป็น PDF</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>ไฟล์ PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Save PDF...</source>
        <translation>บันทึก PDF...</translation>
    </message>
    <message>
        <source>Drawing</source>
        <translation>แบบงาน</translation>
    </message>
    <message>
        <source>Dimension</source>
        <translation>ขนาด</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>พิกัดความเผื่อ</translation>
    </message>
    <message>
        <source>Limits (mm)</source>
        <translation>ขอบเขต (มม.)</translation>
    </message>
    <message>
        <source>Measured (mm)</source>
        <translation>วัดได้ (มม.)</translation>
    </message>
    <message>
        <source>Choose a reference program or a drawing with tolerances to grade against.</source>
        <translation>เลือกโปรแกรมต้นแบบหรือแบบงานที่มีพิกัดความเผื่อเพื่อใช้ตรวจเทียบ</translation>
    </message>
    <message>
        <source>No programs graded: the folder has no program files.</source>
        <translation>ไม่มีโปรแกรมที่ตรวจได้: ในโฟลเดอร์ไม่มีไฟล์โปรแกรม</translation>
    </message>
    <message>
        <source>%1 of %2 in tolerance</source>
        <translation>อยู่ในพิกัด %1 จาก %2</translation>
    </message>
    <message>
        <source>in tolerance</source>
        <translation>อยู่ในพิกัด</translation>
    </message>
    <message>
        <source>out of tolerance</source>
        <translation>นอกพิกัด</translation>
    </message>
    <message>
        <source>not on the part</source>
        <translation>ไม่มีบนชิ้นงาน</translation>
    </message>
    <message>
        <source>The drawing %1 has no toleranced dimension. Give tolerances in a part file (JSON; a DXF drawing's dimension texts are not read) or choose a general tolerance.</source>
        <translation>แบบงาน %1 ไม่มีขนาดที่กำหนดพิกัดความเผื่อ ให้กำหนดพิกัดความเผื่อในไฟล์ชิ้นงาน (JSON; ข้อความบอกขนาดในแบบ DXF ไม่ถูกอ่าน) หรือเลือกพิกัดความเผื่อทั่วไป</translation>
    </message>
    <message>
        <source>The layer of the part's outline:</source>
        <translation>เลเยอร์ของเส้นรอบรูปชิ้นงาน:</translation>
    </message>
    <message>
        <source>Touch-off</source>
        <translation>การตั้งศูนย์มีด</translation>
    </message>
    <message>
        <source>Cutting data</source>
        <translation>ข้อมูลการตัด</translation>
    </message>
    <message>
        <source>%1 line %2</source>
        <translation>%1 บรรทัด %2</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>บรรทัด %1: %2</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ไม่มี</translation>
    </message>
</context>
<context>
    <name>klueng::gui::ExplainBar</name>
    <message>
        <source>in</source>
        <translation>นิ้ว</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>มม.</translation>
    </message>
    <message>
        <source>ft/min</source>
        <translation>ฟุต/นาที</translation>
    </message>
    <message>
        <source>m/min</source>
        <translation>ม./นาที</translation>
    </message>
    <message>
        <source>Cutting data: Vc %1, f %2 %3/rev, ap %4 %3</source>
        <translation>ข้อมูลการตัด: ความเร็วตัด Vc %1, อัตราป้อน f %2 %3/รอบ, ความลึกป้อนตัด ap %4 %3</translation>
    </message>
    <message>
        <source>, Rz %1 µm, Ra %2 µm</source>
        <translation>, ความหยาบผิว Rz %1 ไมครอน, Ra %2 ไมครอน</translation>
    </message>
    <message>
        <source>, power %1 kW, torque %2 N·m</source>
        <translation>, กำลังตัด %1 กิโลวัตต์, แรงบิด %2 นิวตันเมตร</translation>
    </message>
</context>
</TS>
