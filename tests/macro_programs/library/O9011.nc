O9011 (SLOT WITH ROUND ENDS: START X #24 Y #25, LENGTH U #21 ALONG +X, WIDTH D #7, Z #26, Q #17, F #9)
( Tool diameter 10: a slot as wide as the tool is a plunge-and-feed at each level; a wider one )
( also cuts its outline with G2 ends.                                                          )
#1 = #7 / 2 - 5.          (outline offset of the tool centre)
#2 = 0
G0 X#24 Y#25
G0 Z1.
WHILE [#2 GT #26] DO1
  #2 = #2 - #17
  IF [#2 LT #26] THEN #2 = #26
  G1 Z#2 F[#9 / 2]
  G1 X[#24 + #21] F#9
  IF [#1 LE 0] GOTO 10
  G1 Y[#25 - #1]
  G2 X[#24 + #21] Y[#25 + #1] I0 J#1
  G1 X#24
  G2 X#24 Y[#25 - #1] I0 J-#1
  G1 Y#25
  N10 G1 X#24
END1
G0 Z10.
M99
