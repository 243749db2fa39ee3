#!/usr/bin/env python3
"""The contact rule's cost, two binaries side by side (morphogen bench, one thread).

Usage: side_by_side.py OLD_MORPHOGEN NEW_MORPHOGEN [REPEAT [SETTINGS]]
SETTINGS: "all" (default) or "tree" (configs/tree.json only).

For configs/tree.json and the default settings in both modes: the bench of
growth.collisions "allow" and "touch" with each binary, passes interleaved
(old, new, old, new, ...) so that a change in the machine's load hits both;
collide_fraction and the one-thread wall time are medians over REPEAT such
pairs. Then tree.json genome by genome (--genomes 1 --seed S, S = 1..32):
the median over genomes of touch / allow one-thread time, per binary.
"""
import json
import os
import statistics
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
sys.path.insert(0, os.path.join(ROOT, "experiments", "scripts", "contact-rule"))
from bench_rules import bench, with_rule  # noqa: E402  the first study's harness


def main():
    old, new = sys.argv[1], sys.argv[2]
    repeat = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    tree = json.load(open(os.path.join(ROOT, "configs", "tree.json")))
    tree.pop("$schema", None)
    settings = [("tree.json (branching)", tree), ("default, paper", {}),
                ("default, branching", {"growth": {"mode": "branching"}})]
    if len(sys.argv) > 4 and sys.argv[4] == "tree":
        settings = settings[:1]
    print("| settings | binary | allow wall_s_1t | touch wall_s_1t | touch / allow | touch collide_fraction | touch mean vertices |")
    print("|---|---|---|---|---|---|---|")
    for name, base in settings:
        runs = {(b, rule): [] for b in ("old", "new") for rule in ("allow", "touch")}
        for _ in range(repeat):
            for b, binary in (("old", old), ("new", new)):
                for rule in ("allow", "touch"):
                    runs[(b, rule)].append(bench(binary, with_rule(base, rule), "--repeat", "1"))
        for b in ("old", "new"):
            allow = statistics.median(r["wall_s_1t"] for r in runs[(b, "allow")])
            touch = statistics.median(r["wall_s_1t"] for r in runs[(b, "touch")])
            fraction = statistics.median(r["collide_fraction"] for r in runs[(b, "touch")])
            vertices = statistics.median(r["mean_final_vertices"] for r in runs[(b, "touch")])
            print(f"| {name} | {b} | {allow:.3f} | {touch:.3f} | {touch / allow:.2f} | {fraction:.3f} | {vertices:.0f} |",
                  flush=True)
    for b, binary in (("old", old), ("new", new)):
        ratios = []
        for seed in range(1, 33):
            times = {rule: bench(binary, with_rule(tree, rule), "--genomes", "1", "--seed", str(seed),
                                 "--repeat", str(repeat))["wall_s_1t"] for rule in ("allow", "touch")}
            ratios.append(times["touch"] / times["allow"])
        ratios.sort()
        print(f"\ntree.json, {b}, per genome touch / allow: median {statistics.median(ratios):.2f}, "
              f"quartiles {ratios[7]:.2f}-{ratios[24]:.2f}, range {ratios[0]:.2f}-{ratios[-1]:.2f}", flush=True)


if __name__ == "__main__":
    main()
