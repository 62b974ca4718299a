%
O20020 (STOP PIN - SEMICOLON COMMENTS)
G20 G40 G99 ; inch, cancel comp, feed per rev
G28 ; home
T101 ; OD tool (80 deg CNMG)
G50 S2000
G96 S500 M03
G00 X1.1 Z0.1 M08 ; approach
G01 Z0. F0.006 ; face
X-0.03
G00 Z0.1
X0.8
G01 Z-1.0 F0.01 ; turn to 0.8
X1.1
G00 Z0.1
X0.6
G01 Z-0.5 F0.006 ; turn to 0.6 (the pin)
X1.1
G53 G00 X0 ; X home first
G53 Z0
M30
%
