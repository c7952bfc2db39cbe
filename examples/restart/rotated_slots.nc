%
O0022 (SLOTS AND ARCS UNDER G51.1, G51 AND G68, PART IN G91, FOR nckit restart)
( Machine: examples/machines/mill.toml.  A restart's preamble sets the mirror, scaling and  )
( rotation in force at its target again, with their centres, and writes the rest in the       )
( untransformed program coordinates the blocks had, G91 included.                             )
N10 G21 G17 G90 G94 G40 G80
N11 G10 L2 P1 X100. Y50. Z-40.
N12 G10 L2 P3 X-20. Y10. Z-40.
N13 G54 T2 M6
N14 S2500 M3 M8
N15 G0 X0 Y0 Z5.
N20 G68 X10. Y5. R30.
N21 G0 X20. Y0
N22 G1 Z-2. F120.
N23 G91 X15. F300.
N24 G3 X0 Y10. I0 J5.
N25 G1 X-15.
N26 G90 G0 Z5.
N30 G51.1 X0
N31 G0 X20. Y20.
N32 G1 Z-1.5 F120.
N33 G2 X30. Y30. R10. F250.
N34 G91 G1 Y5.
N35 G90 G0 Z5.
N36 G51 X0 Y0 P0.5
N37 G0 X40. Y-20.
N38 G1 Z-1. F100.
N39 G3 X60. Y-20. I10. J0 F200.
N40 G91 G1 X-5. Y-5.
N41 G90 G0 Z5.
N42 G50
N43 G50.1 X0
N44 G69
N50 G0 X0 Y0 Z20.
N51 M9 M5
M30
%
