#!/usr/bin/env python3
"""Writes the golden-trace cases from the hand derivations below.

Each row is written from the hand calculation in its comment (README.md has
the long derivations); this script only formats the numbers to 4 decimals.
Rapids: X 4000 mm/min on the radius, Z 8000 mm/min, each axis on its own.
Rows: (kind, line, t0, t1, x0, z0, x1, z1, i, k, dir, feed, rpm).
Run it again after changing a case: python3 tests/golden/make_cases.py
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
HEADER = "kind,line,t_start,t_end,x_start,z_start,x_end,z_end,i,k,dir,feed_mm_min,rpm,level,program"
MAIN = "{MAIN}"  # the main program's O number, filled in by case()
BOTH = math.hypot(8000, 4000)  # path speed of a dog-leg's first leg when it moves 2:1 (Z:X radius)


def row(kind, line, t0, t1, x0, z0, x1, z1, i=0.0, k=0.0, d="", feed=0.0, rpm=0.0, level=0, prog=MAIN):
    """level: call level (0 = main program); prog: the O number of the program the move is in ("O1000")."""
    nums = [t0, t1, x0, z0, x1, z1, i, k]
    f = lambda v: "%.4f" % (0.0 if abs(v) < 5e-5 else v)
    return ",".join([kind, str(line)] + [f(v) for v in nums] + [d, f(feed), f(rpm), str(level), prog])


def main_program(program):
    """The O number of a program's first block ("O0001"), "" when it has none."""
    for line in program.splitlines():
        t = line.strip()
        if not t or t.startswith("%") or t.startswith("("):
            continue
        if t[0] in "Oo" and len(t) > 1 and t[1].isdigit():
            digits = "".join(ch for ch in t[1:].split()[0] if ch.isdigit())
            return "O%04d" % int(digits)
        if t[0].isalpha() and len(t) > 1 and (t[1].isdigit() or t[1] in "-."):
            return ""  # a G-code line before any O word (header lines are skipped)
    return ""


def case(name, program, rows, alarm=None, args=None):
    d = os.path.join(HERE, name)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "program.nc"), "w") as fh:
        fh.write(program)
    with open(os.path.join(d, "expected.csv"), "w") as fh:
        main = main_program(program)
        fh.write("\n".join([HEADER] + [r.replace(MAIN, main) for r in rows]) + "\n")
    for fname, content in (("expected_alarm", alarm), ("args", args)):
        p = os.path.join(d, fname)
        if content:
            with open(p, "w") as fh:
                fh.write(content + "\n")
        elif os.path.exists(p):
            os.remove(p)


# ---------------------------------------------------------------- G codes
# G00 X100 Z100 from X0 Z300: X 50 mm (radius) takes 0.75 s, Z 200 mm 1.5 s;
# together for 0.75 s (Z covers 100), then Z alone.
case("g00_rapid_dogleg", "G00 X100. Z100.\n", [
    row("RAPID", 1, 0, 0.75, 0, 300, 100, 200, feed=BOTH),
    row("RAPID", 1, 0.75, 1.5, 100, 200, 100, 100, feed=8000),
])

# G98 G01: Z10 -> Z-20 = 30 mm at 300 mm/min = 6 s. Rapid: X 20 radius 0.3 s,
# Z 290 mm 2.175 s; Z covers 40 mm in the first 0.3 s.
case("g01_line_g98", "G98\nG00 X40. Z10.\nG01 Z-20. F300.\n", [
    row("RAPID", 2, 0, 0.3, 0, 300, 40, 260, feed=BOTH),
    row("RAPID", 2, 0.3, 2.175, 40, 260, 40, 10, feed=8000),
    row("LINE", 3, 2.175, 8.175, 40, 10, 40, -20, feed=300),
])

# G99 at 500 rpm: F0.2 -> 100 mm/min. Z2 -> Z-18: 20 mm = 12 s; the taper to
# X40 Z-23: dx 5, dz 5 -> 7.0711 mm = 4.2426 s.
case("g99_line_per_rev", "G97 S500 M03\nG99\nG00 X30. Z2.\nG01 Z-18. F0.2\nG01 X40. Z-23.\nM05\n", [
    row("RAPID", 3, 0, 0.225, 0, 300, 30, 270, feed=BOTH, rpm=500),
    row("RAPID", 3, 0.225, 2.235, 30, 270, 30, 2, feed=8000, rpm=500),
    row("LINE", 4, 2.235, 14.235, 30, 2, 30, -18, feed=100, rpm=500),
    row("LINE", 5, 14.235, 14.235 + math.sqrt(50) / 100 * 60, 30, -18, 40, -23, feed=100, rpm=500),
])

# G02 R5 from X20 Z0 to X30 Z-5: centre Z0 X30 (radius 15) -> i = 5, k = 0;
# quarter circle 5*pi/2 = 7.854 mm at 100 mm/min = 4.7124 s.
RAPID_TO_X20_Z0 = [
    row("RAPID", 2, 0, 0.15, 0, 300, 20, 280, feed=BOTH),
    row("RAPID", 2, 0.15, 2.25, 20, 280, 20, 0, feed=8000),
]
case("g02_arc_radius", "G98\nG00 X20. Z0.\nG02 X30. Z-5. R5. F100.\n", RAPID_TO_X20_Z0 + [
    row("ARC", 3, 2.25, 2.25 + 5 * math.pi / 2 / 100 * 60, 20, 0, 30, -5, 5, 0, "CW", 100),
])
# the 270-degree arc, centre Z-5 X20 (radius 10) -> i = 0, k = -5.
case("g02_arc_long_radius", "G98\nG00 X20. Z0.\nG02 X30. Z-5. R-5. F100.\n", RAPID_TO_X20_Z0 + [
    row("ARC", 3, 2.25, 2.25 + 5 * 1.5 * math.pi / 100 * 60, 20, 0, 30, -5, 0, -5, "CW", 100),
])
# G03 by I/K from X36 Z-20 to X40 Z-22, centre Z-22 X36: quarter circle R2,
# pi mm = 1.885 s. Rapid: X 18 radius 0.27 s (Z covers 36), Z 320 mm 2.4 s.
case("g03_arc_centre", "G98\nG00 X36. Z-20.\nG03 X40. Z-22. I0. K-2. F100.\n", [
    row("RAPID", 2, 0, 0.27, 0, 300, 36, 264, feed=BOTH),
    row("RAPID", 2, 0.27, 2.4, 36, 264, 36, -20, feed=8000),
    row("ARC", 3, 2.4, 2.4 + math.pi / 100 * 60, 36, -20, 40, -22, 0, -2, "CCW", 100),
])

