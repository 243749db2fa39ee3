#!/usr/bin/env python3
"""What touch's fail-safe costs, `morphogen bench` side by side (one thread).

Usage: bench_side_by_side.py OLD_MORPHOGEN NEW_MORPHOGEN [REPEAT] [GENOMES]

For configs/tree.json and the default settings in both modes, with
growth.collisions "allow" and "touch", each binary in turn (old, new, old,
new for every row, so drift hits both): collide_fraction (the phase timer's
share of collision work: with the fail-safe, its check and search for k are
in it), wall_s_all at --threads 1 (the bench's unobserved pass: births as
evolution grows them) and wall_s_1t (the observed, timed pass). Then, for
tree.json, each of the GENOMES genomes on its own (--genomes 1 --seed S),
touch against allow, with the new binary: the median of the per-genome
ratios of their unobserved one-thread times.
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
        out = subprocess.run(["nice", "-n", "10", morphogen, "bench", "--config", path, "--json", "--threads", "1",
                              *extra], check=True, capture_output=True, text=True).stdout
    finally:
        os.unlink(path)
    return json.loads(out)


def with_rule(base, rule):
    config = json.loads(json.dumps(base))
    config.setdefault("growth", {})["collisions"] = rule
    return config


def main():
    old, new = sys.argv[1], sys.argv[2]
    repeat = sys.argv[3] if len(sys.argv) > 3 else "3"
    genomes = int(sys.argv[4]) if len(sys.argv) > 4 else 32
    tree = json.load(open(os.path.join(ROOT, "configs", "tree.json")))
    tree.pop("$schema", None)
    settings = [("tree.json (branching)", tree), ("default, paper", {}),
                ("default, branching", {"growth": {"mode": "branching"}})]
    print("| settings | collisions | binary | collide_fraction | wall_s_all (1 thread) | vs allow | wall_s_1t | "
          "mean final vertices |")
    print("|---|---|---|---|---|---|---|---|")
    for name, base in settings:
        allow = {}
        for rule in ("allow", "touch"):
            for label, binary in (("main", old), ("rewind", new)):
                r = bench(binary, with_rule(base, rule), "--repeat", repeat, "--genomes", str(genomes))
                allow.setdefault(label, r["wall_s_all"])
                print(f"| {name} | {rule} | {label} | {r['collide_fraction']:.3f} | {r['wall_s_all']:.3f} | "
                      f"{r['wall_s_all'] / allow[label]:.2f} | {r['wall_s_1t']:.3f} | "
                      f"{r['mean_final_vertices']:.0f} |", flush=True)
    ratios = []
    for seed in range(1, genomes + 1):
        times = {rule: bench(new, with_rule(tree, rule), "--genomes", "1", "--seed", str(seed),
                             "--repeat", repeat)["wall_s_all"] for rule in ("allow", "touch")}
        ratios.append(times["touch"] / times["allow"])
    ratios.sort()
    q = len(ratios) // 4
    print(f"\ntree.json, per genome (new binary), touch / allow one-thread birth: median "
          f"{statistics.median(ratios):.2f}, quartiles {ratios[q]:.2f}-{ratios[-1 - q]:.2f}, "
          f"range {ratios[0]:.2f}-{ratios[-1]:.2f}")


if __name__ == "__main__":
    main()
