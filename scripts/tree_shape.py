#!/usr/bin/env python3
"""Describe grown meshes in numbers: is it a tree?

For each OBJ file: vertex count, height, and the xy convex-hull area
("footprint") of the vertices in horizontal slabs one unit thick: at the
ground [0,1), at half the canopy height, and everything above the canopy
height. A tree has a small footprint low down and a wide one above the
canopy height. --profile adds the footprint of every one-unit slab from the
ground up. Pure Python (no numpy needed).

Then the three numbers of the "Plants, not blobs" issue, and the verdict:

self_intersecting
    Taken from the project's executable, not computed here:
    `MORPHOGEN score --mesh FILE --json`, key "self_intersecting"
    (true/false). MORPHOGEN is --morphogen (default build/morphogen in the
    repository, the parent of this script's directory). If it is missing,
    fails, or prints no such key, the value is n/a (said once on stderr
    when the executable is missing, per mesh when it fails).

trunk_ratio
    Let zmin, zmax be the lowest and highest vertex z (vertices used by a
    face) and H = zmax - zmin. Sections are taken at N = --sections (default
    64) evenly spaced heights h_i = zmin + (i + 1/2) H / N, i = 0..N-1, so no
    plane passes through zmin or zmax. The section of the triangle mesh by
    the plane z = h is the set of segments where triangles cross it (see
    "Sections" below); its width is its diameter in xy: the largest distance
    between two of its points, computed exactly over the segment endpoints
    (convex hull, then rotating calipers). trunk_ratio = (largest width of
    the sections in the lowest quarter, zmin < h <= zmin + H/4) / (largest
    width of the sections in the upper half, zmin + H/2 <= h < zmax).
    Which section falls in which band is decided on the index i with integer
    arithmetic, not on rounded heights. n/a when there is no section in the
    lowest quarter (N = 1) or the upper half's width is 0.

max_loops_upper_half
    The largest number of loops that any section in the upper half
    (zmin + H/2 <= h < zmax, same sampled heights) cuts the mesh into. The
    loops of a section are the connected components of the graph whose
    nodes are the mesh edges crossed by the plane and whose arcs are the
    crossing triangles (each joins its two crossed edges). On a closed
    surface each component is a closed loop; on an open one it may be an
    open chain, and still counts one.

Sections: a vertex is "above" the plane z = h when z >= h and "below" when
z < h, exactly, with no tolerance; an edge is crossed when one end is above
and the other below, a triangle crosses when it has vertices on both sides,
and then has exactly two crossed edges. A vertex lying exactly on the plane
is thus treated as if the plane were infinitesimally lower: nothing is
counted twice and nothing divides by zero. The section point on crossed
edge (a below, b above) is a + t (b - a), t = (h - za) / (zb - za).
Vertices with identical coordinates are merged first (so OBJ files that
split vertices by normal or uv still connect), and triangles left with a
repeated vertex are dropped.

is_tree: yes when self_intersecting is false and trunk_ratio <= 0.25 and
max_loops_upper_half >= 3; n/a when self_intersecting is unknown; no
otherwise.

OBJ reading: `v x y z` lines are vertices; `f` lines are faces whose
corners may be written a, a/b, a/b/c or a//c (only a, the vertex, is used);
negative indices count back from the last vertex read so far; polygons of
more than 3 corners are fan-triangulated from their first corner.

The new CSV columns self_intersecting,trunk_ratio,max_loops_upper_half,
is_tree come after all the existing ones (after profile with --profile).
--json prints one JSON object per mesh, one per line, instead of CSV, with
every number (and the widths behind trunk_ratio); unknown values are null
there, except is_tree, which is "yes", "no" or "n/a".

usage: scripts/tree_shape.py [--canopy-height 10] [--profile] [--sections 64]
                             [--morphogen build/morphogen] [--json] MESH.obj...
"""
import argparse
import bisect
import json
import math
import os
import subprocess
import sys
from pathlib import Path

DEFAULT_MORPHOGEN = Path(__file__).resolve().parent.parent / "build" / "morphogen"
TREE_MAX_TRUNK_RATIO = 0.25
TREE_MIN_LOOPS = 3


def read_obj_vertices(path):
    return read_obj(path)[0]


def read_obj(path):
    """Vertices [(x, y, z)] and triangles [(i, j, k)] (0-based) of an OBJ file."""
    vertices, triangles = [], []
    with open(path) as f:
        for line_number, line in enumerate(f, 1):
            line = line.split("#", 1)[0]
            tokens = line.split()
            if not tokens:
                continue
            if tokens[0] == "v":
                x, y, z = map(float, tokens[1:4])
                vertices.append((x, y, z))
            elif tokens[0] == "f":
                corners = []
                for token in tokens[1:]:
                    index = int(token.split("/", 1)[0])
                    if index < 0:
                        index += len(vertices)
                    elif index > 0:
                        index -= 1
                    else:
                        raise ValueError(f"{path}:{line_number}: vertex index 0")
                    if not 0 <= index < len(vertices):
                        raise ValueError(f"{path}:{line_number}: vertex index {token} out of range")
                    corners.append(index)
                for k in range(1, len(corners) - 1):
                    triangles.append((corners[0], corners[k], corners[k + 1]))
    return vertices, triangles


