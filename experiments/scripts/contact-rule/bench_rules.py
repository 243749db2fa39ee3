#!/usr/bin/env python3
"""What each collision rule costs, from `morphogen bench` (one thread).

Usage: bench_rules.py MORPHOGEN [REPEAT]

For configs/tree.json and for the default settings in both modes, with
growth.collisions "allow", "touch" and "prevent": collide_fraction, the
one-thread wall time and the mean final vertices (the bench's 32 genomes,
medians of REPEAT passes). Then, for tree.json, every one of the 32 genomes
on its own (--genomes 1 --seed S), "touch" against "allow": the median of
the per-genome ratios of their one-thread times (a birth's growth).
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))


def bench(morphogen, config, *extra):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(config, f)
        path = f.name
    try:
        out = subprocess.run([morphogen, "bench", "--config", path, "--json", "--threads", "1", *extra],
                             check=True, capture_output=True, text=True).stdout
    finally:
        os.unlink(path)
    return json.loads(out)


def with_rule(base, rule):
    config = json.loads(json.dumps(base))
    config.setdefault("growth", {})["collisions"] = rule
    return config


def main():
    morphogen = sys.argv[1]
    repeat = sys.argv[2] if len(sys.argv) > 2 else "5"
    tree = json.load(open(os.path.join(ROOT, "configs", "tree.json")))
    tree.pop("$schema", None)
    settings = [("tree.json (branching)", tree), ("default, paper", {}),
                ("default, branching", {"growth": {"mode": "branching"}})]
    print("| settings | collisions | collide_fraction | wall_s_1t | vs allow | mean final vertices |")
    print("|---|---|---|---|---|---|")
    for name, base in settings:
        allow_wall = None
        for rule in ("allow", "touch", "prevent"):
            r = bench(morphogen, with_rule(base, rule), "--repeat", repeat)
            allow_wall = allow_wall or r["wall_s_1t"]
            print(f"| {name} | {rule} | {r['collide_fraction']:.3f} | {r['wall_s_1t']:.3f} | "
                  f"{r['wall_s_1t'] / allow_wall:.2f} | {r['mean_final_vertices']:.0f} |", flush=True)
    ratios = []
    for seed in range(1, 33):
        times = {rule: bench(morphogen, with_rule(tree, rule), "--genomes", "1", "--seed", str(seed),
                             "--repeat", "3")["wall_s_1t"] for rule in ("allow", "touch")}
        ratios.append(times["touch"] / times["allow"])
    ratios.sort()
    print(f"\ntree.json, per genome, touch / allow one-thread time: median {statistics.median(ratios):.2f}, "
          f"quartiles {ratios[7]:.2f}-{ratios[24]:.2f}, range {ratios[0]:.2f}-{ratios[-1]:.2f}")


if __name__ == "__main__":
    main()
