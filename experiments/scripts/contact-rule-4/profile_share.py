#!/usr/bin/env python3
"""Where one thread's CPU samples go in `morphogen bench --config configs/tree.json --threads 1`.

Usage: profile_share.py MORPHOGEN [REPEAT]

As experiments/scripts/contact-rule-3/profile_share.sh, with the fail-safe's
whole-mesh check (SelfIntersectionCheck, its SpatialHash) counted as
collision work too, as the bench counts it (touch-rewind), and the collision
work divided into its parts. The bench's own FMA peak probe and the kernel
are left out of both sides.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
IGNORED = r"fma_rounds|scalbn|kallsyms"
COLLISION = (r"Contact|fan_certified|certified_along|distance_to_triangle|beside_plane|faces_intersect|"
             r"IndexedTriangle|face_box|outward|triangle_degenerate|SelfIntersection|SpatialHash")
# The collision work's parts: a symbol goes to the first that matches.
PARTS = [("lookups and the rule's loops", r"settle_move"),
         ("the grid's build", r"ContactGrid::build|list_faces|outward"),
         ("fan certificates", r"fan_certified|certified_along|refuse_tangled_fans"),
         ("distances", r"distance_to_triangle|touches"),
         ("the final check", r"SelfIntersection|SpatialHash"),
         ("the flip guard", r"allows|faces_intersect|beside_plane|IndexedTriangle|face_box|triangle_degenerate"),
         ("other", r".")]


def main():
    morphogen = sys.argv[1]
    repeat = sys.argv[2] if len(sys.argv) > 2 else "3"
    config = json.load(open(os.path.join(ROOT, "configs", "tree.json")))
    config.pop("$schema", None)
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "tree.json")
        json.dump(config, open(path, "w"))
        data = os.path.join(work, "perf.data")
        subprocess.run(["perf", "record", "-q", "-o", data, morphogen, "bench", "--config", path, "--json",
                        "--threads", "1", "--repeat", repeat], check=True, capture_output=True)
        report = subprocess.run(["perf", "report", "-i", data, "--no-children", "--percent-limit", "0.2", "--stdio"],
                                check=True, capture_output=True, text=True).stdout
    collide = rest = 0.0
    parts = {name: 0.0 for name, _ in PARTS}
    for line in report.splitlines():
        m = re.match(r"\s+([\d.]+)%\s+\S+\s+\S+\s+\[.\]\s+(.*)", line)
        if not m or re.search(IGNORED, m.group(2)):
            continue
        share, symbol = float(m.group(1)), m.group(2)
        if re.search(COLLISION, symbol):
            collide += share
            parts[next(name for name, pattern in PARTS if re.search(pattern, symbol))] += share
        else:
            rest += share
    print(f"collision {collide:.1f} %, the rest {rest:.1f} %, "
          f"collision / (collision + rest) = {collide / (collide + rest):.3f}")
    print("of the collision work: " + ", ".join(f"{name} {100 * share / collide:.0f} %" for name, share in parts.items()))


if __name__ == "__main__":
    main()
