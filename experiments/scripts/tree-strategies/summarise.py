#!/usr/bin/env python3
"""Scores each run's last best with `score --json` (architecture measures),
grows it in colour and draws one contact sheet per strategy.
Usage: summarise.py MORPHOGEN CONFIG OUT_PNG RUN_DIR... (a table on stdout)"""
import json, pathlib, subprocess, sys

exe, config, png, runs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
glbs = []
print("| run | births | best fitness | vertices | height | tips | limbs | first fork / height | clean |")
print("|---|---|---|---|---|---|---|---|---|")
for run in map(pathlib.Path, runs):
    best = sorted((run / "best").glob("gen_*.genome.json"))[-1]
    births = sum(1 for _ in open(run / "lineage.csv")) - 1
    out = json.loads(subprocess.check_output([exe, "score", "--config", config, "--genome", str(best), "--json"]))
    arch = out["architecture"]
    m = out
    height = m["height"]
    glb = run.parent / f"{run.parent.name}-{run.name}.glb"
    subprocess.check_call([exe, "grow", "--config", config, "--genome", str(best), "--colour", "-o", str(glb)],
                          stdout=subprocess.DEVNULL)
    glbs.append(str(glb))
    fork = arch["first_fork_height"] / height if height else float("nan")
    print(f"| {run.name} | {births} | {out['fitness']:.1f} | {m.get('vertices')} | {height:.1f} | "
          f"{arch['tips']} | {arch['limbs']} | {fork:.2f} | {'no' if m.get('self_intersecting') else 'yes'} |")
subprocess.check_call([exe, "render", *glbs, "-o", png, "--columns", str(len(glbs)), "--size", "256"],
                      stdout=subprocess.DEVNULL)
