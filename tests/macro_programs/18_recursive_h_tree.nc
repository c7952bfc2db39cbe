%
O0018 (RECURSIVE G65: AN H-TREE ENGRAVED FOUR MACRO LEVELS DEEP)
( O0181 engraves an H of size S #19 centred at X #24 Y #25, then calls itself at the four tips )
( with half the size while the level K #6 is below the last level - four nested G65 levels,   )
( each with its own locals, the deepest Fanuc allows. The tips come from a WHILE loop over    )
( the quadrants, with SIN and COS of 45 + 90 i for the signs.                                 )
N10 G21 G17 G90 G54
N20 S6000 M3
N30 G0 Z3.
N40 G65 P181 X0 Y0 S160. K1
N50 G0 Z30.
N60 G0 X0 Y0
N70 M5
N80 M30

O0181 (H OF SIZE S AT X Y; RECURSE AT THE TIPS UP TO LEVEL 4)
#1 = #19 / 2
G0 X[#24 - #1] Y[#25 - #1]
G1 Z-0.2 F300
G1 Y[#25 + #1] F1500
G0 Z1.
G0 X[#24 + #1] Y[#25 - #1]
G1 Z-0.2 F300
G1 Y[#25 + #1] F1500
G0 Z1.
G0 X[#24 - #1] Y#25
G1 Z-0.2 F300
G1 X[#24 + #1] F1500
G0 Z1.
IF [#6 GE 4] GOTO 99
#2 = 0
WHILE [#2 LT 4] DO1
  #3 = 45. + 90. * #2
  #4 = ROUND[SQRT[2] * COS[#3]]   (+1 or -1)
  #5 = ROUND[SQRT[2] * SIN[#3]]
  G65 P181 X[#24 + #4 * #1] Y[#25 + #5 * #1] S#1 K[#6 + 1]
  #2 = #2 + 1
END1
N99 M99
%
