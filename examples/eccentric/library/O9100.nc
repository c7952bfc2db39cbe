O9100 (ECCENTRIC TURNING: ROUGHING PASSES, THEN A FINISHING PASS)
( Arguments: D #7 blank diameter, E #8 eccentricity, R #18 eccentric radius,               )
( K #6 Z start, Z #26 Z end, Q #17 depth of cut per roughing pass on the radius,         )
( F #9 roughing feed, H #11 finishing feed, both mm/rev along Z, U #21 allowance on        )
( the diameter, A #1 spindle angle per block in degrees, 5 when not given.                 )
IF [#8 GE #18] THEN #3000 = 1 (ECCENTRICITY MUST BE SMALLER THAN THE ECCENTRIC RADIUS)
IF [[#8 + #18] GT [#7 / 2]] THEN #3000 = 2 (ECCENTRIC CYLINDER DOES NOT FIT IN THE BLANK)
IF [#26 GE #6] THEN #3000 = 3 (Z END MUST LIE BELOW Z START)
IF [#1 EQ #0] THEN #1 = 5.
#100 = [#7 / 2] - [#18 - #8]        (largest stock, radius, at 180 degrees)
#101 = #21 / 2                      (finishing allowance, radius)
#102 = FUP[[#100 - #101] / #17]     (roughing passes)
#103 = 1
WHILE [#103 LE #102] DO1
  #105 = #101 + [#100 - #101] - #103 * #17   (this pass: offset from the finished profile)
  IF [#105 LT #101] THEN #105 = #101
  #106 = #9
  M98 P9101
  #103 = #103 + 1
END1
#105 = 0                            (finishing pass on the profile itself)
#106 = #11
M98 P9101
M99
