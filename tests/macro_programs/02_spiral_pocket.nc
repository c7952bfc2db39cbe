%
O0002 (CIRCULAR POCKET CLEARED BY AN ARCHIMEDEAN SPIRAL, HELICAL RAMP ENTRY)
( Pocket D70 at X100 Y50, 6 mm deep in two levels. Per level: a helical ramp down on a small  )
( circle, then a spiral of 6.5-degree G1 chords out to the finished radius, then a full circle.  )
N10 G21 G17 G90 G54 G40
N20 S6000 M3
#1 = 100.        (centre X)
#2 = 50.         (centre Y)
#3 = 35.         (pocket radius)
#4 = 5.          (tool radius)
#5 = 4.          (stepover per turn)
#6 = 3.          (depth per level)
#7 = 2           (levels)
#8 = 6.5         (angle step, degrees)
#9 = 900.        (feed)
#20 = #3 - #4    (radius of the tool centre at the wall)
#21 = 2.         (helix radius)
N30 G0 X[#1 + #21] Y#2
N40 G0 Z2.
#10 = 1
WHILE [#10 LE #7] DO1
  #11 = -#6 * #10
  (helical ramp: two turns from the level above)
  G3 X[#1 + #21] Y#2 Z[#11 + #6 / 2] I-#21 J0 F[#9 / 3]
  G3 X[#1 + #21] Y#2 Z#11 I-#21 J0
  (spiral r = #21 + #5 * angle / 360 until the wall radius)
  #12 = 0
  #13 = #21
  WHILE [#13 LT #20] DO2
    #12 = #12 + #8
    #13 = #21 + #5 * #12 / 360.
    IF [#13 GT #20] THEN #13 = #20
    G1 X[#1 + #13 * COS[#12]] Y[#2 + #13 * SIN[#12]] F#9
  END2
  (finish the wall with a full circle from where the spiral ended)
  #14 = #5001 - #1
  #15 = #5002 - #2
  G3 X#5001 Y#5002 I-#14 J-#15
  G1 X[#1 + #21] Y#2
  #10 = #10 + 1
END1
N50 G0 Z20.
N60 M5
N70 G0 X0 Y0
N80 M30
%
