%
O0010 (M99 P: RETURN TO A SEQUENCE NUMBER OF THE CALLER; EARLY RETURN FROM A SUBPROGRAM)
( Four parts sit in a row on the fixture. O0101 machines the part at #120 and counts it; after )
( the last one it returns with M99 P900, past the caller's GOTO that would start another part. )
( O0102 returns early - a plain M99 in the middle - when the part needs no chamfer.             )
N10 G21 G17 G90 G54
N20 S3500 M3
#120 = 0         (parts done)
#121 = 4         (parts on the fixture)
#122 = -90.      (X of the first part)
#123 = 60.       (part pitch)
G0 Z10.
N100 M98 P101
N110 GOTO 100
N120 G0 X400. Y400. (skipped: M99 P900 comes back below it)
N900 G0 Z50.
N910 G0 X0 Y0
N920 M5
N930 M30

O0101 (ONE PART: A 40 X 20 CONTOUR, THEN MAYBE A CHAMFER)
#1 = #122 + #120 * #123
G0 X[#1 - 20.] Y-10.
G1 Z-3. F250
G1 X[#1 + 20.] F900
G1 Y10.
G1 X[#1 - 20.]
G1 Y-10.
G0 Z2.
M98 P102
#120 = #120 + 1
IF [#120 GE #121] GOTO 50
M99
N50 M99 P900

O0102 (CHAMFER ONLY THE EVEN PARTS)
IF [[#120 MOD 2] EQ 0] GOTO 20
M99 (odd part: back to the caller at once)
N20 G0 X[#1 - 21.] Y-11.
G1 Z-0.5 F250
G1 X[#1 + 21.] F900
G1 Y11.
G1 X[#1 - 21.]
G1 Y-11.
G0 Z2.
M99
%
