#!/usr/bin/env python3
"""Compares two morphogen binaries on the whole growth benchmark, alternating.

usage: experiments/scripts/bench_ab.py OLD_BINARY NEW_BINARY [PAIRS]   (default 8 pairs)

Runs `bench --json --threads 1 --repeat 3` with each binary in turn, swapping
which goes first every pair, and prints the median and geometric mean of the
per-pair speed ratios NEW/OLD for think and for whole growth. This is how
changes that the kernel-only loop (experiments/scripts/kernel_ab) cannot judge are
decided: cache effects between the gather and the kernel, or anything outside
the kernel. On a shared machine a single run proves little; the pairs share
the machine's state of the moment, so their ratios are what counts.
"""
import json
import statistics
import subprocess
import sys

KEYS = {"think": "think_vertex_steps_per_s", "growth": "vertex_steps_per_s_1t"}


def bench(binary):
    out = subprocess.run([binary, "bench", "--json", "--threads", "1", "--repeat", "3"],
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def main():
    if len(sys.argv) not in (3, 4):
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        sys.exit(2)
    old, new = sys.argv[1], sys.argv[2]
    pairs = int(sys.argv[3]) if len(sys.argv) == 4 else 8
    speeds = {"old": {k: [] for k in KEYS}, "new": {k: [] for k in KEYS}}
    for i in range(pairs):
        order = [("old", old), ("new", new)] if i % 2 == 0 else [("new", new), ("old", old)]
        for name, binary in order:
            result = bench(binary)
            for k, key in KEYS.items():
                speeds[name][k].append(result[key])
        print(f"pair {i + 1}: " + "  ".join(
            f"{k} {speeds['old'][k][-1] / 1e6:.2f} -> {speeds['new'][k][-1] / 1e6:.2f} M" for k in KEYS), flush=True)
    for k in KEYS:
        ratios = [n / o for n, o in zip(speeds["new"][k], speeds["old"][k])]
        print(f"{k}: old median {statistics.median(speeds['old'][k]) / 1e6:.3f} M, "
              f"new median {statistics.median(speeds['new'][k]) / 1e6:.3f} M vertex-steps/s; "
              f"new/old median {statistics.median(ratios):.3f}, geometric mean {statistics.geometric_mean(ratios):.3f}")


if __name__ == "__main__":
    main()
