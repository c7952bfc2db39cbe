O9010 (COUNTERBORE: X #24 Y #25 CENTRE, D #7 DIAMETER, Z #26 DEPTH, Q #17 PER TURN, F #9)
( Tool diameter 10 assumed: the helix runs on radius D/2 - 5, then one full circle at depth. )
IF [#7 LE 10.] GOTO 90
#1 = #7 / 2 - 5.
G0 X[#24 + #1] Y#25
G0 Z1.
G65 P9013 X#24 Y#25 R#1 Z#26 Q#17 F#9
G3 X[#24 + #1] Y#25 I-#1 J0 F#9
G1 X#24 Y#25
G0 Z10.
N90 M99
