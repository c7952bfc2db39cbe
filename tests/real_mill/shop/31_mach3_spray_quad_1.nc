(Set-up for Quadrant 1 of spray area)
G00 Z-2 (Move Z-axis down 2 inches)
G00 Y9 (Move Y-axis 9 inches)
G01 Y40 F500 M3 (Sprayer on / move 40 inches)
M5 (Sprayer-off)
G00 X2 (Move X-axis over by step)
G01 Y9 F500 M3
M5 (Sprayer-off)
G00 X4
G01 Y40 F500 M3
M5 (Sprayer-off)
G00 X6
G01 Y9 F500 M3
M5 (Sprayer-off)
G00 X8
G01 Y40 F500 M3
M5 (Sprayer-off)
G00 X10
G01 Y9 F500 M3
M5 (Sprayer-off)
G00 X12
G01 Y40 F500 M3
M5 (Sprayer-off)
G00 X14
G01 Y9 F500 M3
M5 (Sprayer-off)
G00 X16
G01 Y40 F500 M3
M5 (Sprayer-off)
G00 X18
G01 Y9 F500 M3
M5 (Sprayer-off)
G00 X20
G01 Y40 F500 M3
M5 (Sprayer-off)
G00 X22
G01 Y9 F500 M3
M5 (Sprayer-off)
G00 X24
G01 Y40 F500 M3
M5 (Sprayer-off)
G00 X26
G01 Y9 F500 M3
M5 (Sprayer-off)
G00 X28
G01 Y40 F500 M3
M5 (Sprayer-off)
G00 Z0 (Return Z-axis to Zero)
X0 Y0 (Return X-axis and Y-axis to zero 'Home')
M30 (End program)
