%
O0012 (VACANT VARIABLES AND INDIRECT ADDRESSING: A POINT TABLE IN #100-#139)
( The table holds X Y pairs at #[100 + 2i] and #[101 + 2i]; a vacant X ends it. A vacant Y     )
( keeps Y where it was: the word is dropped, as G1 X#1 Y#0 is G1 X#1. O0121 moves only the     )
( axes it was given: G65 P121 Z-2. is a pure Z move. Vacant counts as 0 in arithmetic but is   )
( not equal to 0 in EQ and NE.                                                                  )
N10 G21 G17 G90 G54
N20 S5000 M3
#100 = -50.
#101 = -30.
#102 = 50.
#103 = #0        (Y vacant: stays at -30)
#104 = 50.
#105 = 30.
#106 = #0        (X vacant: end of the table)
#107 = 99.
#108 = 0
#109 = 0
G0 Z5.
G0 X#100 Y#101
G1 Z-1. F200
#1 = 2
WHILE [#[100 + 2 * #1 - 2] NE #0] DO1
  G1 X#[100 + 2 * [#1 - 1]] Y#[101 + 2 * [#1 - 1]] F900
  #1 = #1 + 1
END1
(#1 is now 4, the first vacant entry; #[2 * #1 + 98] = #106, vacant, counts as 0)
#2 = #[2 * #1 + 98] + 10.
G1 X#2 Y#2
(EQ tells vacant from 0: #108 is 0, #110 is vacant)
#3 = 1
IF [#108 EQ #0] THEN #3 = 2
IF [#110 EQ #0] THEN #3 = #3 + 10
IF [#110 EQ 0] THEN #3 = #3 + 100
IF [#110 GE 0] THEN #3 = #3 + 1000
G1 X[#3 / 100.] Y[-#3 / 100.]
(vacant arguments: only the given axes move)
G65 P121 Z-2.
G65 P121 X40. F600.
G65 P121 Y-40.
G65 P121 X-40. Y40. Z0
(an assignment of vacant keeps it vacant; a vacant times 5 is 0)
#4 = #0
#5 = #4 * 5
G1 X#4 Y#5 Z#4
G0 Z20.
N30 M5
N40 M30

O0121 (MOVE THE AXES GIVEN: X #24 Y #25 Z #26, FEED F #9 OR 700)
IF [#9 EQ #0] THEN #9 = 700.
G1 X#24 Y#25 Z#26 F#9
M99
%
