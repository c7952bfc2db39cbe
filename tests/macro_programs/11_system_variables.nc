%
O0011 (SYSTEM VARIABLES: WORK OFFSETS WRITTEN BY #5221 AND #5241, POSITIONS FROM #5001 AND #5021,)
( MODAL STATE FROM #4001 #4003 #4109 SAVED AND RESTORED BY A MACRO                              )
( G54 and G55 are set from the program: a two-station fixture. O0111 cuts a small cross at the  )
( current point in G91 and restores the caller's motion group, distance mode and feed after.    )
N10 G21 G17 G90
#5221 = 100.     (G54 X: station 1)
#5222 = -50.
#5223 = -20.
#5241 = #5221 - 180.  (G55 X: station 2, 180 mm to the left)
#5242 = #5222 + 20.
#5243 = #5223
N20 G54 S4000 M3
N30 G0 X0 Y0 Z25.
N40 G1 Z5. F444.
(#5001-#5003: the end point of the previous block, work coordinates)
#1 = #5001
#2 = #5003
N50 G1 X[#1 + 30.] Y[#5002 + 10.] Z[#2 - 5.]
N60 G65 P111 D8.
(#5021: machine coordinates; X here must be G54 X + 30)
#3 = #5021 - #5221
N70 G0 X0 Y0 Z10.
N80 G1 Y-#3 F333.
N90 G55 G0 X0 Y0 (station 2)
N100 G1 Z0 F500.
N110 G65 P111 D12.
N120 G1 X[#5001 + 15.] (the feed and G90 are the caller's again)
(move G54 by 10 mm while it is not active, then use it)
#5221 = #5221 + 10.
N130 G54 G0 X0 Y0 Z10.
N140 G0 Z50.
N150 M5
N160 M30

O0111 (CROSS OF HALF-LENGTH D AT THE CURRENT POINT, INCREMENTAL; MODAL STATE RESTORED)
#10 = #4001      (motion: G0 or G1)
#11 = #4003      (distance: G90 or G91)
#12 = #4109      (feed)
G91 G1 X#7 F150.
X-[2 * #7]
X#7 Y#7
Y-[2 * #7]
Y#7
G#10 G#11 F#12
M99
%
