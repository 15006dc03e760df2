#!/usr/bin/python3
"""Writes data/w2_particles.txt (id x y z vx vy vz, SI units) for scene W2: the same
initial state as peers/common/gen.py (validation/bench/peers) produces for every peer (same recipe, same
seed), so swarf starts identically to LAMMPS, LIGGGHTS, Yade and ESyS-Particle."""
import os, random

NS, S2, OFF2, VR, SEED = 27, 1.05e-3, 0.55e-3, 0.5, 12345
here = os.path.dirname(os.path.abspath(__file__))
os.makedirs(os.path.join(here, "data"), exist_ok=True)
rng = random.Random(SEED)
with open(os.path.join(here, "data", "w2_particles.txt"), "w") as f:
    n = 0
    for k in range(NS):
        for j in range(NS):
            for i in range(NS):
                x, y, z = OFF2 + i * S2, OFF2 + j * S2, OFF2 + k * S2
                v = tuple(rng.uniform(-VR, VR) for _ in range(3))
                n += 1
                f.write("%d %.12e %.12e %.12e %.12e %.12e %.12e\n" % ((n, x, y, z) + v))
