O9013 (HELIX DOWN FROM THE CURRENT Z TO Z #26 ON RADIUS R #18 ABOUT X #24 Y #25, Q #17 PER TURN)
( Starts at angle 0, X + R; each block is half a turn; the last one stops at Z exactly.      )
#1 = #5003
#2 = 0
WHILE [#1 GT #26] DO1
  #1 = #1 - #17 / 2
  IF [#1 LT #26] THEN #1 = #26
  #2 = 1 - #2
  G3 X[#24 + #18 * [1 - 2 * #2]] Y#25 Z#1 I[#24 - #5001] J0 F#9
END1
IF [#2 EQ 0] GOTO 20
G3 X[#24 + #18] Y#25 I[#24 - #5001] J0 (back to angle 0 at the bottom)
N20 M99
