#!/usr/bin/python3
"""Writes the water wheel (issue 15 item 5): wheel.obj and wheel.toml.

A paddle wheel (hub + 6 paddles, axis y through the origin) on a hinge with a damping torque
-c omega, fed by an inflow region above it that creates spheres moving down (-z) at speed U,
off the axis at x = X, under gravity; an outflow region below the wheel removes them. The
inflow's rate is RATE particles per second: the mass flow of a stream COLS x ROWS abreast with
S between particles along it.

Usage: /usr/bin/python3 make_case.py [OUTDIR]   (default: this directory)
"""
import math
import os
import sys

# Wheel, m
HUB_R, HUB_LEN, HUB_SEG = 2.5e-3, 6e-3, 24
PADDLES, PADDLE_IN, PADDLE_OUT, PADDLE_W, PADDLE_T = 6, 2.6e-3, 10e-3, 6e-3, 0.8e-3
# Stream: spheres of radius RP in a COLS x ROWS cross-section, spacing S, speed U, m/s
RP, S, U = 0.5e-3, 1.25e-3, 2.0
COLS, ROWS = 2, 3  # the stream's cross-section in particles (for its rate)
RATE = COLS * ROWS * U / S  # particles per second: 9600
END = 0.2  # s
X = 6.0e-3  # stream centre's distance from the axis, m
C = 1e-6  # damping torque per angular velocity, N m s/rad
Z0 = 11.5e-3  # the inflow box's bottom, m (just above the paddles' reach)
OUT_Z = -12e-3  # everything below this is removed, m


def box(verts, tris, centre, axes, half):
    """A closed box: centre, three orthonormal axes, half sizes; outward counterclockwise."""
    base = len(verts)
    for k in range(8):
        s = [(1 if k & 1 else -1), (1 if k & 2 else -1), (1 if k & 4 else -1)]
        verts.append([centre[i] + sum(s[a] * half[a] * axes[a][i] for a in range(3)) for i in range(3)])
    for t in [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4), (2, 6, 7), (2, 7, 3),
              (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]:
        tris.append([base + t[0], base + t[1], base + t[2]])


def cylinder_y(verts, tris, r, length, n):
    """A closed n-gon prism along y, centred on the origin, outward."""
    base = len(verts)
    # u = z, v = x, e = y: u x v = e (right-handed)
    for s in (-0.5, 0.5):
        for k in range(n):
            a = 2 * math.pi * k / n
            verts.append([r * math.sin(a), s * length, r * math.cos(a)])
    verts.append([0.0, -0.5 * length, 0.0])
    verts.append([0.0, 0.5 * length, 0.0])
    c0, c1 = base + 2 * n, base + 2 * n + 1
    for k in range(n):
        k1 = (k + 1) % n
        tris += [[base + k, base + k1, base + n + k1], [base + k, base + n + k1, base + n + k],
                 [c0, base + k1, base + k], [c1, base + n + k, base + n + k1]]


def main(out):
    verts, tris = [], []
    cylinder_y(verts, tris, HUB_R, HUB_LEN, HUB_SEG)
    for p in range(PADDLES):
        a = 2 * math.pi * (p + 0.5) / PADDLES
        radial = [math.cos(a), 0.0, math.sin(a)]
        tangent = [-math.sin(a), 0.0, math.cos(a)]
        mid = 0.5 * (PADDLE_IN + PADDLE_OUT)
        box(verts, tris, [mid * radial[0], 0.0, mid * radial[2]], [radial, [0.0, 1.0, 0.0], tangent],
            [0.5 * (PADDLE_OUT - PADDLE_IN), 0.5 * PADDLE_W, 0.5 * PADDLE_T])
    with open(os.path.join(out, "wheel.obj"), "w") as f:
        f.write("# paddle wheel: hub and %d paddles, axis y, m\n" % PADDLES)
        for v in verts:
            f.write("v %.9g %.9g %.9g\n" % tuple(v))
        for t in tris:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))

    with open(os.path.join(out, "wheel.toml"), "w") as f:
        f.write("""# The water wheel, small version (validation/water_wheel/README.md); made by make_case.py.
[material]
density = 2500.0

[[inflow]]
box_min = [%(x0)g, %(y0)g, %(z0)g]
box_max = [%(x1)g, %(y1)g, %(z1)g]
rate = %(rate)g
radius_min = %(rp)g
velocity = [0.0, 0.0, %(mu)g]
seed = 1

[[outflow]]
box_min = [-1.0, -1.0, -1.0]
box_max = [1.0, 1.0, %(outz)g]

[environment]
gravity = [0.0, 0.0, -9.81]

[contact]
youngs_modulus = 1e8
restitution = 0.5
friction = 0.3

[[mesh]]
name = "wheel"
file = "wheel.obj"
dynamics = "rigid_body"
density = 1000.0
rotation = "hinge"
hinge_axis = [0.0, 1.0, 0.0]
fixed = "xyz"
torque_damping = %(c)g

[integrator]
scheme = "verlet"
dt = 5e-7
end_time = %(end)g

[output]
plots = false
series_interval = 5e-5
frame_interval = 5e-3
""" % {"rp": RP, "c": C, "x0": X - 1.2e-3, "x1": X + 1.2e-3, "y0": -1.8e-3, "y1": 1.8e-3, "z0": Z0,
       "z1": Z0 + 2e-3, "rate": RATE, "mu": -U, "outz": OUT_Z, "end": END})


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__)))
