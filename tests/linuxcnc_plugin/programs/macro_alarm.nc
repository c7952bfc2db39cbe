%
O2000 (A MACRO ALARM IN THE MIDDLE OF A LOOP: THE MACHINE STOPS BEFORE THAT BLOCK MOVES)
( Three squares of a row of five are milled; the fourth square's check raises alarm 3007. )
N10 G21 G17 G90 G54 G94
N20 G0 X0 Y0 Z5.
N30 S3000 M3
#1 = 0                                    (square number)
WHILE [#1 LT 5] DO1
  #2 = #1 * 25.                           (X of the square's corner)
  IF [#1 EQ 3] THEN #3000 = 7 (CLAMP PRESSURE LOST)
  G0 X#2 Y0
  G1 Z-1. F300.
  G1 X[#2 + 10.] F600.
  Y10.
  X#2
  Y0
  G0 Z5.
  #1 = #1 + 1
END1
M5
M30
%
