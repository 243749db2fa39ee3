#!/usr/bin/env python3
"""A MAP-Elites run's elites by their architecture: exports them (`archive`),
measures each (`score --json`), prints how many have 2+ and 3+ limbs and
draws the forked ones (2+ limbs) in colour, fittest first.
Usage: map_limbs.py MORPHOGEN CONFIG RUN_DIR OUT_PNG"""
import json, pathlib, subprocess, sys

exe, config, run, png = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3]), sys.argv[4]
elites = run / "elites"
subprocess.run([exe, "archive", str(run), "--out", str(elites)], check=True, stdout=subprocess.DEVNULL)
rows = []
for genome in sorted(elites.glob("*.genome.json")):
    d = json.loads(subprocess.check_output([exe, "score", "--config", config, "--genome", str(genome), "--json"]))
    a = d["architecture"]
    fork = a["first_fork_height"] / d["height"] if d["height"] else 1.0
    rows.append((d["fitness"], a["limbs"], a["tips"], fork, genome))
print(f"{run.name}: {len(rows)} elites, {sum(r[1] >= 2 for r in rows)} with 2+ limbs, "
      f"{sum(r[1] >= 3 for r in rows)} with 3+, best {max(r[0] for r in rows):.1f}")
forked = sorted((r for r in rows if r[1] >= 2), key=lambda r: -r[0])
for f, limbs, tips, fork, genome in forked:
    print(f"  {genome.name}: fitness {f:.1f}, {limbs} limbs, {tips} tips, first fork at {fork:.2f}")
glbs = []
for f, limbs, tips, fork, genome in forked[:12]:
    glb = elites / f"{genome.name.split('.')[0]}_l{limbs}_f{fork:.2f}.glb"
    subprocess.run([exe, "grow", "--config", config, "--genome", str(genome), "--colour", "-o", str(glb)],
                   check=True, stdout=subprocess.DEVNULL)
    glbs.append(str(glb))
if glbs:
    subprocess.run([exe, "render", *glbs, "-o", png, "--columns", str(min(6, len(glbs))), "--size", "220"],
                   check=True, stdout=subprocess.DEVNULL)
