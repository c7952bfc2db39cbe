%
O0001 (BOLT-HOLE CIRCLE: 8 HOLES ON A 120 MM PCD, PECK DRILLED, WHILE LOOPS WITH SIN/COS)
( A WHILE loop walks the circle; an inner WHILE pecks each hole deeper until the full depth.  )
N10 G21 G17 G90 G40 G54
N20 T1
N30 S2400 M3
N40 M8
#1 = 60.          (pitch circle radius)
#2 = 8            (holes)
#3 = 22.5         (angle of the first hole)
#4 = -18.         (hole depth)
#5 = 4.           (peck)
#6 = 2.           (rapid clearance above the work)
#7 = 150.         (drilling feed)
#10 = 0           (hole counter)
N50 G0 Z[#6 + 10.]
WHILE [#10 LT #2] DO1
  #11 = #3 + 360. * #10 / #2
  #12 = #1 * COS[#11]
  #13 = #1 * SIN[#11]
  G0 X#12 Y#13
  G0 Z#6
  #14 = 0
  WHILE [#14 GT #4] DO2
    #14 = #14 - #5
    IF [#14 LT #4] THEN #14 = #4
    G1 Z#14 F#7
    G0 Z#6
  END2
  #10 = #10 + 1
END1
N60 G0 Z50.
N70 M9
N80 M5
N90 G0 X0 Y0
N100 M30
%
