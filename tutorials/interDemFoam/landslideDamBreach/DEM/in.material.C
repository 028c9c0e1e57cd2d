# Material C: coarse, nearly uniform gravel ("unsize coarse-grained"),
# d = 20, 30, 40 mm, mass fractions 0.3, 0.4, 0.3; density 2650 kg/m3
fix             p1 all particletemplate/sphere 15485863 atom_type 1 density constant 2650 radius constant 0.010
fix             p2 all particletemplate/sphere 15485867 atom_type 1 density constant 2650 radius constant 0.015
fix             p3 all particletemplate/sphere 32452843 atom_type 1 density constant 2650 radius constant 0.020
fix             pdd all particledistribution/discrete 86028121 3 p1 0.3 p2 0.4 p3 0.3
