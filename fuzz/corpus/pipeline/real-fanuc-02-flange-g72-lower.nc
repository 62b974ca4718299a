%
:0200(flange hub, facing cycle)
n10 g21 g40 g99
n20 g28 u0 w0
n30 t0101(od 80deg r0.8)
n40 g50 s1800
n50 g96 s160 m3
n60 g0 x104. z2. m8
n70 g72 w2. r.5
n80 g72 p90 q155 u.4 w.2 f.3
n90 g0 z-20.
n100 g1 x80. f.12
n110 z-12.
n120 x50.
n130 z-2.
n140 x46. z0.
n150 x-1.6
n155 z2.
n160 g0 x200. z150.
n165 g41 x104. z2.
n170 g70 p90 q155
n180 g0 g40 x200. z150. m9
n190 m5
n200 m30
%
