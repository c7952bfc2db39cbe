O9100 (move X to A times B at feed F: a Macro B macro for MDI and call-level tests)
IF [#9 EQ #0] THEN #9 = 600
G1 X[#1 * #2] F#9
M99
