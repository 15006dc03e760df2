#!/usr/bin/env python3
"""Writes examples/insert_r6_c7.stl: a CAD-like cutting insert for examples/cut_tool_from_file.toml.

A parallelogram insert seen along its cutting edge (y), as a CAD package would export it: in
mm, ASCII STL with 9 significant digits, its own origin (the sharp tip at x = 3, z = 1 mm, the
edge from y = 0 to 1 mm), a 6 deg rake face 2 mm long, a 7 deg flank 1.5 mm long, the back
faces parallel to them, and a honed edge of 20 um radius faceted every 2 deg (finer than
swarf's generated tool, 5 deg). In swarf's frame: it cuts along +x, the rake face faces +x
(toward the chip), the flank -z. swarf measures rake 6 deg, clearance 7 deg and r_n 20 um from
it (to the 9 digits written) and places its sharp tip where the generated tool's would be.

    python3 scripts/make_example_insert.py [OUT.stl]
"""
import math
import sys

RAKE, CLEARANCE = 6.0, 7.0          # deg
EDGE_RADIUS = 0.020                 # mm
RAKE_LENGTH, FLANK_LENGTH = 2.0, 1.5  # mm, from the sharp tip
WIDTH = 1.0                         # mm along y
TIP = (3.0, 1.0)                    # mm: the sharp tip's (x, z) in the file
ARC_STEP = 2.0                      # deg


def profile():
    """The profile in (x, z), counterclockwise, the sharp tip at the origin."""
    a, g = math.radians(RAKE), math.radians(CLEARANCE)
    dr = (-math.sin(a), math.cos(a))  # along the rake face, away from the edge
    df = (-math.cos(g), math.sin(g))  # along the flank
    wedge = math.pi / 2 - a - g
    bis = (dr[0] + df[0], dr[1] + df[1])
    n = math.hypot(*bis)
    bis = (bis[0] / n, bis[1] / n)
    d = EDGE_RADIUS / math.sin(wedge / 2)
    c = (d * bis[0], d * bis[1])  # the arc's centre
    tf = ((c[0] * df[0] + c[1] * df[1]) * df[0], (c[0] * df[0] + c[1] * df[1]) * df[1])
    tr = ((c[0] * dr[0] + c[1] * dr[1]) * dr[0], (c[0] * dr[0] + c[1] * dr[1]) * dr[1])
    a0 = math.atan2(tf[1] - c[1], tf[0] - c[0])
    a1 = math.atan2(tr[1] - c[1], tr[0] - c[0])
    turn = (a1 - a0) % (2 * math.pi)  # counterclockwise from the flank's tangent point: past the tip
    if turn > math.pi:
        turn -= 2 * math.pi
    steps = max(2, math.ceil(abs(math.degrees(turn)) / ARC_STEP))
    arc = [(c[0] + EDGE_RADIUS * math.cos(a0 + turn * k / steps),
            c[1] + EDGE_RADIUS * math.sin(a0 + turn * k / steps)) for k in range(steps + 1)]
    rake_end = (RAKE_LENGTH * dr[0], RAKE_LENGTH * dr[1])
    flank_end = (FLANK_LENGTH * df[0], FLANK_LENGTH * df[1])
    back = (rake_end[0] + flank_end[0], rake_end[1] + flank_end[1])
    poly = arc + [rake_end, back, flank_end]
    area2 = sum(p[0] * q[1] - p[1] * q[0] for p, q in zip(poly, poly[1:] + poly[:1]))
    return poly if area2 > 0 else poly[::-1]


def triangles(poly):
    """Closed, outward: caps at y = 0 and y = WIDTH, side walls."""
    n = len(poly)
    v = [(TIP[0] + x, y, TIP[1] + z) for y in (0.0, WIDTH) for (x, z) in poly]
    tris = []
    for k in range(1, n - 1):  # a counterclockwise (x, z) polygon faces -y: the cap at y = 0 keeps it
        tris.append((v[0], v[k], v[k + 1]))
        tris.append((v[n], v[n + k + 1], v[n + k]))
    for k in range(n):
        a, b = k, (k + 1) % n
        tris.append((v[a], v[n + a], v[n + b]))
        tris.append((v[a], v[n + b], v[b]))
    return tris


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    s = math.sqrt(sum(x * x for x in n))
    return tuple(x / s for x in n)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "examples/insert_r6_c7.stl"
    lines = ["solid insert_r6_c7 (mm; scripts/make_example_insert.py)"]
    for t in triangles(profile()):
        lines.append("  facet normal {:.9g} {:.9g} {:.9g}".format(*normal(*t)))
        lines.append("    outer loop")
        for p in t:
            lines.append("      vertex {:.9g} {:.9g} {:.9g}".format(*p))
        lines.append("    endloop")
        lines.append("  endfacet")
    lines.append("endsolid insert_r6_c7")
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