# G04: X and U in seconds, P in milliseconds (G98: a dwell with the spindle stopped is fine).
case("g04_dwell", "G98\nG04 X1.5\nG04 U0.5\nG04 P250\n", [
    row("DWELL", 2, 0, 1.5, 0, 300, 0, 300),
    row("DWELL", 3, 1.5, 2.0, 0, 300, 0, 300),
    row("DWELL", 4, 2.0, 2.25, 0, 300, 0, 300),
])

# G20: X1 Z1 = 25.4 mm; F10 in/min = 254 mm/min; W-1 = 25.4 mm in 6 s.
# Rapid: X 12.7 radius 0.1905 s (Z covers 25.4), Z 274.6 mm 2.0595 s.
case("g20_inch", "G20 G98\nG00 X1. Z1.\nG01 W-1. F10.\n", [
    row("RAPID", 2, 0, 0.1905, 0, 300, 25.4, 274.6, feed=BOTH),
    row("RAPID", 2, 0.1905, 2.0595, 25.4, 274.6, 25.4, 25.4, feed=8000),
    row("LINE", 3, 2.0595, 8.0595, 25.4, 25.4, 25.4, 0, feed=254),
])
# G21 back to mm: X1 inch = 25.4, then X20 mm (2.7 mm radius, 0.0405 s).
case("g21_metric", "G20\nG00 X1.\nG21\nG00 X20.\n", [
    row("RAPID", 2, 0, 0.1905, 0, 300, 25.4, 300, feed=4000),
    row("RAPID", 4, 0.1905, 0.231, 25.4, 300, 20, 300, feed=4000),
])

# G27 X0 Z300 = the reference point: rapid back, lamp on, no alarm.
TO_X40_Z50 = [
    row("RAPID", 1, 0, 0.3, 0, 300, 40, 260, feed=BOTH),
    row("RAPID", 1, 0.3, 1.875, 40, 260, 40, 50, feed=8000),
]
case("g27_reference_check", "G00 X40. Z50.\nG27 X0. Z300.\n", TO_X40_Z50 + [
    row("RAPID", 2, 1.875, 2.175, 40, 50, 0, 90, feed=BOTH),
    row("RAPID", 2, 2.175, 3.75, 0, 90, 0, 300, feed=8000),
])

# G28 via X60 Z100 to the reference X0 Z300, G29 back via X60 Z100 to X30 Z20.
case("g28_g29_reference", "G00 X40. Z50.\nG28 X60. Z100.\nG29 X30. Z20.\n", TO_X40_Z50 + [
    row("RAPID", 2, 1.875, 2.025, 40, 50, 60, 70, feed=BOTH),   # X 10 radius 0.15 s, Z 50 0.375 s
    row("RAPID", 2, 2.025, 2.25, 60, 70, 60, 100, feed=8000),
    row("RAPID", 2, 2.25, 2.7, 60, 100, 0, 160, feed=BOTH),     # X 30 radius 0.45 s, Z 200 1.5 s
    row("RAPID", 2, 2.7, 3.75, 0, 160, 0, 300, feed=8000),
    row("RAPID", 3, 3.75, 4.2, 0, 300, 60, 240, feed=BOTH),
    row("RAPID", 3, 4.2, 5.25, 60, 240, 60, 100, feed=8000),
    row("RAPID", 3, 5.25, 5.475, 60, 100, 30, 70, feed=BOTH),   # X 15 radius 0.225 s, Z 80 0.6 s
    row("RAPID", 3, 5.475, 5.85, 30, 70, 30, 20, feed=8000),
])
# Fanuc: G28 without axis words moves nothing.
case("g28_no_axes", "G00 X40. Z50.\nG28\n", TO_X40_Z50)

# G32 at 500 rpm, lead 1.5: 750 mm/min; Z5 -> Z-25 = 30 mm in 2.4 s.
case("g32_thread", "G97 S500 M03\nG00 X30. Z5.\nG32 Z-25. F1.5\n", [
    row("RAPID", 2, 0, 0.225, 0, 300, 30, 270, feed=BOTH, rpm=500),
    row("RAPID", 2, 0.225, 2.2125, 30, 270, 30, 5, feed=8000, rpm=500),
    row("THREAD", 3, 2.2125, 4.6125, 30, 5, 30, -25, feed=750, rpm=500),
])

# G42, offset 01 (R0.8, tip 3 -> tip = centre + 0.8*(-1,-1) in (z, x)).
# Start-up ends R to the right of the first contour move's start: centre
# Z2 x10.8 -> tip X20 Z1.2. Inside corner at Z-10 X20 (both offsets meet at
# centre Z-9.2 x10.8 -> tip X20 Z-10). The last contour move ends offset
# perpendicular to itself: centre Z-9.2 x15 -> tip X28.4 Z-10. Cancel to the
# uncompensated point X50 Z10: X 10.8 radius 0.162 s, Z 20 0.15 s.
case("g42_nose_comp_right",
     "G98 T0101\nG42 G00 X20. Z2.\nG01 Z-10. F100.\nX30.\nG40 G00 X50. Z10.\n", [
         row("RAPID", 2, 0, 0.15, 0, 300, 20, 280, feed=BOTH),
         row("RAPID", 2, 0.15, 2.241, 20, 280, 20, 1.2, feed=8000),
         row("LINE", 3, 2.241, 8.961, 20, 1.2, 20, -10, feed=100),
         row("LINE", 4, 8.961, 11.481, 20, -10, 28.4, -10, feed=100),
         row("RAPID", 5, 11.481, 11.631, 28.4, -10, 48.4, 10, feed=BOTH),
         row("RAPID", 5, 11.631, 11.643, 48.4, 10, 50, 10, feed=4000),
     ])
