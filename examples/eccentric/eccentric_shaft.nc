%
O1000 (ECCENTRIC SHAFT - TURNED WITHOUT AN ECCENTRIC FIXTURE)
( Run: nckit moves examples/eccentric/eccentric_shaft.nc --machine examples/machines/lathe.toml )
(        --library examples/eccentric/library                                              )
( Blank 60 mm, eccentric cylinder R20 offset 3 mm from the blank axis, Z 0 to -30.          )
( X follows the spindle angle by the law of cosines; see O9100 in the library folder.       )
N10 G21 G18 G40
N20 G10 L2 P1 Z-20.                 (part face 20 mm from machine Z0)
N30 G54 G97 S60 M3                  (60 rpm: the X slide must follow 2e at the spindle frequency)
N40 T1
N50 M8
N60 G65 P9100 D60. E3. R20. K0 Z-30. Q2.5 F0.3 H0.1 U0.4 A5.
N70 G0 X80. Z20.
N80 M9
N90 M5
N100 M30
%
