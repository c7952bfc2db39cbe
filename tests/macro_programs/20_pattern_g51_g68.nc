%
O0020 (ONE GROOVE MOTIF AS A SUBPROGRAM, PLACED BY G52 + M98, MIRRORED, SCALED AND ROTATED)
( O0201 cuts a chevron and an arc round its local origin. The main program places it with   )
( G52 four times: as drawn; mirrored in X - G51.1 X0, the G3 becomes a G2 -; at half size      )
( - G51 I0.5 J0.5, Z not scaled -; turned 30 degrees - G68 R30 -; and then a ring of six copies from a WHILE loop    )
( with G68 R[#1] about the ring's centre, mirrored in Y as well - nesting: mirror, then         )
( rotation -. G50.1, G50 and G69 cancel each one.                                                )
N10 G21 G17 G90 G54 G94
N20 S3000 M3
N30 G0 Z2.
N40 G52 X-60. Y40.
N50 M98 P201
N60 G52 X0 Y40.
N70 G51.1 X0
N80 M98 P201
N90 G50.1 X0
N100 G52 X60. Y40.
N110 G51 X0 Y0 I0.5 J0.5
N120 M98 P201
N130 G50
N140 G52 X-60. Y-20.
N150 G68 X0 Y0 R30.
N160 M98 P201
N170 G69
N180 G52 X40. Y-30.
N190 G51.1 Y0
#1 = 0
WHILE [#1 LT 360] DO1
G68 X0 Y0 R#1
G52 X40. Y-30.
M98 P202
G69
#1 = #1 + 60.
END1
N200 G50.1 Y0
N210 G52 X0 Y0
N220 G0 Z10.
N230 X0 Y0
N240 M5
N250 M30

O0201 (CHEVRON AND ARC ROUND THE LOCAL ORIGIN)
G0 X-8. Y-4.
G1 Z-1. F150
G1 X0 Y4. F400
G1 X8. Y-4.
G0 Z2.
G0 X-6. Y-10.
G1 Z-1. F150
G3 X6. Y-10. I6. J0 F400
G0 Z2.
M99

O0202 (ONE SPOKE OF THE RING: A SHORT GROOVE 15 TO 25 MM OUT ALONG X)
G0 X15. Y0
G1 Z-0.5 F150
G1 X25. Y2. F400
G0 Z2.
M99
%