# G41 boring, offset 04 (R0.4, tip 2 -> tip = centre + 0.4*(-1,+1)). Travel
# -Z with the tool on the left = below the bore line: centre x9.6; start-up
# tip X20 Z1.6; inside corner tip X20 Z-10; face end centre Z-9.6 x6 -> tip
# X12.8 Z-10; cancel to X0 Z10: X 6.4 radius 0.096 s, Z 20 0.15 s.
case("g41_nose_comp_left",
     "G98 T0404\nG41 G00 X20. Z2.\nG01 Z-10. F100.\nX12.\nG40 G00 X0. Z10.\n", [
         row("RAPID", 2, 0, 0.15, 0, 300, 20, 280, feed=BOTH),
         row("RAPID", 2, 0.15, 2.238, 20, 280, 20, 1.6, feed=8000),
         row("LINE", 3, 2.238, 9.198, 20, 1.6, 20, -10, feed=100),
         row("LINE", 4, 9.198, 11.358, 20, -10, 12.8, -10, feed=100),
         row("RAPID", 5, 11.358, 11.454, 12.8, -10, 0, 2.8, feed=BOTH),
         row("RAPID", 5, 11.454, 11.508, 0, 2.8, 0, 10, feed=8000),
     ])
# G40 alone: the same path without compensation (the tip follows the program).
case("g40_no_comp", "G98 T0101 G40\nG00 X20. Z2.\nG01 Z-10. F100.\nX30.\n", [
    row("RAPID", 2, 0, 0.15, 0, 300, 20, 280, feed=BOTH),
    row("RAPID", 2, 0.15, 2.235, 20, 280, 20, 2, feed=8000),
    row("LINE", 3, 2.235, 9.435, 20, 2, 20, -10, feed=100),
    row("LINE", 4, 9.435, 12.435, 20, -10, 30, -10, feed=100),
])

# G50 X100 Z50 at the start position: the tool now reads X100 Z50.
# X 10 radius 0.15 s, Z 10 0.075 s: X covers 5 mm radius in the first 0.075 s.
case("g50_coordinate_set", "G50 X100. Z50.\nG00 X80. Z40.\n", [
    row("RAPID", 2, 0, 0.075, 100, 50, 90, 40, feed=BOTH),
    row("RAPID", 2, 0.075, 0.15, 90, 40, 80, 40, feed=4000),
])

# G50 S2000 + G96 S150: C = 1000*150/(2 pi) = 23873.24 rpm*mm, clamp radius
# xc = C/2000 = 11.9366. Facing X60 -> X0 at F0.25:
# t = 60/0.25 * ((30^2 - xc^2)/(2C) + xc/2000) = 5.2401 s.
C150 = 1000 * 150 / (2 * math.pi)
XC150 = C150 / 2000
FACE = 60 / 0.25 * ((30 ** 2 - XC150 ** 2) / (2 * C150) + XC150 / 2000)
RPM60 = 1000 * 150 / (math.pi * 60)
case("g96_g50s_facing", "G50 S2000\nG96 S150 M03\nG00 X60. Z0.\nG01 X0. F0.25\n", [
    row("RAPID", 3, 0, 0.45, 0, 300, 60, 240, feed=BOTH, rpm=2000),
    row("RAPID", 3, 0.45, 2.25, 60, 240, 60, 0, feed=8000, rpm=RPM60),
    row("LINE", 4, 2.25, 2.25 + FACE, 60, 0, 0, 0, feed=0.25 * RPM60, rpm=RPM60),
])
# G97 after G96: constant 1000 rpm; F0.1 -> 100 mm/min, 10 mm in 6 s.
case("g97_constant_rpm", "G96 S100 M03\nG97 S1000\nG00 X20. Z10.\nG01 Z0. F0.1\n", [
    row("RAPID", 3, 0, 0.15, 0, 300, 20, 280, feed=BOTH, rpm=1000),
    row("RAPID", 3, 0.15, 2.175, 20, 280, 20, 10, feed=8000, rpm=1000),
    row("LINE", 4, 2.175, 8.175, 20, 10, 20, 0, feed=100, rpm=1000),
])
# G98 and G99 in turn: 5 mm at 100 mm/min (3 s), then 5 mm at 0.1 * 800 = 80 mm/min (3.75 s).
case("g98_g99_feed_modes", "M03 S800\nG98 G01 X10. F100.\nG99 G01 X20. F0.1\n", [
    row("LINE", 2, 0, 3, 0, 300, 10, 300, feed=100, rpm=800),
    row("LINE", 3, 3, 6.75, 10, 300, 20, 300, feed=80, rpm=800),
])

