%
O0013 (ARCS FROM MACRO-COMPUTED POINTS: A SCALLOPED FLANGE, R ARCS, HELIX, G18 AND G19 ARCS)
( 1. A flange outline of 9 lobes: each lobe is a G3 arc about a point on a 50 mm circle,    )
(    joined by G2 arcs about points between them; ends and centres come from SIN and COS.  )
( 2. Chord-and-R arcs: R #18 positive under 180 degrees, negative over it.                  )
( 3. A helix of 2.5 turns as five half-turn G3 blocks with computed Z.                      )
( 4. A G18 fillet profile and a G19 cross-section arc from computed points.                 )
N10 G21 G17 G90 G54
N20 S5000 M3
#1 = 9           (lobes)
#2 = 50.         (lobe centre radius)
#3 = 12.         (lobe radius)
#4 = 360. / #1   (lobe pitch angle)
(the lobes and the valleys meet where the lobe circle cuts the 53 mm circle)
#5 = 53.
#6 = ACOS[[#2 * #2 + #5 * #5 - #3 * #3] / [2 * #2 * #5]]   (half-angle at the origin)
G0 Z5.
G0 X[#5 * COS[-#6]] Y[#5 * SIN[-#6]]
G1 Z-2. F300
#10 = 0
WHILE [#10 LT #1] DO1
  #11 = #10 * #4                        (this lobe's angle)
  #12 = #2 * COS[#11]                   (lobe centre)
  #13 = #2 * SIN[#11]
  G3 X[#5 * COS[#11 + #6]] Y[#5 * SIN[#11 + #6]] I[#12 - #5001] J[#13 - #5002] F800
  (valley arc about a centre on the 75 mm circle half-way to the next lobe)
  #14 = #11 + #4 / 2
  #15 = 75. * COS[#14]
  #16 = 75. * SIN[#14]
  G2 X[#5 * COS[#11 + #4 - #6]] Y[#5 * SIN[#11 + #4 - #6]] I[#15 - #5001] J[#16 - #5002]
  #10 = #10 + 1
END1
G0 Z5.
(R arcs: a 120 degree arc with +R, then a 240 degree arc back with -R)
#18 = 20.
#20 = -120.
#21 = 100.
G0 X[#20 + #18] Y#21
G1 Z-1. F300
G3 X[#20 + #18 * COS[120.]] Y[#21 + #18 * SIN[120.]] R#18 F600
G3 X[#20 + #18] Y#21 R-#18
G0 Z5.
(helix: 2.5 turns of radius 15 from Z2 down to Z-8, in half turns)
#22 = 120.
#23 = 100.
#24 = 15.
G0 X[#22 + #24] Y#23
G0 Z2.
#10 = 1
WHILE [#10 LE 5] DO1
  #25 = 2. - 10. * #10 / 5
  #26 = #24 * [1 - 2 * [#10 MOD 2]]      (alternating sides)
  G3 X[#22 + #26] Y#23 Z#25 I[#22 - #5001] J0 F400
  #10 = #10 + 1
END1
G0 Z20.
(G18 fillet: a 60 degree arc of radius 8 in XZ, then an R arc from the computed end point)
G18
G0 X-100. Y-100.
G0 Z0
G1 X-60. F500
#27 = 8.
G2 X[-60. + #27 * SIN[60.]] Z[#27 * [COS[60.] - 1]] I0 K-#27
G3 X[#5001 + 10.] Z[#5003 - 5.] R[12.]
G0 Z20.
(G19 cross-section: a 120 degree arc over the top, in YZ)
G19
G0 X-100. Y100.
G0 Z10.
G2 Y[100. + 20. * COS[30.] * 2] Z10. J[20. * COS[30.]] K[-20. * SIN[30.]] F500
G17
G0 Z40.
N30 M5
N40 M30
%
