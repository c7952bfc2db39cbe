%
O0007 (G65 MACRO CALLS: ARGUMENT SPECIFICATION I AND II, NESTED CALLS, L REPEATS)
( O0071 rectangular pocket outline with rounded corners, specification I:                   )
(   X #24 Y #25 centre, U #21 V #22 size, R #18 corner radius, Z #26 depth, F #9 feed.      )
( O0072 polyline through up to ten points, specification II: A #1 feed, then I J K triples   )
(   I1 #4 J1 #5 K1 #6 ... = X Y Z of each point; an empty triple ends the list.              )
( O0073 a corner arc, called by O0071 four times: a second macro level with its own locals.  )
( O0074 a drilled hole; G65 L3 repeats it along X, the step kept in common variable #100.    )
N10 G21 G17 G90 G54
N20 S5000 M3
#1 = 111.        (a local of the main program: the calls must not change it)
G0 Z5.
N30 G65 P71 X-60. Y40. U50. V30. R6. Z-4. F800.
N40 G65 P71 X60. Y40. U40. V40. R10. Z-3. F600.
N50 G65 P72 A900. I-80. J-20. K-1. I-40. J-50. K-1.5 I0 J-20. K-2. I40. J-50. K-1.5 I80. J-20. K-1.
#100 = -50.
N60 G65 P74 L3 X25. Z-6. F150.
(the main program's #1 is still 111: move to X = #1 - 111)
N70 G0 Z30.
N80 G0 X[#1 - 111.] Y0
N90 M5
N100 M30

O0071 (RECTANGULAR OUTLINE WITH ROUNDED CORNERS)
IF [#18 EQ #0] THEN #18 = 0
#1 = #21 / 2 - #18
#2 = #22 / 2 - #18
G0 X[#24 - #21 / 2] Y[#25 - #2]
G1 Z#26 F[#9 / 3]
G1 Y[#25 + #2] F#9
G65 P73 X[#24 - #1] Y[#25 + #2] R#18 A180. F#9
G1 X[#24 + #1]
G65 P73 X[#24 + #1] Y[#25 + #2] R#18 A90. F#9
G1 Y[#25 - #2]
G65 P73 X[#24 + #1] Y[#25 - #2] R#18 A0 F#9
G1 X[#24 - #1]
G65 P73 X[#24 - #1] Y[#25 - #2] R#18 A270. F#9
G0 Z5.
M99

O0072 (POLYLINE THROUGH I J K TRIPLES)
G0 X#4 Y#5
G1 Z#6 F[#1 / 3]
#2 = 7           (number of the next X variable; B is no argument here)
WHILE [#2 LE 31] DO1
  IF [#[#2] EQ #0] GOTO 90
  G1 X#[#2] Y#[#2 + 1] Z#[#2 + 2] F#1
  #2 = #2 + 3
END1
N90 G0 Z5.
M99

O0073 (CORNER ARC: CENTRE X Y, RADIUS R, FROM ANGLE A TO A - 90, CLOCKWISE)
IF [#18 LE 0] GOTO 99
#2 = #1 - 90.
G2 X[#24 + #18 * COS[#2]] Y[#25 + #18 * SIN[#2]] I[-#18 * COS[#1]] J[-#18 * SIN[#1]] F#9
N99 M99

O0074 (ONE HOLE AT X = #100 + X, THEN #100 ADVANCES)
#100 = #100 + #24
G0 X#100 Y-10.
G1 Z#26 F#9
G0 Z5.
M99
%
