( nckit-machine: lathe_b.toml )
%
O0016 (LATHE, INCH: 1/2-13 UNC THREAD AND A FINISH FEED FROM THE SURFACE FINISH WANTED)
( G20: X diameters and Z in inches. The finishing feed per revolution comes from the peak-to- )
( valley height Rt = f^2 / 8 r of a nose radius r: f = SQRT[8 r Rt], 0.00317 in/rev here.     )
( The thread lead K#2 = 1/13 in is rounded to the 0.0001 in input increment: 0.0769 in =    )
( 1.95326 mm, which a K word with four decimals in mm cannot hold; neither can F hold f.    )
( Infeed along the flank: each pass starts 0.5 x depth x TAN[30] further back in Z.           )
N10 G18 G20 G90 G40 G95
N20 G97 S900 M3
#1 = 0.5         (major diameter)
#2 = 1 / 13      (lead, in per rev)
#3 = 0.6134 * #2 (thread depth on the radius)
#4 = 0.0315      (nose radius, in)
#5 = 0.00004     (peak-to-valley wanted, in: 1 micron)
#6 = SQRT[8 * #4 * #5]
#7 = -1.25       (thread end Z)
(turn the major diameter, finishing feed)
N30 G0 X[#1 + 0.1] Z0.1
N40 G1 X#1 F[#6 * 2]
N50 G1 Z[#7 - 0.2] F#6
N60 G1 X[#1 + 0.1]
N70 G0 Z0.3
(threading: passes of equal chip area, depth_n = depth_1 x SQRT[n], flank infeed)
#8 = #3 / SQRT[6]  (first pass depth: 6 passes to full depth)
#9 = 1
WHILE [#9 LE 6] DO1
  #10 = #8 * SQRT[#9]
  #11 = 0.3 + #10 * TAN[30.]
  G0 X[#1 - 2 * #10] Z#11
  G33 Z#7 K#2
  G0 X[#1 + 0.1]
  G0 Z0.3
  #9 = #9 + 1
END1
N80 G0 X2. Z0.3
N90 M5
N100 M30
%
