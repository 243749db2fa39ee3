#!/usr/bin/env python3
"""Describe grown meshes in numbers: is it a tree?

For each OBJ file: vertex count, height, and the xy convex-hull area
("footprint") of the vertices in horizontal slabs one unit thick: at the
ground [0,1), at half the canopy height, and everything above the canopy
height. A tree has a small footprint low down and a wide one above the
canopy height. --profile adds the footprint of every one-unit slab from the
ground up. Pure Python (no numpy needed).

usage: scripts/tree_shape.py [--canopy-height 10] [--profile] MESH.obj...
"""
import argparse
import sys


def read_obj_vertices(path):
    vertices = []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                x, y, z = map(float, line.split()[1:4])
                vertices.append((x, y, z))
    return vertices


def hull_area(points):
    """Area of the convex hull of 2-D points (Andrew's monotone chain)."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return 0.0

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    hull = lower[:-1] + upper[:-1]
    return 0.5 * abs(sum(hull[i][0] * hull[i - 1][1] - hull[i - 1][0] * hull[i][1] for i in range(len(hull))))


def slab_footprint(vertices, lo, hi):
    return hull_area([(x, y) for x, y, z in vertices if lo <= z < hi])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--canopy-height", type=float, default=10.0)
    parser.add_argument("--profile", action="store_true", help="footprint of every one-unit slab")
    parser.add_argument("meshes", nargs="+")
    args = parser.parse_args()
    h = args.canopy_height
    header = "mesh,vertices,height,footprint_ground,footprint_half_height,footprint_canopy,footprint_all"
    print(header + (",profile" if args.profile else ""))
    for path in args.meshes:
        v = read_obj_vertices(path)
        if not v:
            print(f"{path}: no vertices", file=sys.stderr)
            continue
        top = max(z for _, _, z in v)
        row = [
            path,
            str(len(v)),
            f"{top:.3f}",
            f"{slab_footprint(v, 0.0, 1.0):.1f}",
            f"{slab_footprint(v, 0.5 * h - 0.5, 0.5 * h + 0.5):.1f}",
            f"{slab_footprint(v, h, float('inf')):.1f}",
            f"{hull_area([(x, y) for x, y, _ in v]):.1f}",
        ]
        if args.profile:
            row.append(" ".join(f"{slab_footprint(v, z, z + 1):.0f}" for z in range(int(top) + 1)))
        print(",".join(row))


if __name__ == "__main__":
    main()
