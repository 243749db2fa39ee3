#!/usr/bin/env python3
"""Hand-built trees and shrubs against evolved bests, under several fitness configs.

usage: probe_search.py SHAPES_BIN OUT_DIR COUNT SEED CONFIG=EVOLVED_BEST.obj...

Draws COUNT trees (trunk, LIMBS limbs, a crown of spiky shoots on each) and
COUNT spiky columns at random sizes, scores each under every CONFIG with
`build/morphogen score`, and prints, per config, the best of each family beside
the evolved best given for it. Run from the repository root.
"""
import csv
import json
import os
import random
import subprocess
import sys


def score(mesh, config):
    out = subprocess.run(["build/morphogen", "score", "--mesh", mesh, "--config", config, "--json"],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def main():
    shapes, out_dir, count, seed = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    configs = [arg.split("=", 1) for arg in sys.argv[5:]]
    os.makedirs(out_dir, exist_ok=True)
    rng = random.Random(seed)
    meshes = []
    for i in range(count):
        limbs, fork = rng.choice([3, 4, 5, 6]), rng.uniform(3, 7)
        top, spread = rng.uniform(fork + 3, 12), rng.uniform(2.5, 5.5)
        crown, spikes = rng.uniform(1.3, 3.0), rng.choice([0, 6, 10])
        path = f"{out_dir}/tree-{i:02d}.obj"
        subprocess.run([shapes, "tree", str(limbs), f"{fork:.2f}", f"{top:.2f}", f"{spread:.2f}", f"{crown:.2f}",
                        str(spikes), path], check=True)
        meshes.append(("tree", path, f"{limbs} limbs, fork {fork:.1f}, top {top:.1f}, spread {spread:.1f}, "
                                      f"crown {crown:.1f}, {spikes} spikes"))
        radius, height = rng.uniform(1.5, 4.0), rng.uniform(10, 14)
        rings, per_ring = rng.choice([2, 3, 4]), rng.choice([4, 6, 8])
        path = f"{out_dir}/column-{i:02d}.obj"
        subprocess.run([shapes, "column", f"{radius:.2f}", f"{height:.2f}", str(rings), str(per_ring), path], check=True)
        meshes.append(("column", path, f"radius {radius:.1f}, height {height:.1f}, {rings}x{per_ring} spikes"))
    writer = csv.writer(sys.stdout)
    writer.writerow(["config", "family", "best_fitness", "height", "tips", "limbs", "volume", "area", "shape"])
    for config, evolved in configs:
        name = os.path.basename(config).removesuffix(".json")
        best = {}
        for family, path, what in meshes:
            d = score(path, config)
            if d["fitness"] is not None and (family not in best or d["fitness"] > best[family][0]["fitness"]):
                best[family] = (d, what)
        best["evolved"] = (score(evolved, config), evolved)
        for family in ("tree", "column", "evolved"):
            d, what = best[family]
            a = d["architecture"]
            writer.writerow([name, family, f'{d["fitness"]:.2f}', f'{d["height"]:.2f}', a["tips"], a["limbs"],
                             f'{d["volume"]:.1f}', f'{d["area"]:.1f}', what])
        sys.stdout.flush()


if __name__ == "__main__":
    main()
