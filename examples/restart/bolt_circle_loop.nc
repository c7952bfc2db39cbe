%
O0019 (SIX SPOT-FACED HOLES ON A BOLT CIRCLE - MACRO B LOOP, FOR nckit restart)
( Machine: examples/machines/mill.toml.  Part zero: centre of the circle, G54 set by G10. )
( The tool broke at the fourth hole: restart with --seq 40:4, the 4th time N40 is reached. )
N10 G21 G17 G90 G94 G40 G49 G80
N11 G10 L2 P1 X100. Y80. Z-50.
N12 G54 T1 M6
N13 S2400 M3
N14 M8
#1 = 40.                   (bolt circle radius)
#2 = 0                     (hole counter)
WHILE [#2 LT 6] DO1
#3 = #2 * 60.
N40 G0 X[#1 * COS[#3]] Y[#1 * SIN[#3]]
N41 Z2.
N42 G1 Z-3. F150.
N43 G91 G2 I-2. J0 F300.
N44 G90 G0 Z5.
#2 = #2 + 1
END1
N90 M9
N91 M5
N92 G0 Z50.
M30
%
