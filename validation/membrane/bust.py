#!/usr/bin/python3
"""Writes bust.obj: a closed, non-convex triangulated body in the spirit of the paper's figure 6
(a rigid bust under a falling membrane), generated here so that its origin is known.

A surface of revolution about z (units: mm): a pedestal, shoulders, a narrow neck (a concave
waist) and a head, with a nose and a chin (bumps) and two eye sockets and the hollow under
the nose (dents) that break the symmetry. 180 x 100 quads plus two caps: 36,000 triangles.
Usage: bust.py [OUT.obj]
"""
import math
import sys

N_THETA, N_Z = 180, 100


def profile(z):
    """Radius (mm) of the surface of revolution at height z (mm), 0 <= z <= 100."""
    pieces = [(0, 34), (8, 34), (10, 30), (22, 44), (34, 40), (44, 16), (52, 13), (58, 17), (68, 22),
              (80, 22), (90, 17), (96, 9), (100, 0)]
    for (z0, r0), (z1, r1) in zip(pieces, pieces[1:]):
        if z <= z1:
            s = (z - z0) / (z1 - z0)
            s = 0.5 - 0.5 * math.cos(math.pi * s)  # smooth between the knots
            return r0 + (r1 - r0) * s
    return 0.0


def bump(theta, z, t0, z0, wt, wz):
    dt = math.atan2(math.sin(theta - t0), math.cos(theta - t0))
    return math.exp(-(dt / wt) ** 2 - ((z - z0) / wz) ** 2)


def radius(theta, z):
    r = profile(z)
    if r <= 0:
        return 0.0
    r += 6.0 * bump(theta, z, 0.0, 76, 0.18, 5)  # nose
    r += 3.0 * bump(theta, z, 0.0, 64, 0.45, 3)  # chin
    r -= 3.5 * bump(theta, z, 0.38, 83, 0.16, 3)  # eye sockets
    r -= 3.5 * bump(theta, z, -0.38, 83, 0.16, 3)
    r -= 2.0 * bump(theta, z, 0.0, 70, 0.25, 1.5)  # under the nose
    return max(r, 0.5)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "bust.obj"
    verts, faces = [], []
    zs = [100.0 * j / N_Z for j in range(N_Z + 1)]
    for j, z in enumerate(zs[:-1]):
        for i in range(N_THETA):
            th = 2 * math.pi * i / N_THETA
            r = radius(th, z)
            verts.append((r * math.cos(th), r * math.sin(th), z))
    top = len(verts)
    verts.append((0.0, 0.0, 100.0))
    bottom = len(verts)
    verts.append((0.0, 0.0, 0.0))

    def vid(i, j):
        return j * N_THETA + i % N_THETA

    for j in range(N_Z - 1):
        for i in range(N_THETA):
            a, b, c, d = vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)
            faces += [(a, b, c), (a, c, d)]  # outward normals (counter-clockwise seen from outside)
    for i in range(N_THETA):
        faces.append((vid(i, N_Z - 1), vid(i + 1, N_Z - 1), top))
        faces.append((vid(i + 1, 0), vid(i, 0), bottom))
    with open(out, "w") as f:
        f.write(f"# bust.py (swarf validation/membrane): {len(verts)} vertices, {len(faces)} triangles, mm\n")
        for v in verts:
            f.write(f"v {v[0]:.5f} {v[1]:.5f} {v[2]:.5f}\n")
        for a, b, c in faces:
            f.write(f"f {a + 1} {b + 1} {c + 1}\n")
    print(f"{out}: {len(verts)} vertices, {len(faces)} triangles")


if __name__ == "__main__":
    main()
