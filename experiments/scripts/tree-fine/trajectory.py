#!/usr/bin/env python3
"""The limbs, first fork / height and fitness of the best of every generation
of each GA run (RUN_DIR/best/gen_*.genome.json, scored with `score --json`).
Usage: trajectory.py MORPHOGEN CONFIG RUN_DIR...  (one line a run: GEN:LIMBS/FORK/FITNESS)"""
import json, subprocess, sys, pathlib
exe, config = sys.argv[1], sys.argv[2]
for run in sys.argv[3:]:
    row = []
    for g in sorted(pathlib.Path(run, "best").glob("gen_*.genome.json")):
        d = json.loads(subprocess.check_output([exe, "score", "--config", config, "--genome", str(g), "--json"]))
        a = d["architecture"]
        fork = a["first_fork_height"] / d["height"] if a["first_fork_height"] else float("nan")
        row.append(f"{int(g.name[4:8])}:{a['limbs']}/{fork:.2f}/{d['fitness']:.0f}")
    print(run, " ".join(row), flush=True)
