O0005
N10 G21 G97
N15 G99
N20 T0101
N30 G00 X45. Z2.
N40 G01 X38. Z-10. F0.2 (alarm: cutting while the spindle is stopped)
N50 M30
