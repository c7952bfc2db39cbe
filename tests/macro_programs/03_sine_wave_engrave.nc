%
O0003 (ENGRAVED SINE WAVES: 5 ROWS, ALTERNATE DIRECTIONS, PHASE SHIFT PER ROW)
( Each row is y = Y0 + A * SIN[360 * x / L + phase], written as 2 mm chords. Odd rows run     )
( backwards - MOD picks the direction - and the amplitude shrinks by 20% per row.                   )
N10 G21 G17 G90 G54
N20 S5000 M3
#1 = -60.        (X start)
#2 = 60.         (X end)
#3 = 40.         (wavelength)
#4 = 6.          (amplitude of row 0)
#5 = 2.          (chord length along X)
#6 = 5           (rows)
#7 = 18.         (row pitch)
#8 = -0.3        (engraving depth)
#9 = 45.         (phase shift per row, degrees)
#10 = 0
WHILE [#10 LT #6] DO1
  #11 = -36. + #10 * #7                   (row centre line Y)
  #12 = #4 * [1 - 0.2 * #10]              (amplitude)
  #13 = #9 * #10                          (phase)
  #14 = [#10 MOD 2]                       (0: left to right, 1: right to left)
  #15 = FIX[[#2 - #1] / #5 + 0.5]         (chords per row)
  #16 = 0
  #17 = #1 + [#2 - #1] * #14              (first x)
  #18 = #5 * [1 - 2 * #14]                (signed step)
  G0 X#17 Y[#11 + #12 * SIN[360. * [#17 - #1] / #3 + #13]]
  G1 Z#8 F300
  WHILE [#16 LT #15] DO2
    #16 = #16 + 1
    #19 = #17 + #18 * #16
    G1 X#19 Y[#11 + #12 * SIN[360. * [#19 - #1] / #3 + #13]] F1200
  END2
  G0 Z2.
  #10 = #10 + 1
END1
N30 G0 Z25.
N40 M5
N50 M30
%
