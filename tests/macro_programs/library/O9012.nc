O9012 (FRAME CHAMFER: A #150 X #151 RECTANGLE CENTRED ON THE ORIGIN, 0.8 MM DEEP, CORNER R 5)
#1 = #150 / 2
#2 = #151 / 2
#3 = 5.
G0 X[-#1 + #3] Y-#2
G1 Z-0.8 F300
G1 X[#1 - #3] F1200
G3 X#1 Y[-#2 + #3] R#3
G1 Y[#2 - #3]
G3 X[#1 - #3] Y#2 R#3
G1 X[-#1 + #3]
G3 X-#1 Y[#2 - #3] R#3
G1 Y[-#2 + #3]
G3 X[-#1 + #3] Y-#2 R#3
G0 Z10.
M99
