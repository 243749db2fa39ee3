#!/usr/bin/env python3
"""Tips / limbs / first fork (as a fraction of the height) that `morphogen
score --json` reads on the limb controls written by controls.cpp, against
their labels, for one or more binaries: a markdown table, a * after each
wrong reading (experiments/2026-11-28-limb-measure-controls.md).

    table.py DIR NAME=BINARY [NAME=BINARY ...]
"""
import json
import subprocess
import sys

RESOLUTIONS = (500, 1000, 2000, 5000)


def reading(binary, path):
    report = json.loads(subprocess.run([binary, "score", "--mesh", path, "--json"], check=True,
                                       capture_output=True, text=True).stdout)
    a = report["architecture"]
    zmin = min(float(line.split()[3]) for line in open(path) if line.startswith("v "))
    return a["tips"], a["limbs"], a["first_fork_height"] / (report["height"] - zmin)


def main():
    folder, binaries = sys.argv[1], [arg.split("=", 1) for arg in sys.argv[2:]]
    labels = json.load(open(f"{folder}/labels.json"))
    print("| control | label: tips / limbs / fork | binary | " + " | ".join(f"{n} vertices" for n in RESOLUTIONS) + " |")
    print("|---|---|---|" + "---|" * len(RESOLUTIONS))
    wrong = {name: 0 for name, _ in binaries}
    for c in labels:
        for name, binary in binaries:
            cells = []
            for n in RESOLUTIONS:
                tips, limbs, fork = reading(binary, f"{folder}/{c['name']}-{n}.obj")
                ok = tips == c["tips"] and limbs == c["limbs"] and abs(fork - c["fork_fraction"]) <= c["fork_tolerance"]
                wrong[name] += not ok
                cells.append(f"{tips} / {limbs} / {fork:.2f}" + ("" if ok else " *"))
            label = f"{c['tips']} / {c['limbs']} / {c['fork_fraction']:.2f} ± {c['fork_tolerance']:.2f}"
            print(f"| {c['name']} | {label} | {name} | " + " | ".join(cells) + " |")
    for name, count in wrong.items():
        print(f"\n{name}: {count} of {len(labels) * len(RESOLUTIONS)} readings wrong")


if __name__ == "__main__":
    main()
