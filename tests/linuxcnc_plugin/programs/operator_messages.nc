%
O1001 (operator messages: MSG comments and #3006)
G21 G90 G17 G54
G0 X0 Y0 Z5
(MSG, Check the clamps)
G1 X10 F300
( msg,second message )
G1 Y10
#3006 = 1 (TURN THE PART OVER)
G1 X0
M30
%
