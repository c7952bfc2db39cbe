( nckit-machine: lathe_b.toml )
%
O0014 (LATHE: STEPPED SHAFT WITH A BALL END AND AN M24 X 2 THREAD, X IN DIAMETERS)
( Roughing: WHILE passes of 2.5 mm on the diameter, largest step first, allowance kept.    )
( Finishing at a fixed rpm: the profile with a G3 ball end computed from its radius.      )
( Threading: G33 passes with depth = first depth x SQRT[pass], the last ones at full depth.  )
( #5001 reads X as a diameter here, as a Fanuc lathe shows it.                              )
N10 G18 G21 G90 G40 G95
N20 G92 S3000    (spindle limit for G96: G92 S in G-code system B)
N30 T0101
N40 G96 S200 M3
N50 M8
#1 = 50.         (blank diameter)
#2 = 2.5         (depth of cut on the diameter)
#3 = 0.4         (finishing allowance on the diameter)
#4 = 0.25        (roughing feed, mm/rev)
#5 = 0.1         (finishing feed)
(steps: diameter #[10 + 2 i], Z end #[11 + 2 i], from the end of the part)
#10 = 24.
#11 = -30.
#12 = 36.
#13 = -55.
#14 = 44.
#15 = -80.
N60 G0 X[#1 + 4.] Z2.
(facing)
N70 G1 Z0 F#4
N80 G1 X-1.
N90 G0 Z2.
(roughing: each step from the largest, passes from the last diameter down to it + allowance)
#20 = #1          (current diameter)
#21 = 2
WHILE [#21 GE 0] DO1
  #22 = #[10 + 2 * #21] + #3       (target diameter of this step)
  #23 = #[11 + 2 * #21]            (its Z end)
  WHILE [#20 GT #22] DO2
    #20 = #20 - #2
    IF [#20 LT #22] THEN #20 = #22
    G0 X#20
    G1 Z[#23 + 0.2] F#4
    G1 X[#20 + 1.]
    G0 Z2.
  END2
  #21 = #21 - 1
END1
(finishing: ball end R = half the first diameter, then the steps with 1 mm fillets)
#30 = #10 / 2
N95 G97 S1500 (fixed rpm: the ball end runs down to X0, where G96 would sit at the limit)
N100 G0 X0
N110 G1 Z0 F#5
N120 G3 X#10 Z-#30 R#30
N130 G1 Z[#11 + 1.]
N140 G2 X[#10 + 2.] Z#11 R1.
N150 G1 X[#12 - 2.]
N160 G3 X#12 Z[#11 - 1.] R1.
N170 G1 Z[#13 + 1.]
N180 G2 X[#12 + 2.] Z#13 R1.
N190 G1 X#14
N200 G1 Z#15
N210 G1 X[#5001 + 6.] (6 mm over the last diameter, read back from #5001)
N220 G0 X[#1 + 4.] Z5.
(threading M24 x 2 on the first step: runs at a fixed rpm)
N230 G97 S600
#24 = 2.         (pitch)
#25 = 1.2269     (thread depth on the radius)
#26 = 0.35       (first pass depth on the radius)
#27 = #10        (major diameter)
#28 = 1
#29 = 0
WHILE [#29 LT #25] DO1
  #29 = #26 * SQRT[#28]
  IF [#29 GT #25] THEN #29 = #25
  G0 X[#27 - 2 * #29] Z4.
  G33 Z[#11 + 3.] K#24
  G0 X[#27 + 4.]
  G0 Z4.
  #28 = #28 + 1
END1
(one spring pass at full depth)
G0 X[#27 - 2 * #25]
G33 Z[#11 + 3.] K#24
G0 X[#27 + 4.]
N300 G0 X100. Z5.
N310 M9
N320 M5
N330 M30
%
