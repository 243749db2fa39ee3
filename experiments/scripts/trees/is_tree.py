#!/usr/bin/env python3
"""Architecture of grown meshes, and whether each is a tree by the skeleton.

usage: is_tree.py CONFIG MESH...   (prints CSV: one row per mesh)

A tree here (issue 36's reading of "what a person calls a tree"): a clean
solid (no self-intersection) whose trunk forks below the crown (the first
fork lower than 3/4 of the height) into at least 3 limbs, each at least 3x
as long as it is thick (the skeleton's `limbs`, docs/fitness-measures.md
"Architecture measures"), each reaching the crown (its tip in the upper half
of the plant). The numbers come from `morphogen score --json`.
"""
import csv
import json
import os
import subprocess
import sys

# The build of the checkout this script is in, so that it runs from any directory.
MORPHOGEN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "build", "morphogen")


def measure(config, mesh):
    out = subprocess.run([MORPHOGEN, "score", "--mesh", mesh, "--config", config, "--json"],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def main():
    config, meshes = sys.argv[1], sys.argv[2:]
    writer = csv.writer(sys.stdout)
    writer.writerow(["mesh", "fitness", "vertices", "height", "tips", "limbs", "limbs_in_crown",
                     "first_fork_height", "strahler", "solidity", "self_intersecting", "is_tree"])
    for mesh in meshes:
        d = measure(config, mesh)
        a = d["architecture"]
        height = d["height"]
        # A limb reaches the crown when its last skeleton node is in the upper half.
        limbs_in_crown = sum(1 for z in a["limb_tip_z"] if z >= 0.5 * height)
        is_tree = (not d["self_intersecting"] and a["limbs"] >= 3 and limbs_in_crown >= 3
                   and a["first_fork_height"] < 0.75 * height)
        writer.writerow([mesh, f'{d["fitness"]:.2f}', d["vertices"], f"{height:.2f}", a["tips"], a["limbs"],
                         limbs_in_crown, f'{a["first_fork_height"]:.2f}', a["strahler"],
                         "" if a["solidity"] is None else f'{a["solidity"]:.3f}', d["self_intersecting"],
                         "yes" if is_tree else "no"])


if __name__ == "__main__":
    main()
