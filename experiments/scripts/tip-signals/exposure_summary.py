#!/usr/bin/env python3
"""Exposure (docs/algorithm.md §5.9, default keys) of every vertex of grown
OBJ meshes: the deciles over all vertices, and the share of each mesh's
vertices that are lit (E > 0.75) and dark (E = 0). Usage: exposure_summary.py MESH.obj..."""
import math
import sys
from collections import Counter

import os
CELL, DEPTH, FULL_SHADE = (float(os.environ.get("CELL", 1)), int(os.environ.get("DEPTH", 4)),
                          float(os.environ.get("FULL_SHADE", 32)))


def vertices(path):
    with open(path) as f:
        return [tuple(float(t) for t in line.split()[1:4]) for line in f if line.startswith("v ")]


def exposures(points):
    voxels = [tuple(math.floor(c / CELL) for c in p) for p in points]
    counts = Counter(voxels)
    result = []
    for i, j, k in voxels:
        shadow = sum(2.0 ** -d * counts.get((i + dx, j + dy, k + d), 0)
                     for d in range(DEPTH + 1) for dx in range(-d, d + 1) for dy in range(-d, d + 1))
        result.append(min(1.0, max(0.0, (FULL_SHADE - shadow + 1.0) / FULL_SHADE)))
    return result


def main():
    every = []
    print("mesh vertices lit dark")
    for path in sys.argv[1:]:
        e = exposures(vertices(path))
        every += e
        print(f"{path.rsplit('/', 1)[-1]} {len(e)} {sum(x > 0.75 for x in e) / len(e):.2f} {sum(x == 0 for x in e) / len(e):.2f}")
    every.sort()
    print("deciles", " ".join(f"{every[min(len(every) - 1, len(every) * q // 10)]:.2f}" for q in range(11)))


main()