def convex_hull(points):
    """Convex hull of 2-D points, counter-clockwise, no collinear points (Andrew's monotone chain)."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts

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
    return lower[:-1] + upper[:-1]


def hull_area(points):
    """Area of the convex hull of 2-D points (Andrew's monotone chain)."""
    hull = convex_hull(points)
    if len(hull) < 3:
        return 0.0
    return 0.5 * abs(sum(hull[i][0] * hull[i - 1][1] - hull[i - 1][0] * hull[i][1] for i in range(len(hull))))


def diameter(points):
    """Largest distance between two of the 2-D points: convex hull, then rotating calipers."""
    hull = convex_hull(points)
    n = len(hull)
    if n < 2:
        return 0.0
    if n == 2:
        return math.dist(hull[0], hull[1])

    def area2(a, b, c):
        return abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))

    best = 0.0
    j = 1
    for i in range(n):
        a, b = hull[i], hull[(i + 1) % n]
        # j: the hull vertex farthest from the line through edge (a, b)
        while area2(a, b, hull[(j + 1) % n]) > area2(a, b, hull[j]):
            j = (j + 1) % n
        best = max(best, math.dist(a, hull[j]), math.dist(b, hull[j]))
    return best


def slab_footprint(vertices, lo, hi):
    return hull_area([(x, y) for x, y, z in vertices if lo <= z < hi])


class Sections:
    """Horizontal sections of a triangle mesh (see the module docstring)."""

    def __init__(self, vertices, triangles):
        canonical = {}
        remap = [canonical.setdefault(v, len(canonical)) for v in vertices]
        self.points = list(canonical)
        tris = []
        for t in triangles:
            a, b, c = (remap[i] for i in t)
            if a != b and b != c and a != c:
                zs = (self.points[a][2], self.points[b][2], self.points[c][2])
                tris.append((min(zs), max(zs), (a, b, c)))
        tris.sort(key=lambda item: item[0])
        self.triangles = tris
        self.tri_zmin = [item[0] for item in tris]
        used = {i for _, _, t in tris for i in t}
        zs = [self.points[i][2] for i in used]
        self.zmin = min(zs) if zs else 0.0
        self.zmax = max(zs) if zs else 0.0

    def section(self, h):
        """(width, loops) of the section by the plane z = h."""
        pts = self.points
        crossing = {}  # crossed edge (lo, hi vertex) -> its section point
        parent = {}

        def find(e):
            while parent[e] != e:
                parent[e] = parent[parent[e]]
                e = parent[e]
            return e

        for k in range(bisect.bisect_left(self.tri_zmin, h)):  # triangles with zmin < h
            _, tzmax, t = self.triangles[k]
            if tzmax < h:
                continue
            crossed = []
            for u, v in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
                if (pts[u][2] >= h) != (pts[v][2] >= h):
                    e = (u, v) if u < v else (v, u)
                    if e not in crossing:
                        lo, hi = (u, v) if pts[u][2] < h else (v, u)
                        (xa, ya, za), (xb, yb, zb) = pts[lo], pts[hi]
                        s = (h - za) / (zb - za)
                        crossing[e] = (xa + s * (xb - xa), ya + s * (yb - ya))
                        parent[e] = e
                    crossed.append(e)
            # a crossing triangle has exactly two crossed edges
            ra, rb = find(crossed[0]), find(crossed[1])
            if ra != rb:
                parent[ra] = rb
        loops = sum(1 for e in parent if parent[e] == e)
        return diameter(list(crossing.values())), loops

    def numbers(self, n_sections):
        """trunk_ratio, max_loops_upper_half and the widths behind the ratio."""
        height = self.zmax - self.zmin
        low_width = high_width = 0.0
        low_count = 0
        max_loops = 0
        if height > 0 and n_sections > 0:
            for i in range(n_sections):
                odd = 2 * i + 1  # h = zmin + odd * H / (2 N)
                in_low_quarter = 2 * odd <= n_sections  # (i + 1/2) / N <= 1/4
                in_upper_half = odd >= n_sections  # (i + 1/2) / N >= 1/2
                if not (in_low_quarter or in_upper_half):
                    continue
                h = self.zmin + odd * height / (2 * n_sections)
                width, loops = self.section(h)
                if in_low_quarter:
                    low_count += 1
                    low_width = max(low_width, width)
                if in_upper_half:
                    high_width = max(high_width, width)
                    max_loops = max(max_loops, loops)
        ratio = low_width / high_width if low_count and high_width > 0 else None
        return {
            "trunk_ratio": ratio,
            "max_loops_upper_half": max_loops,
            "width_lowest_quarter": low_width,
            "width_upper_half": high_width,
        }