# ---------------------------------------------------------------- M codes, T, switches
# Headless runs record M00/M01 and go on; nothing after M02 runs.
case("m00_m01_m02", "G00 X10.\nM00\nM01\nG00 X20.\nM02\nG00 X30.\n", [
    row("RAPID", 1, 0, 0.075, 0, 300, 10, 300, feed=4000),
    row("RAPID", 4, 0.075, 0.15, 10, 300, 20, 300, feed=4000),
])
case("m01_optional_stop_on", "G00 X10.\nM01\nG00 X20.\n", [
    row("RAPID", 1, 0, 0.075, 0, 300, 10, 300, feed=4000),
    row("RAPID", 3, 0.075, 0.15, 10, 300, 20, 300, feed=4000),
], args="--optional-stop")
case("m30_end", "G00 X10.\nM30\nG00 X20.\n", [
    row("RAPID", 1, 0, 0.075, 0, 300, 10, 300, feed=4000),
])
# M03/M05/M04: the rpm column follows the spindle (G98 cuts need no spindle).
case("m03_m04_m05_spindle", "G98 G97 S800\nM03\nG01 X10. F100.\nM05\nG01 X20.\nM04\nG01 X30.\n", [
    row("LINE", 3, 0, 3, 0, 300, 10, 300, feed=100, rpm=800),
    row("LINE", 5, 3, 6, 10, 300, 20, 300, feed=100, rpm=0),
    row("LINE", 7, 6, 9, 20, 300, 30, 300, feed=100, rpm=800),
])
# M05 in a cutting block acts after the cut (SPEC 7 order).
case("m05_after_motion", "M03 S500\nG01 X10. F0.2 M05\n", [
    row("LINE", 2, 0, 3, 0, 300, 10, 300, feed=100, rpm=500),
])
case("m08_m09_coolant", "G98\nM08\nG01 X10. F100. M09\n", [
    row("LINE", 3, 0, 3, 0, 300, 10, 300, feed=100),
])
# Classic C axis: brake on, C-axis mode, C/H rotations (no time), off again.
case("m41_m91_m86_m87_c_axis", "M86\nM41\nG00 C90.\nH-100.\nM91\nM87\nG00 X10.\n", [
    row("RAPID", 7, 0, 0.075, 0, 300, 10, 300, feed=4000),
], args="--dialect classic")
# Offset 02 (X +0.4 diameter, Z -0.2) shifts the controlled point; T0200 cancels.
case("t_tool_offset", "T0202\nG00 X20. Z10.\nG00 U-2.\nT0200\nG00 X20.\n", [
    row("RAPID", 2, 0, 0.153, 0, 300, 20.4, 279.6, feed=BOTH),
    row("RAPID", 2, 0.153, 2.1765, 20.4, 279.6, 20.4, 9.8, feed=8000),
    row("RAPID", 3, 2.1765, 2.1915, 20.4, 9.8, 18.4, 9.8, feed=4000),
    row("RAPID", 5, 2.1915, 2.2035, 18.4, 9.8, 20, 9.8, feed=4000),
])
case("block_skip_on", "G00 X10.\n/G00 X50.\nG00 Z250.\n", [
    row("RAPID", 1, 0, 0.075, 0, 300, 10, 300, feed=4000),
    row("RAPID", 3, 0.075, 0.45, 10, 300, 10, 250, feed=8000),
], args="--block-skip")
case("block_skip_off", "G00 X10.\n/G00 X50.\nG00 Z250.\n", [
    row("RAPID", 1, 0, 0.075, 0, 300, 10, 300, feed=4000),
    row("RAPID", 2, 0.075, 0.375, 10, 300, 50, 300, feed=4000),
    row("RAPID", 3, 0.375, 0.75, 50, 300, 50, 250, feed=8000),
])

# ---------------------------------------------------------------- alarms
X10 = [row("RAPID", 1, 0, 0.075, 0, 300, 10, 300, feed=4000)]
# The 1999 trainer stops on an S above the maximum; a Fanuc or Haas clamps it (W132, issue 38).
case("alarm_a101_speed_above_max", "G00 X10.\nG97 S3500 M03\n", X10,
     alarm="program.nc:2:5: alarm A101", args="--dialect classic")
case("alarm_a102_no_feed", "G98\nG00 X10.\nG01 Z290.\n",
     [row("RAPID", 2, 0, 0.075, 0, 300, 10, 300, feed=4000)], alarm="program.nc:3:1: alarm A102")
case("alarm_a103_g99_without_s", "M03\nG00 X10.\nG01 Z290. F0.2\n",
     [row("RAPID", 2, 0, 0.075, 0, 300, 10, 300, feed=4000)], alarm="program.nc:3:1: alarm A103")
# Sample 05: N40 (line 12) cuts under G99 with the spindle stopped.
with open(os.path.join(HERE, "..", "..", "resources", "samples", "05-runtime-alarms.txt")) as fh:
    SAMPLE05 = fh.read()
case("alarm_a104_sample05", SAMPLE05, [
    row("RAPID", 11, 0, 0.3375, 0, 300, 45, 255, feed=BOTH),   # X 22.5 radius 0.3375 s
    row("RAPID", 11, 0.3375, 2.235, 45, 255, 45, 2, feed=8000),  # Z 298 mm 2.235 s
], alarm="program.nc:12:5: alarm A104")
# A Fanuc reverses the spindle (W133; issue 38): the run goes on, nothing moves after M04.
case("spindle_reversal_fanuc_reverses", "M03 S500\nG98 G01 X10. F100.\nM04\n",
     [row("LINE", 2, 0, 3, 0, 300, 10, 300, feed=100, rpm=500)])
case("alarm_a106_start_with_brake", "M86\nS100 M03\n", [], alarm="program.nc:2:6: alarm A106")
case("alarm_a107_brake_while_turning", "M03 S100\nM86\n", [], alarm="program.nc:2:1: alarm A107")
RPM30 = 1000 * 100 / (math.pi * 30)
case("alarm_a108_thread_under_g96", "G96 S100 M03\nG00 X30. Z5.\nG32 Z-10. F1.\n", [
    row("RAPID", 2, 0, 0.225, 0, 300, 30, 270, feed=BOTH, rpm=3000),  # X0: clamped to the maximum
    row("RAPID", 2, 0.225, 2.2125, 30, 270, 30, 5, feed=8000, rpm=RPM30),
], alarm="program.nc:3:1: alarm A108", args="--dialect classic")  # Fanuc/Haas: W131, the thread runs
case("alarm_a109_c_outside_c_axis_mode", "G00 C90.\n", [], alarm="program.nc:1:5: alarm A109",
     args="--dialect classic")
case("alarm_a110_c_axis_without_brake", "M41\n", [], alarm="program.nc:1:1: alarm A110",
     args="--dialect classic")
case("alarm_a111_brake_release_in_c_axis", "M86\nM41\nM87\n", [], alarm="program.nc:3:1: alarm A111",
     args="--dialect classic")
case("alarm_a112_travel_limit", "G00 X10.\nG00 Z1200.\n", X10, alarm="program.nc:2:1: alarm A112")
case("alarm_a113_arc_not_on_one_circle", "G98 G00 X20. Z0.\nG02 X30. Z-5. I5. K1. F100.\n",
     [row("RAPID", 1, 0, 0.15, 0, 300, 20, 280, feed=BOTH), row("RAPID", 1, 0.15, 2.25, 20, 280, 20, 0, feed=8000)],
     alarm="program.nc:2:15: alarm A113")
case("alarm_a114_arc_radius_too_small", "G98 G00 X20. Z0.\nG02 X30. Z-5. R3. F100.\n",
     [row("RAPID", 1, 0, 0.15, 0, 300, 20, 280, feed=BOTH), row("RAPID", 1, 0.15, 2.25, 20, 280, 20, 0, feed=8000)],
     alarm="program.nc:2:15: alarm A114")
