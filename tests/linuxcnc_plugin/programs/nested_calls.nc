%
O1002 (nested calls: the call levels LinuxCNC shows while the plug-in runs them)
G21 G90 G17 G94
G0 X0 Y0 Z5
M98 P100
G0 X0 Y0
M30
O100 (subprogram of this file: call level 1)
G1 Y10 F600
G65 P9101 A5 B2
G1 Y0
M99
%
