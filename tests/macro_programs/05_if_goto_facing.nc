%
O0005 (FACE MILLING WITH IF-GOTO LOOPS AND IF-THEN DECISIONS)
( Passes are counted with IF [..] GOTO back to N100 instead of WHILE. IF-THEN picks the        )
( direction of each pass; a forward GOTO skips the finishing pass when the stock is too thin;  )
( a compound condition [[..] AND [..]] adds a clean-up pass.                                   )
N10 G21 G17 G90 G54
N20 S3000 M3
#1 = -80.        (X min of the face)
#2 = 80.         (X max)
#3 = -50.        (Y min)
#4 = 50.         (Y max)
#5 = 32.         (cutter diameter)
#6 = 0.7         (stepover, fraction of the diameter)
#7 = 1.6         (stock to face off)
#8 = 0.6         (roughing depth per level)
#9 = 0.25        (finishing allowance)
#20 = #5 * #6    (stepover)
#21 = FUP[[#4 - #3] / #20]   (passes per level)
#22 = 0          (depth reached)
#23 = #7 - #9    (roughing stock)
G0 Z10.
N100 #22 = #22 + #8
IF [#22 GT #23] THEN #22 = #23
#24 = 0          (pass counter)
N200 #25 = #3 + #24 * [#4 - #3] / #21
#26 = #1 - #5 / 2 - 2.
#27 = #2 + #5 / 2 + 2.
IF [[#24 MOD 2] NE 0] THEN #26 = #2 + #5 / 2 + 2.
IF [[#24 MOD 2] NE 0] THEN #27 = #1 - #5 / 2 - 2.
G0 X#26 Y#25
G1 Z[#7 - #22] F400
G1 X#27 F1500
G0 Z[#7 - #22 + 1.]
#24 = #24 + 1
IF [#24 LE #21] GOTO 200
IF [#22 LT #23] GOTO 100
(finishing pass only when there is a real allowance left)
IF [#9 LT 0.05] GOTO 400
#24 = 0
N300 #25 = #3 + #24 * [#4 - #3] / #21
G0 X[#1 - #5 / 2 - 2.] Y#25
G1 Z0 F300
G1 X[#2 + #5 / 2 + 2.] F900
G0 Z1.
#24 = #24 + 1
IF [#24 LE #21] GOTO 300
N400 IF [[#21 GE 4] AND [#9 GT 0]] THEN #30 = 1
IF [#30 EQ #0] GOTO 500
(clean-up pass along the edge at Y max)
G0 X#1 Y[#4 + 3.]
G1 Z0 F300
G1 X#2 F900
N500 G0 Z50.
N510 M5
N520 GOTO 600
N530 G0 X300. Y300. (never reached)
N600 G0 X0 Y0
N610 M30
%