# G27 to X10 Z20 (not the reference point): the move runs, then the alarm.
# From X40 Z50: X 15 radius and Z 30 both take 0.225 s: one straight rapid.
case("alarm_a115_g27_not_reference", "G00 X40. Z50.\nG27 X10. Z20.\n", TO_X40_Z50 + [
    row("RAPID", 2, 1.875, 2.1, 40, 50, 10, 20, feed=BOTH),
], alarm="program.nc:2:1: alarm A115")
case("alarm_a116_thread_spindle_stopped", "G97 S500\nG32 Z-10. F1.\n", [], alarm="program.nc:2:1: alarm A116")
case("alarm_a119_thread_without_s", "M03\nG32 Z-10. F1.\n", [], alarm="program.nc:2:1: alarm A119")
# Nose-comp interference: a concave R0.3 fillet under a R0.8 nose. The fillet
# is tangent to the Z-10 line, so the line's offset runs on to Z-10 + 0 in
# centre terms: centre Z-10 x10.8 -> tip X20 Z-10.8 (12 mm, 7.2 s); the arc
# block (line 4) raises A201 and nothing after it runs.
case("alarm_a201_nose_comp_interference",
     "G98 T0101\nG42 G00 X20. Z2.\nG01 Z-10. F100.\nG02 X20.6 Z-10.3 R0.3\nG01 X30.\nG40 G00 X50. Z10.\n", [
         row("RAPID", 2, 0, 0.15, 0, 300, 20, 280, feed=BOTH),
         row("RAPID", 2, 0.15, 2.241, 20, 280, 20, 1.2, feed=8000),
         row("LINE", 3, 2.241, 9.441, 20, 1.2, 20, -10.8, feed=100),
     ], alarm="program.nc:4:1: alarm A201",
     # The tool the user chose (not a guess for a plain program): its R0.8 alarms (issue 38 item 7).
     args="--tool 1=cnmg-80-r08")


# ---------------------------------------------------------------- the samples
class Hand:
    """Bookkeeping for a hand derivation: time and the controlled point (X as a
    diameter). Every duration and point is given by the derivation; this only
    adds up the times and splits rapids into their dog-leg legs."""

    def __init__(self, rpm_at):
        self.t, self.x, self.z, self.rows, self.rpm_at = 0.0, 0.0, 300.0, [], rpm_at

    def rapid(self, line, x, z):
        tx, tz = abs(x - self.x) / 2 / 4000, abs(z - self.z) / 8000  # minutes
        legs = []
        if tx == 0 or tz == 0 or abs(tx - tz) < 1e-12:
            legs.append((x, z, max(tx, tz)))
        elif tx < tz:  # X arrives first; Z has covered 8000 * tx
            legs += [(x, self.z + math.copysign(8000 * tx, z - self.z), tx), (x, z, tz - tx)]
        else:
            legs += [(self.x + math.copysign(2 * 4000 * tz, x - self.x), z, tz), (x, z, tx - tz)]
        for lx, lz, minutes in legs:
            length = math.hypot((lx - self.x) / 2, lz - self.z)
            self.rows.append(row("RAPID", line, self.t, self.t + minutes * 60, self.x, self.z, lx, lz,
                                 feed=length / minutes, rpm=self.rpm_at(self.x)))
            self.t, self.x, self.z = self.t + minutes * 60, lx, lz

    def feed(self, kind, line, x, z, seconds, feed, i=0.0, k=0.0, d=""):
        self.rows.append(row(kind, line, self.t, self.t + seconds, self.x, self.z, x, z, i, k, d, feed,
                             self.rpm_at(self.x)))
        self.t, self.x, self.z = self.t + seconds, x, z


def sample(name):
    with open(os.path.join(HERE, "..", "..", "resources", "samples", name)) as fh:
        return fh.read()


# Sample 01 (config offsets = the shipped ones for T0101: R0.8 tip 3, X/Z 0).
# G96 S180, G50 S2500: rpm(x) = min(C / x, 2500), x = radius, C = 1000*180/(2 pi).
# A G99 cut at F with x >= x_c = C/2500 all along: t = 60/(F C) * L * (x0 + x1)/2.
C180 = 1000 * 180 / (2 * math.pi)
XC180 = C180 / 2500
rpm01 = lambda xd: min(C180 / (abs(xd) / 2), 2500) if xd != 0 else 2500


def g96cut(h, line, x, z, f, kind="LINE"):
    length = math.hypot((x - h.x) / 2, z - h.z)
    assert min(h.x, x) / 2 >= XC180
    h.feed(kind, line, x, z, 60 / (f * C180) * length * (h.x + x) / 4, f * rpm01(h.x))


s01 = Hand(rpm01)
s01.rapid(13, 54, 2)   # N50
s01.rapid(14, 54, 0)   # N60
# N70 facing X54 -> X-1.6: (60/0.2) * ((27^2 - x_c^2)/(2C) + (x_c + 0.8)/2500) = 4.6006 s
s01.feed("LINE", 15, -1.6, 0, 60 / 0.2 * ((27 ** 2 - XC180 ** 2) / (2 * C180) + (XC180 + 0.8) / 2500),
         0.2 * rpm01(54))
s01.rapid(16, -1.6, 2)  # N80
s01.rapid(17, 47, 2)    # N90
line = 18
for i, (x, z, up) in enumerate([(47, -59.8, 50), (44, -39.8, 47), (41, -39.8, 44),
                                (37, -19.8, 41), (33, -19.8, 37), (31, -19.8, 33)]):
    if i > 0:
        s01.rapid(line, x, 2)
        line += 1
    g96cut(s01, line, x, z, 0.25)
    g96cut(s01, line + 1, up, z, 0.25)
    line += 2
    if i < 5:
        s01.rapid(line, up, 2)
        line += 1
s01.rapid(40, 100, 100)  # N320
# Finishing under G42 (see README: the tip keeps the diameters and faces; the
# 45-degree chamfers move the corners by k = 0.8 (2 - sqrt 2); the R2 corner
# becomes a quarter circle R2.8 around Z-22.8 X34.4).
K = 0.8 * (2 - math.sqrt(2))
s01.rapid(41, 24, 1.2)
for ln, x, z in [(42, 24, -K), (43, 30, -3 - K), (44, 30, -20), (45, 34.4, -20)]:
    g96cut(s01, ln, x, z, 0.1)
