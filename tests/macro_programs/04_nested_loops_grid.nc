%
O0004 (GRID OF 3 X 2 RECTANGULAR POCKETS - THREE NESTED WHILE LOOPS DO1 DO2 DO3)
( DO1 rows, DO2 columns, DO3 depth passes: each pass cuts the pocket outline, then O0041      )
( zigzags its inside with a DO1 loop of its own - loops belong to their program level.        )
( A second, separate DO1 loop at the end chamfers the grid outline: a loop number reused.     )
N10 G21 G17 G90 G54
N20 S4500 M3
N30 M8
#1 = 3           (columns)
#2 = 2           (rows)
#3 = 40.         (column pitch)
#4 = 35.         (row pitch)
#5 = 24.         (pocket length, tool centre)
#6 = 16.         (pocket width, tool centre)
#7 = 2.5         (depth per pass)
#8 = -7.         (final depth)
#9 = 3.          (zigzag stepover)
#20 = -40.       (X of the first pocket centre)
#21 = -17.5      (Y of the first pocket centre)
G0 Z5.
#10 = 0
WHILE [#10 LT #2] DO1
  #11 = 0
  WHILE [#11 LT #1] DO2
    #12 = #20 + #11 * #3 - #5 / 2     (pocket corner X)
    #13 = #21 + #10 * #4 - #6 / 2     (pocket corner Y)
    G0 X#12 Y#13
    G1 Z0.5 F500
    #14 = 0
    WHILE [#14 GT #8] DO3
      #14 = #14 - #7
      IF [#14 LT #8] THEN #14 = #8
      G1 Z#14 F200
      G1 X[#12 + #5] F700
      G1 Y[#13 + #6]
      G1 X#12
      G1 Y#13
      M98 P41
    END3
    G0 Z5.
    #11 = #11 + 1
  END2
  #10 = #10 + 1
END1
(chamfer around the whole grid: four sides, one DO1 loop again)
#30 = #20 - #5 / 2 - 6.
#31 = #21 - #6 / 2 - 6.
#32 = [#1 - 1] * #3 + #5 + 12.
#33 = [#2 - 1] * #4 + #6 + 12.
G0 X#30 Y#31
G1 Z-1. F300
#10 = 0
WHILE [#10 LT 4] DO1
  IF [#10 EQ 0] THEN #30 = #30 + #32
  IF [#10 EQ 1] THEN #31 = #31 + #33
  IF [#10 EQ 2] THEN #30 = #30 - #32
  IF [#10 EQ 3] THEN #31 = #31 - #33
  G1 X#30 Y#31 F800
  #10 = #10 + 1
END1
N40 G0 Z30.
N50 M9
N60 M5
N70 M30

O0041 (ZIGZAG INSIDE THE POCKET AT THE CURRENT DEPTH; SHARES #12 #13 #5 #6 #9)
#140 = #13
#141 = 0
WHILE [#140 LT [#13 + #6]] DO1
  #140 = #140 + #9
  IF [#140 GT [#13 + #6]] THEN #140 = #13 + #6
  #141 = 1 - #141
  G1 X[#12 + #5 * #141] F700
  G1 Y#140
END1
G1 X#12 Y#13
M99
%
