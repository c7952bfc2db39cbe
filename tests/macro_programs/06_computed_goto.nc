%
O0006 (COMPUTED GOTO: A DISPATCH TABLE OF ENGRAVED SHAPES)
( Six stations in a row. The shape of each is [station MOD 4] + 1, and GOTO #20 jumps to the   )
( block N1000 + 100 * shape: 1 square, 2 triangle, 3 circle, 4 slot with round ends. Every     )
( shape ends with GOTO 900, which moves on to the next station.                                )
N10 G21 G17 G90 G54
N20 S6000 M3
#1 = 6           (stations)
#2 = -100.       (X of station 0)
#3 = 40.         (pitch)
#4 = 10.         (shape size)
#5 = -0.5        (depth)
#10 = 0
G0 Z5.
N900 IF [#10 GE #1] GOTO 2000
#11 = #2 + #10 * #3          (station centre X)
#12 = 20. - 10. * [#10 MOD 3] (station centre Y)
#13 = [#10 MOD 4] + 1
#10 = #10 + 1
#20 = 1000 + 100 * #13
GOTO #20
N1100 (square)
G0 X[#11 - #4 / 2] Y[#12 - #4 / 2]
G1 Z#5 F200
G1 X[#11 + #4 / 2] F600
G1 Y[#12 + #4 / 2]
G1 X[#11 - #4 / 2]
G1 Y[#12 - #4 / 2]
G0 Z2.
GOTO 900
N1200 (equilateral triangle, corners at 90 210 330 degrees)
#21 = #4 / SQRT[3]
G0 X#11 Y[#12 + #21]
G1 Z#5 F200
#22 = 210.
WHILE [#22 LE 450.] DO1
  G1 X[#11 + #21 * COS[#22]] Y[#12 + #21 * SIN[#22]] F600
  #22 = #22 + 120.
END1
G0 Z2.
GOTO 900
N1300 (circle)
G0 X[#11 + #4 / 2] Y#12
G1 Z#5 F200
G2 X[#11 + #4 / 2] Y#12 I[-#4 / 2] J0 F600
G0 Z2.
GOTO 900
N1400 (slot with round ends, R programmed)
#23 = #4 / 4
G0 X[#11 - #4 / 2] Y[#12 - #23]
G1 Z#5 F200
G1 X[#11 + #4 / 2] F600
G3 X[#11 + #4 / 2] Y[#12 + #23] R#23
G1 X[#11 - #4 / 2]
G3 X[#11 - #4 / 2] Y[#12 - #23] R#23
G0 Z2.
GOTO 900
N2000 G0 Z40.
N2010 M5
N2020 M30
%