s01.feed("ARC", 46, 40, -22.8, 60 / (0.1 * C180) * 2.8 * (17.2 * math.pi / 2 + 2.8), 0.1 * rpm01(34.4),
         i=0, k=-2.8, d="CCW")
for ln, x, z in [(47, 40, -40), (48, 44 - 2 * K, -40), (49, 46, -41 - K), (50, 46, -60), (51, 50.4, -60)]:
    g96cut(s01, ln, x, z, 0.1)
s01.rapid(52, 100, 100)  # N440 cancel
case("sample01_step_shaft", sample("01-step-shaft.txt"), s01.rows)

# Sample 02: G97. Turning at 1000 rpm, F0.2 (200 mm/min); threads at 800 rpm,
# lead 1.5 (1200 mm/min), Z5 -> Z-30 = 35 mm in 1.75 s.
s02 = Hand(lambda xd: 1000)
s02.rapid(12, 34, 2)                                   # N40
s02.feed("LINE", 13, 30, 2, 2 / 200 * 60, 200)         # N50: 2 mm radius
s02.feed("LINE", 14, 30, -40, 42 / 200 * 60, 200)      # N60
s02.feed("LINE", 15, 34, -40, 2 / 200 * 60, 200)       # N70
s02.rapid(16, 100, 100)                                # N80
s02.rpm_at = lambda xd: 800                            # N100 G97 S800
s02.rapid(19, 32, 5)                                   # N110
line = 20
for x in (29.4, 28.9, 28.5, 28.16):
    s02.rapid(line, x, 5)
    s02.feed("THREAD", line + 1, x, -30, 35 / 1200 * 60, 1200)
    s02.rapid(line + 2, 32, -30)
    if x != 28.16:
        s02.rapid(line + 3, 32, 5)
    line += 4
s02.rapid(line - 1, 100, 100)                          # N270
case("sample02_thread", sample("02-thread.txt"), s02.rows)


# ---------------------------------------------------------------- Fanuc extras (SPEC 13)
# G18/G80 are no-ops, G55 a (zero) work offset, M42 a gear range. After G50
# X100 Z50 at the start position (machine Z300 X0), work = machine + (Z-250,
# X+100): G53 X0 Z250 (machine) is work X100 Z0, a Z-only rapid of 50 mm.
case("fanuc_g18_g53_g55_g80_m42", "G18 G21 G40 G80 G99\nG55\nG50 X100. Z50.\nG53 X0. Z250.\nM42\n", [
    # G53: machine zero is the reference point X0 Z300, shifted with the work by
    # G50 (+100 in X, -250 in Z): machine X0 Z250 = work X100 Z300; 250 mm of Z at 8000.
    row("RAPID", 4, 0, 1.875, 100, 50, 100, 300, feed=8000),
])
# Subprograms are not simulated yet: the run stops on M98 with A117.
# The P of M98 comes from a variable, so only the run finds that O1000 is missing.
case("alarm_a135_subprogram_missing", "G00 X10.\n#1=1000\nM98 P#1\n", X10, alarm="program.nc:3:1: alarm A135")


# ---------------------------------------------------------------- canned cycles (Fanuc 0i-TF)
# All at G98 F100 (cuts: length / 100 mm/min) or G97 S500 (threads at lead * 500).
# The cycle's moves all carry the cycle block's line; derivations in
# tests/core/machine/cycles_test.cpp and README.md.
rpm500 = lambda xd: 500
CYC = "G98 G97 S500 M03\n"

# G90 X40 Z-20 from X50 Z2: X in, 22 mm along Z (13.2 s), out 5 mm radius
# (3 s), rapid back; "X35." repeats it (out 7.5 mm: 4.5 s). G94 X20 Z-2: Z to
# -2, face 15 mm (9 s), back 4 mm along Z (2.4 s), rapid out. G00 cancels.
h = Hand(rpm500)
h.rapid(2, 50, 2)
for line, x, up in ((3, 40, 3.0), (4, 35, 4.5)):
    h.rapid(line, x, 2)
    h.feed("LINE", line, x, -20, 13.2, 100)
    h.feed("LINE", line, 50, -20, up, 100)
    h.rapid(line, 50, 2)
h.rapid(5, 50, -2)
h.feed("LINE", 5, 20, -2, 9.0, 100)
h.feed("LINE", 5, 20, 2, 2.4, 100)
h.rapid(5, 50, 2)
h.rapid(6, 60, 2)
case("cycle_g90_g94", CYC + "G00 X50. Z2.\nG90 X40. Z-20. F100.\nX35.\nG94 X20. Z-2.\nG00 X60.\n", h.rows)

# G92 from X35 Z5: rapid to the pass diameter, thread 25 mm at 1.5 * 500 =
# 750 mm/min (2 s), rapid out in X, rapid back in Z; "X28.9" repeats it.
h = Hand(rpm500)
h.rapid(2, 35, 5)
for line, x in ((3, 29.4), (4, 28.9)):
    h.rapid(line, x, 5)
    h.feed("THREAD", line, x, -20, 2.0, 750)
    h.rapid(line, 35, -20)
    h.rapid(line, 35, 5)
h.rapid(5, 100, 100)
case("cycle_g92_thread", "G97 S500 M03\nG00 X35. Z5.\nG92 X29.4 Z-20. F1.5\nX28.9\nG00 X100. Z100.\n", h.rows)

# G71 U2 R0.5 / P10 Q20 U0.4 W0.1 from X50 Z2 on the profile X30 Z-20 X40 Z-40
# X50: levels X46 X42 (to the offset shoulder Z-39.9) and X38 X34 (to Z-19.9),
# 45-degree retract X+1 Z+0.5, rapid back to Z2; then the profile offset by
# X+0.4 Z+0.1 and a rapid back to A. The profile blocks are skipped; G70 then
# follows the profile itself and returns to A.
h = Hand(rpm500)
h.rapid(2, 50, 2)
for x, z_end in ((46, -39.9), (42, -39.9), (38, -19.9), (34, -19.9)):
    h.rapid(4, x, 2)
    h.feed("LINE", 4, x, z_end, (2 - z_end) / 100 * 60, 100)
    h.rapid(4, x + 1, z_end + 0.5)
    h.rapid(4, x + 1, 2)
