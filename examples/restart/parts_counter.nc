%
O0020 (SPOT DRILL A ROW OF HOLES AND COUNT PARTS IN RETAINED VARIABLES, FOR nckit restart --journal)
( Machine: examples/machines/mill.toml.  #500 counts parts started, #501 the last hole begun, )
( #502 parts finished: a restart from a run journal must not count the part twice. )
N10 G21 G17 G90 G94 G40 G49 G80
N11 G10 L2 P1 X60. Y40. Z-50.
N12 G54 T1 M6
N13 S2000 M3
#500 = #500 + 1
#1 = 0
WHILE [#1 LT 8] DO1
#501 = #1 + 1
N40 G0 X[#1 * 12.5] Y[#1 * 4.]
N41 Z2.
N42 G1 Z-3. F150.
N43 G2 X[#1 * 12.5 + 4.] Y[#1 * 4.] I2. J0 F300.
N44 G0 Z5.
#1 = #1 + 1
END1
#502 = #502 + 1
N90 M5
N91 G0 Z50.
M30
%
