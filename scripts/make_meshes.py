#!/usr/bin/env python3
"""Writes the small OFF meshes of data/collision/meshes (boxes, a capped cylinder, a gripper):
closed, outward-facing triangle meshes in each object's own frame. Rerun after editing; the
outputs are committed."""
import math
import os

OUT = os.path.join(os.path.dirname(__file__), "..", "data", "collision", "meshes")


def box(c, h):
    """Vertices and triangles of an axis-aligned box with centre c and half-extents h."""
    v = [(c[0] + (h[0] if i & 1 else -h[0]), c[1] + (h[1] if i & 2 else -h[1]),
          c[2] + (h[2] if i & 4 else -h[2])) for i in range(8)]
    t = [(0, 2, 1), (1, 2, 3), (4, 5, 6), (5, 7, 6), (0, 1, 4), (1, 5, 4),
         (2, 6, 3), (3, 6, 7), (0, 4, 2), (2, 4, 6), (1, 3, 5), (3, 7, 5)]
    return v, t


def cylinder(r, z0, z1, n):
    """A closed prism of n sides around the z axis (its vertices on the circle of radius r)."""
    v = [(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n), z)
         for z in (z0, z1) for k in range(n)]
    v += [(0, 0, z0), (0, 0, z1)]
    t = []
    for k in range(n):
        a, b = k, (k + 1) % n
        t += [(a, b, n + b), (a, n + b, n + a), (2 * n, b, a), (2 * n + 1, n + a, n + b)]
    return v, t


def merge(*parts):
    v, t = [], []
    for pv, pt in parts:
        t += [(a + len(v), b + len(v), c + len(v)) for a, b, c in pt]
        v += pv
    return v, t


def write(name, mesh):
    v, t = mesh
    with open(os.path.join(OUT, name), "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(v), len(t)))
        for p in v:
            f.write("%.17g %.17g %.17g\n" % p)
        for a, b, c in t:
            f.write("3 %d %d %d\n" % (a, b, c))


def main():
    os.makedirs(OUT, exist_ok=True)
    # Table: top face at z = 0, 1.2 x 0.8 m, 4 cm thick.
    write("table.off", box((0, 0, -0.02), (0.6, 0.4, 0.02)))
    # Wall: 4 cm thick, across the x axis at x = 0.5, 30 cm high, standing on the table.
    write("wall.off", box((0.5, 0, 0.15), (0.02, 0.4, 0.15)))
    # Part: 20 x 10 x 6 cm block whose bottom face is its frame's z = 0.
    write("part.off", box((0, 0, 0.03), (0.1, 0.05, 0.03)))
    # Arm: 40 cm bar from its origin along +x.
    write("arm.off", box((0.2, 0, 0), (0.2, 0.02, 0.02)))
    # Block: an obstacle beside the pivot on the -x side.
    write("block.off", box((-0.35, 0, 0.5), (0.2, 0.1, 0.1)))
    # Can: radius 3.3 cm, 12 cm tall, standing on its frame's z = 0.
    write("can.off", cylinder(0.033, 0.0, 0.12, 32))
    # Gripper: palm box behind the fingertip point (0, 0, 0.12), two fingers either side (y).
    write("gripper.off", merge(box((0, 0, 0.03), (0.06, 0.06, 0.03)),
                               box((0, 0.05, 0.1), (0.01, 0.005, 0.04)),
                               box((0, -0.05, 0.1), (0.01, 0.005, 0.04))))
    # Table under the can (a grasp from the table top).
    write("counter.off", box((0.4, 0.1, -0.02), (0.3, 0.3, 0.02)))


if __name__ == "__main__":
    main()