h.rapid(4, 30.4, 2.1)
for x, z, mm in ((30.4, -19.9, 22), (40.4, -19.9, 5), (40.4, -39.9, 20), (50.4, -39.9, 5)):
    h.feed("LINE", 4, x, z, mm / 100 * 60, 100)
h.rapid(4, 50, 2)
h.rapid(10, 30, 2)
for x, z, mm in ((30, -20, 22), (40, -20, 5), (40, -40, 20), (50, -40, 5)):
    h.feed("LINE", 10, x, z, mm / 100 * 60, 100)
h.rapid(10, 50, 2)
h.rapid(11, 100, 100)
case("cycle_g71_g70", CYC + "G00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F100.\nN10 G00 X30.\n"
     "G01 Z-20.\nX40.\nZ-40.\nN20 X50.\nG70 P10 Q20\nG00 X100. Z100.\n", h.rows)

# G74 R1 / Z-10 Q4000 from X0 Z2: pecks to Z-2, -6, -10 (4, 5, 5 mm: 2.4, 3,
# 3 s), backing off 1 mm between, rapid out. G75 R0.5 / X30 Z-24 P3000 Q2000
# from X42 Z-20: in X pecks of 3 mm radius to X36 (1.8 s), back 0.5 to X37,
# on to X30 (3.5 mm, 2.1 s), out to X42; at Z-20, -22, -24; back to the start.
h = Hand(rpm500)
h.rapid(2, 0, 2)
for z, back, secs in ((-2, -1, 2.4), (-6, -5, 3.0), (-10, None, 3.0)):
    h.feed("LINE", 4, 0, z, secs, 100)
    if back is not None:
        h.rapid(4, 0, back)
h.rapid(4, 0, 2)
h.rapid(5, 42, -20)
for z in (-20, -22, -24):
    if z != -20:
        h.rapid(7, 42, z)
    h.feed("LINE", 7, 36, z, 1.8, 100)
    h.rapid(7, 37, z)
    h.feed("LINE", 7, 30, z, 2.1, 100)
    h.rapid(7, 42, z)
h.rapid(7, 42, -20)
case("cycle_g74_g75", CYC + "G00 X0. Z2.\nG74 R1.\nG74 Z-10. Q4000 F100.\nG00 X42. Z-20.\nG75 R0.5\n"
     "G75 X30. Z-24. P3000 Q2000 F100.\n", h.rows)

# G76 P020060 Q50 R0.05 / X28.16 Z-20 P920 Q300 F1.5 from X35 Z5: depths
# 0.3 sqrt(n) up to k - d = 0.87, then 2 passes at k = 0.92 (11 passes). Pass
# at depth d: X = 28.16 + 2 (0.92 - d), starting d tan(30) towards -Z
# (one-flank infeed), thread to Z-20 at 750 mm/min, out in X, back in Z.
depths = [0.3 * math.sqrt(n) for n in range(1, 9)] + [0.87, 0.92, 0.92]
h = Hand(rpm500)
h.rapid(2, 35, 5)
for d in depths:
    zs = 5 - d * math.tan(math.radians(30))
    h.rapid(4, 35, zs)
    h.rapid(4, 28.16 + 2 * (0.92 - d), zs)
    h.feed("THREAD", 4, 28.16 + 2 * (0.92 - d), -20, (zs + 20) / 750 * 60, 750)
    h.rapid(4, 35, -20)
    h.rapid(4, 35, 5)
case("cycle_g76_thread", "G97 S500 M03\nG00 X35. Z5.\nG76 P020060 Q50 R0.05\nG76 X28.16 Z-20. P920 Q300 F1.5\n",
     h.rows)

# G83 Z-20 R-3 Q8000 from the initial level X0 Z5 (Fanuc, G-code system A):
# the R point is 3 mm below the initial level, Z2; 8 mm pecks from it reach
# Z-6, Z-14, Z-20. Between pecks: rapid to Z2, rapid down to d = 1 mm
# (parameter 5115) above the last peck (Z-5, Z-13), feed on at 100 mm/min
# (8, 9, 7 mm: 4.8, 5.4, 4.2 s). Then back to the initial level; G80 ends it.
h = Hand(rpm500)
h.rapid(2, 0, 5)
for z_from, z_to in ((None, -6), (-5, -14), (-13, -20)):
    h.rapid(3, 0, 2)
    if z_from is not None:
        h.rapid(3, 0, z_from)
    h.feed("LINE", 3, 0, z_to, abs(h.z - z_to) / 100 * 60, 100)
h.rapid(3, 0, 5)
case("cycle_g83_fanuc_peck", CYC + "G00 X0 Z5.\nG83 Z-20. R-3. Q8000 F100.\nG80\n", h.rows)


# ---------------------------------------------------------------- program flow (issue 9)
# Every case starts with G98 G00 X40. Z0. from X0 Z300: X 20 mm on the radius
# takes 0.3 s, while Z covers 8000 * 0.3 / 60 = 40 mm (to Z260); then Z alone
# 260 mm = 1.95 s. Feed-per-minute moves take length / F minutes.
def to_x40_z0(line):
    return [row("RAPID", line, 0, 0.3, 0, 300, 40, 260, feed=BOTH),
            row("RAPID", line, 0.3, 2.25, 40, 260, 40, 0, feed=8000)]


# M98 P2000 L2 calls O2000 twice; each pass cuts W-5 (5 mm at 300 = 1 s) and
# calls O3000 twice (L2): U-2 is 1 mm on the radius at 120 mm/min = 0.5 s, the
# rapid U2 back is 1 mm at 4000 mm/min = 0.015 s. Then G00 X60: 10 mm = 0.15 s.
rows = to_x40_z0(2)
t, z = 2.25, 0.0
for _ in range(2):
    rows.append(row("LINE", 7, t, t + 1, 40, z, 40, z - 5, feed=300, level=1, prog="O2000"))
    t, z = t + 1, z - 5
    for _ in range(2):
        rows.append(row("LINE", 11, t, t + 0.5, 40, z, 38, z, feed=120, level=2, prog="O3000"))
        rows.append(row("RAPID", 12, t + 0.5, t + 0.515, 38, z, 40, z, feed=4000, level=2, prog="O3000"))
        t += 0.515
