(The second notch's run-up crosses the first notch's path: refused.)
G90 G1 X10 Z50 F3000
M27
G1 Z20 F950
M28
G0 X10.0005 Z30
G1 Z25 F3000
M27
G1 X30 F950
M28
G0 X50 Z99.5
M27
G1 Z80 F950
M30
