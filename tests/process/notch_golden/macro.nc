(Notches made by a Macro B loop: one notch every 12.5 mm along the tube.)
G90 G1 X0 Z30 F3000
#1 = 0
WHILE [#1 LT 6] DO1
G0 X[10 + #1 * 12.5] Z30
G1 Z20 F4000
M27
G1 Z[8 - #1] F[900 + #1 * 100]
M28
#1 = #1 + 1
END1
G0 X150 Z50
M30
