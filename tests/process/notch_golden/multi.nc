(Several notches on the notcher: a run-up on a long approach, a head that steps back,)
(two cuts in a row, an arc on the way, a cut without a programmed laser-off.)
G90 G18 G1 X10 Z50 F3000
M24
G1 Z20 F5000
M27
G1 Z5 F950
M28
G0 X30 Z25
G1 Z20 F3000
M27
G1 Z10 F1200
M27
G1 X40 F800
M28
G0 X60 Z40
G2 X80 Z40 R10 F2000
G0 Z30
M27
G1 X95 Z22.5 F700
G0 X120
M27
G1 Z2.25 F1500
G1 X140 F3000
M25
M30
