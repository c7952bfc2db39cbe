( nckit-block-delete: on )
%
O0017 (A 2 X 2 NEST BY G52 LOCAL OFFSETS, G92 SHIFT, G91 MACRO MOVES, G28, BLOCK DELETE)
( Each nest position gets its own G52 shift from a WHILE loop; the same part program O0171   )
( runs there in local coordinates. O0171 cuts a hexagon with G91 moves built from COS and SIN. )
( Blocks starting with / are deleted: block delete is on for this program.                    )
N10 G21 G17 G90 G54
N20 S4000 M3
#1 = 0
WHILE [#1 LT 4] DO1
  #2 = 110. * [#1 MOD 2] - 55.
  #3 = 90. * FIX[#1 / 2] - 45.
  G52 X#2 Y#3
  M98 P171
/ G0 X300. Y300. (deleted: never runs)
  #1 = #1 + 1
END1
N30 G52 X0 Y0
(G92 makes the current point X0 Y0; #5041 reads the work position, then G92.1 cancels)
N40 G0 X-150. Y-100. Z5.
N50 G92 X0 Y0
N60 G1 X20. Y10. F600
#4 = #5041 + #5042
N70 G92.1
N80 G1 X[#4 * 2] Y0
/N90 G1 X400. (deleted)
N100 G91 G28 Z0
N110 G90 G28 X0 Y0
N120 M5
N130 M30

O0171 (HEXAGON ACROSS FLATS 40 AT THE LOCAL ORIGIN, INCREMENTAL SIDES)
#10 = 40. / SQRT[3]   (side length = circumradius)
G90 G0 X#10 Y0
G1 Z-2. F300
#11 = 0
WHILE [#11 LT 6] DO1
  #12 = 120. + 60. * #11
  G91 G1 X[#10 * COS[#12]] Y[#10 * SIN[#12]] F900
  #11 = #11 + 1
END1
G90 G0 Z5.
M99
%
