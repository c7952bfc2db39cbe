%
O0015 (FIXTURE PLATE FROM A MACRO LIBRARY: COUNTERBORES, A SLOT, A CHAMFERED FRAME)
( Run with --library tests/macro_programs/library: O9010 counterbore, which calls O9013     )
( helix; O9011 slot with round ends; O9012 frame chamfer, an M98 subprogram that reads its    )
( size from common variables #150 and #151.                                                   )
N10 G21 G17 G90 G54
N20 S5000 M3
N30 G0 Z10.
(four counterbores on the diagonals)
#1 = 0
WHILE [#1 LT 4] DO1
  #2 = 90. * #1 + 45.
  G65 P9010 X[70. * COS[#2]] Y[70. * SIN[#2]] D16. Z-6. Q1.5 F500.
  #1 = #1 + 1
END1
(a slot from X-40 to X40 along the X axis, 10 wide)
N40 G65 P9011 X-40. Y0 U80. D10. Z-4. Q1.5 F400.
(chamfer around the plate)
#150 = 200.
#151 = 160.
N50 M98 P9012
N60 G0 Z50.
N70 M5
N80 M30
%
