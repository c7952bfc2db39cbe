%
O0023 (LATHE, G-CODE SYSTEM A, DIAMETER WORDS, U W INCREMENTAL, G50 SHIFT AND CLAMP, FOR nckit restart)
( Machine: examples/machines/lathe.toml.  A restart's preamble sets the G50 S clamp, the work )
( offset and the G50 Z coordinate shift again in system A's own codes, then G7 diameter mode;   )
( the rest writes X as diameters. The shift leaves X as it was: see docs/restart.md, Limits.    )
N10 G21 G18 G99 G40
N20 G10 L2 P1 Z-30.
N30 G54 T0101
N40 G50 S2500
N50 G96 S150 M3
N60 G0 X42. Z3.
N70 G50 X42. Z1.
N80 G1 Z0 F0.15
N90 U-10. F0.1
N100 W-12.
N110 G2 U8. W-4. R4.
N120 G1 W-10.
N130 U6. W-2.
N140 G0 X44. Z2.
N150 G97 S800
N160 G1 X30. Z0 F0.2
N170 W-5.
N180 G0 U10. W5.
N190 M5
M30
%
