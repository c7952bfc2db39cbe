O9101 (ONE PASS: RADIUS OFFSET #105 FROM THE PROFILE, FEED #106 MM/REV)
( The G32 lead-in waits for the spindle index pulse and lasts two whole turns, so every     )
( pass leaves it at spindle angle 0: the eccentric points the same way on every pass.       )
#110 = 2 * #106                     (lead-in length: two turns)
#111 = 0                            (spindle angle theta, degrees)
#112 = [#6 - #26] / #106 * 360      (angle turned over the length)
#113 = #8 + #18 + #105              (radius at theta = 0: e + r)
G0 X[#7 + 4] Z[#6 + #110]
G0 X[2 * #113]
G32 Z#6 F#106
WHILE [#111 LT #112] DO1
  #117 = #111
  #111 = #111 + #1
  IF [#111 GT #112] THEN #111 = #112
  ( law of cosines: a = e cos theta + sqrt[r^2 - e^2 sin^2 theta] )
  #114 = #8 * COS[#111] + SQRT[#18 * #18 - #8 * #8 * SIN[#111] * SIN[#111]] + #105
  #115 = #6 - #106 * #111 / 360
  ( feed along the path per turn, so that each block takes its share of a turn )
  #116 = SQRT[[#114 - #113] * [#114 - #113] + [#106 * [#111 - #117] / 360] * [#106 * [#111 - #117] / 360]]
  G99 G1 X[2 * #114] Z#115 F[#116 * 360 / [#111 - #117]]
  #113 = #114
END1
G0 X[#7 + 4]
M99