class SelfIntersection:
    """Asks `MORPHOGEN score --mesh FILE --json` for "self_intersecting"."""

    def __init__(self, executable):
        self.executable = str(executable)
        self.available = os.path.isfile(self.executable) and os.access(self.executable, os.X_OK)
        self.warned = False

    def __call__(self, path):
        """True, False, or None (unknown)."""
        if not self.available:
            if not self.warned:
                print(f"tree_shape: {self.executable} not found: self_intersecting is n/a", file=sys.stderr)
                self.warned = True
            return None
        try:
            done = subprocess.run([self.executable, "score", "--mesh", str(path), "--json"],
                                  capture_output=True, text=True)
        except OSError as error:
            print(f"tree_shape: {self.executable}: {error}: self_intersecting of {path} is n/a", file=sys.stderr)
            return None
        value = None
        if done.returncode == 0:
            try:
                value = json.loads(done.stdout).get("self_intersecting")
            except (ValueError, AttributeError):
                value = None
        if not isinstance(value, bool):
            detail = done.stderr.strip().splitlines()[-1:] or [f"exit status {done.returncode}"]
            print(f"tree_shape: {self.executable} score gave no self_intersecting for {path} ({detail[0]}): n/a",
                  file=sys.stderr)
            return None
        return value


def is_tree(self_intersecting, trunk_ratio, loops):
    if self_intersecting is None:
        return "n/a"
    shape = trunk_ratio is not None and trunk_ratio <= TREE_MAX_TRUNK_RATIO and loops >= TREE_MIN_LOOPS
    return "yes" if shape and not self_intersecting else "no"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--canopy-height", type=float, default=10.0)
    parser.add_argument("--profile", action="store_true", help="footprint of every one-unit slab")
    parser.add_argument("--sections", type=int, default=64,
                        help="number of evenly spaced horizontal sections (default 64)")
    parser.add_argument("--morphogen", default=str(DEFAULT_MORPHOGEN),
                        help="the morphogen executable that says self_intersecting (default: build/morphogen "
                             "in the repository)")
    parser.add_argument("--json", action="store_true", help="one JSON object per mesh instead of CSV")
    parser.add_argument("meshes", nargs="+")
    args = parser.parse_args()
    if args.sections < 1:
        parser.error("--sections must be at least 1")
    h = args.canopy_height
    self_intersecting_of = SelfIntersection(args.morphogen)
    header = "mesh,vertices,height,footprint_ground,footprint_half_height,footprint_canopy,footprint_all"
    new_columns = "self_intersecting,trunk_ratio,max_loops_upper_half,is_tree"
    if not args.json:
        print(header + (",profile" if args.profile else "") + "," + new_columns)
    for path in args.meshes:
        v, triangles = read_obj(path)
        if not v:
            print(f"{path}: no vertices", file=sys.stderr)
            continue
        top = max(z for _, _, z in v)
        footprints = [
            slab_footprint(v, 0.0, 1.0),
            slab_footprint(v, 0.5 * h - 0.5, 0.5 * h + 0.5),
            slab_footprint(v, h, float("inf")),
            hull_area([(x, y) for x, y, _ in v]),
        ]
        profile = [slab_footprint(v, z, z + 1) for z in range(int(top) + 1)] if args.profile else None
        numbers = Sections(v, triangles).numbers(args.sections)
        si = self_intersecting_of(path)
        tree = is_tree(si, numbers["trunk_ratio"], numbers["max_loops_upper_half"])
        if args.json:
            record = {
                "mesh": path,
                "vertices": len(v),
                "triangles": len(triangles),
                "height": top,
                "footprint_ground": footprints[0],
                "footprint_half_height": footprints[1],
                "footprint_canopy": footprints[2],
                "footprint_all": footprints[3],
            }
            if profile is not None:
                record["profile"] = profile
            record["sections"] = args.sections
            record["self_intersecting"] = si
            record.update(numbers)
            record["is_tree"] = tree
            print(json.dumps(record))
            continue
        row = [path, str(len(v)), f"{top:.3f}"] + [f"{a:.1f}" for a in footprints]
        if args.profile:
            row.append(" ".join(f"{a:.0f}" for a in profile))
        row += [
            "n/a" if si is None else str(si).lower(),
            "n/a" if numbers["trunk_ratio"] is None else f"{numbers['trunk_ratio']:.3f}",
            str(numbers["max_loops_upper_half"]),
            tree,
        ]
        print(",".join(row))


if __name__ == "__main__":
    main()
