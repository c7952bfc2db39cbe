%
O0008 (G66 MODAL MACRO CALL: A PECK-DRILLING MACRO RUN AFTER EVERY POSITIONING BLOCK)
( O0081 drills where the positioning block left the tool: R #18 rapid plane, Z #26 depth,     )
( Q #17 peck, F #9 feed; it returns to the Z it started from, read from #5003.                )
( Positions: a square of 4, then a WHILE loop of 5 holes on an arc; G67 cancels, then a       )
( second G66 with other arguments drills 3 deeper holes.                                       )
N10 G21 G17 G90 G54
N20 S3000 M3
N30 M8
N40 G0 Z20.
N50 G0 X-60. Y-60.
N60 G66 P81 R2. Z-12. Q5. F120.
N70 X-30.
N80 Y-30.
N90 X-60.
N100 Y-60.
(five holes on an arc of radius 70 about the origin, 30 to 150 degrees)
#1 = 30.
WHILE [#1 LE 150.] DO1
  G0 X[70. * COS[#1]] Y[70. * SIN[#1]]
  #1 = #1 + 30.
END1
N110 G67
N120 G0 X0 Y0 (no hole here)
N130 G66 P81 R5. Z-30. Q8. F90.
N140 G0 X50. Y-40.
N150 X70.
N160 X90.
N170 G67
N180 G0 Z50.
N190 M9
N200 M5
N210 M30

O0081 (PECK DRILL AT THE CURRENT XY)
#1 = #5003              (initial Z)
#2 = #18                (bottom of the last peck)
G0 Z#18
WHILE [#2 GT #26] DO1
  #2 = #2 - #17
  IF [#2 LT #26] THEN #2 = #26
  G1 Z#2 F#9
  G0 Z#18
END1
G0 Z#1
M99
%
