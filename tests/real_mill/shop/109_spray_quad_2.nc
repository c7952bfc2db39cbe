; (Set-up for Quadrant 2 of spray area) - Move to the starting position 2
G00 Z-2 ; Move Z-axis down 2 inches
G00 Y9 ; Move Y-axis 9 inches
G01 Y40 F500 M3 ; Sprayer on / move 40 inches
M5 ; Sprayer-off
G00 X2 ; Move X-axis over by step
G01 Y9 F500 M3 ; Sprayer on / move 9 inches
M5 ; Sprayer-off
G00 X4 ; Move X-axis over by step
G01 Y40 F500 M3 ; Sprayer on / move 40 inches
M5 ; Sprayer-off
G00 X6 ; Move X-axis over by step
G01 Y9 F500 M3 ; Sprayer on / move 9 inches
M5 ; Sprayer-off
G00 X8 ; Move X-axis over by step
G01 Y40 F500 M3 ; Sprayer on / move 40 inches
M5 ; Sprayer-off
G00 X10 ; Move X-axis over by step
G01 Y9 F500 M3 ; Sprayer on / move 9 inches
M5 ; Sprayer-off
G00 X12 ; Move X-axis over by step
G01 Y40 F500 M3 ; Sprayer on / move 40 inches
M5 ; Sprayer-off
G00 X14 ; Move X-axis over by step
G01 Y9 F500 M3 ; Sprayer on / move 9 inches
M5 ; Sprayer-off
G00 X16 ; Move X-axis over by step
G01 Y40 F500 M3 ; Sprayer on / move 40 inches
M5 ; Sprayer-off
G00 X18 ; Move X-axis over by step
G01 Y9 F500 M3 ; Sprayer on / move 9 inches
M5 ; Sprayer-off
G00 X20 ; Move X-axis over by step
G01 Y40 F500 M3 ; Sprayer on / move 40 inches
M5 ; Sprayer-off
G00 X22 ; Move X-axis over by step
G01 Y9 F500 M3 ; Sprayer on / move 9 inches
M5 ; Sprayer-off
G00 X24 ; Move X-axis over by step
G01 Y40 F500 M3 ; Sprayer on / move 40 inches
M5 ; Sprayer-off
G00 X26 ; Move X-axis over by step
G01 Y9 F500 M3 ; Sprayer on / move 9 inches
M5 ; Sprayer-off
G00 X28 ; Move X-axis over by step
G01 Y40 F500 M3 ; Sprayer on / move 40 inches
M5 ; Sprayer-off
G00 Z0 ; Return Z-axis to Zero
X0 Y0 ; Return X-axis and Y-axis to zero 'Home'
M30 ; End program

