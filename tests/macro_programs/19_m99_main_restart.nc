%
O0019 (M99 IN THE MAIN PROGRAM: A PALLET OF 5 PARTS, THE PROGRAM RESTARTS ITSELF)
( The main program ends in M99, which starts it again from the top, as a bar feeder job     )
( does. Common variable #130 counts the parts across the restarts: vacant at the first pass,  )
( so the start-up blocks run once. #3901 counts parts machined; after the fifth part IF GOTO   )
( reaches M30.                                                                                )
N10 G21 G17 G90 G54
IF [#130 NE #0] GOTO 20
N15 S3000 M3 (first pass only)
#130 = 0
N20 #1 = -100. + 50. * #130
N30 G0 X#1 Y-20. Z5.
N40 G1 Z-2. F400
N50 G1 Y20. F1000
N60 G2 X[#1 + 20.] Y20. R10.
N70 G1 Y-20.
N80 G0 Z5.
#130 = #130 + 1
#3901 = #3901 + 1
IF [#130 GE 5] GOTO 900
N100 M99
N900 G0 Z50.
N910 M5
N920 M30
%
