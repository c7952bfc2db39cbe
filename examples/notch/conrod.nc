(Connecting-rod fracture-split notch, the notching paper's program.)
(The tube/rod feeds on X; the cutting head moves on Z. M24/M25 swing the head in and out,)
(M27 switches the laser on: all three are exact stops on the notcher, see examples/machines/notcher.toml.)
(Run: nckit notch examples/notch/conrod.nc --machine examples/machines/notcher.toml -o conrod_notched.nc)
N10 G01 G90 X68.5 F3000
N20 M24
N30 G01 G90 Z-15.53 F5000
N40 M27
N50 G01 G90 Z-33.63 F950
N60 G01 G90 X73.5 F3000
N70 M25
M30