rows.append(row("RAPID", 4, t, t + 0.15, 40, z, 60, z, feed=4000))
case("flow_nested_calls_l_repeats",
     "O0100 (NESTED CALLS)\nG98 G00 X40. Z0.\nM98 P2000 L2\nG00 X60.\nM30\n"
     "O2000 (STEP LEFT, TWO DIPS)\nG01 W-5. F300.\nM98 P3000 L2\nM99\n"
     "O3000 (ONE DIP)\nG01 U-2. F120.\nG00 U2.\nM99\n", rows)

# M99 P50 returns to N50 of the caller, skipping N40 (X80 never happens):
# Z0 -> Z-10 at 600 mm/min = 1 s, then X40 -> X60 = 0.15 s.
case("flow_m99_p_returns_to_n",
     "O0200\nG98 G00 X40. Z0.\nM98 P2100\nN40 G00 X80.\nN50 G00 X60.\nM30\nO2100\nG01 Z-10. F600.\nM99 P50\n",
     to_x40_z0(2) + [
         row("LINE", 8, 2.25, 3.25, 40, 0, 40, -10, feed=600, level=1, prog="O2100"),
         row("RAPID", 5, 3.25, 3.4, 40, -10, 60, -10, feed=4000),
     ])

# Haas M97 P100 L3: the blocks from N100 of the same program up to M99, three
# times; W-4. at 480 mm/min = 0.5 s each. Program O00300 (Haas, G21 for mm).
rows = to_x40_z0(4)
for k in range(3):
    rows.append(row("LINE", 8, 2.25 + 0.5 * k, 2.75 + 0.5 * k, 40, -4 * k, 40, -4 * (k + 1), feed=480,
                    level=1, prog="O0300"))
rows.append(row("RAPID", 6, 3.75, 3.9, 40, -12, 60, -12, feed=4000))
case("flow_m97_haas_local_repeats",
     "%\nO00300 (M97 LOCAL)\nG21 G98\nG00 X40. Z0.\nM97 P100 L3\nG00 X60.\nM30\nN100 G01 W-4. F480.\nM99\n%\n",
     rows, args="--dialect haas")

# A backward GOTO: N10 runs while #1 < 3 after counting, so three times;
# W-2. at 240 mm/min = 0.5 s each.
rows = to_x40_z0(2)
for k in range(3):
    rows.append(row("LINE", 4, 2.25 + 0.5 * k, 2.75 + 0.5 * k, 40, -2 * k, 40, -2 * (k + 1), feed=240))
rows.append(row("RAPID", 7, 3.75, 3.9, 40, -6, 60, -6, feed=4000))
case("flow_goto_backward_loop",
     "O0400\nG98 G00 X40. Z0.\n#1 = 0\nN10 G01 W-2. F240.\n#1 = #1 + 1\nIF [#1 LT 3] GOTO 10\nG00 X60.\nM30\n", rows)

# WHILE DO2 around WHILE DO1: two outer passes of two W-1. cuts (1 mm at
# 120 mm/min = 0.5 s), each outer pass ending with U2. (1 mm radius rapid,
# 0.015 s). Then X44 -> X60: 8 mm at 4000 = 0.12 s.
rows = to_x40_z0(2)
t, z, x = 2.25, 0.0, 40.0
for _ in range(2):
    for _ in range(2):
        rows.append(row("LINE", 7, t, t + 0.5, x, z, x, z - 1, feed=120))
        t, z = t + 0.5, z - 1
    rows.append(row("RAPID", 10, t, t + 0.015, x, z, x + 2, z, feed=4000))
    t, x = t + 0.015, x + 2
rows.append(row("RAPID", 13, t, t + 0.12, 44, z, 60, z, feed=4000))
case("flow_nested_while",
     "O0500\nG98 G00 X40. Z0.\n#1 = 0\nWHILE [#1 LT 2] DO2\n#2 = 0\nWHILE [#2 LT 2] DO1\nG01 W-1. F120.\n"
     "#2 = #2 + 1\nEND1\nG00 U2.\n#1 = #1 + 1\nEND2\nG00 X60.\nM30\n", rows)

# G65 P9600 X30. Z-6. A10. F200.: X -> #24, Z -> #26, A -> #1, F -> #9.
# X40 -> X30 at 200 mm/min: 5 mm = 1.5 s; Z0 -> Z-6: 1.8 s; rapid to X[30+10]
# = X40: 5 mm on the radius = 0.075 s; back in the main: X60, 0.15 s.
case("flow_g65_arguments",
     "O0600\nG98 G00 X40. Z0.\nG65 P9600 X30. Z-6. A10. F200.\nG00 X60.\nM30\n"
     "O9600 (GROOVE TO X#24 Z#26, CLEAR BY #1)\nG01 X#24 F#9\nZ#26\nG00 X[#24+#1]\nM99\n",
     to_x40_z0(2) + [
         row("LINE", 7, 2.25, 3.75, 40, 0, 30, 0, feed=200, level=1, prog="O9600"),
         row("LINE", 8, 3.75, 5.55, 30, 0, 30, -6, feed=200, level=1, prog="O9600"),
         row("RAPID", 9, 5.55, 5.625, 30, -6, 40, -6, feed=4000, level=1, prog="O9600"),
         row("RAPID", 4, 5.625, 5.775, 40, -6, 60, -6, feed=4000),
     ])

# #3000 = 1 stops the run with program alarm 3001 and the comment as its text;
# the G01 after it never runs.
case("flow_program_alarm_3000",
     "O0700\nG98 G00 X40. Z0.\n#1 = 5\nIF [#1 GT 4] THEN #3000 = 1 (DIAMETER TOO SMALL)\nG01 Z-10. F300.\nM30\n",
     to_x40_z0(2), alarm="program.nc:4:1: alarm A130: program alarm 3001 (#3000 = 1): DIAMETER TOO SMALL")
