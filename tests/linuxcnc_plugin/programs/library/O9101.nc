O9101 (call level 2: a tool change, where LinuxCNC waits for the machine, then X to A times B)
T1 M6
G1 X[#1 * #2] F600
M99
