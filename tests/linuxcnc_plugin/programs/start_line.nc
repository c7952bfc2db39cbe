(Run from line 14: the blocks before it select tool 2 and its length offset, start the)
(spindle and the flood coolant, set the feed and a variable the blocks after it use.)
G21 G90 G17 G94 G40 G80
G54
T2 M6
G43 H2
S1200 M3
M8
#100 = 30
G0 X20 Y10 Z5
G1 Z-1 F300
G1 X50 F600
G1 Y#100
G1 X20 Y#100
G2 X10 Y20 R10
G1 Y10
G0 Z5
M9
M5
M30
