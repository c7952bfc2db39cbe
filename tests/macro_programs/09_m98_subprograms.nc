%
O0009 (M98 SUBPROGRAMS: P AND L, THE PACKED FORM P30123, NESTING, INCREMENTAL PATTERNS)
( O0091 cuts one slot and steps 25 mm along X in G91: M98 P91 L4 cuts four of them.          )
( M98 P30123 is the packed form: three repeats of O0123, which steps down 2 mm in G91 and     )
( calls O0124, a square contour, as a nested subprogram.                                       )
( Subprograms share the caller's variables: O0124 reads #110, its size, from the main program. )
N10 G21 G17 G90 G54
N20 S4000 M3
N30 G0 Z5.
N40 G0 X-90. Y60.
N50 M98 P91 L4
N60 G90 G0 Z5.
#110 = 50.
N70 G0 X-25. Y-25.
N80 G1 Z0 F300
N90 M98 P30123
N100 G90 G0 Z10.
(the last slot and the square once more, from a different start, with L1 and plain P)
N110 G0 X60. Y50.
N120 M98 P91
N130 G90 G1 Z-1. F300
N140 M98 P124 L2
N150 G90 G0 Z40.
N160 M5
N170 M30

O0091 (ONE SLOT 15 MM LONG IN -Y, THEN 25 MM ALONG +X; INCREMENTAL)
G91 G1 Z-8. F200
G1 Y-15. F500
G0 Z8.
G0 X25. Y15.
M99

O0123 (ONE LEVEL: 2 MM DOWN, THEN THE SQUARE)
G91 G1 Z-2. F150
M98 P124
M99

O0124 (SQUARE OF SIDE #110 FROM THE CURRENT POINT, COUNTERCLOCKWISE; INCREMENTAL)
G91 G1 X#110 F700
Y#110
X-#110
Y-#110
M99
%
