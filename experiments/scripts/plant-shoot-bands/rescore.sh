#!/usr/bin/env bash
# Hand-built trees at the growth's 1,000 vertices and evolved bests, scored by
# configs/tree.json's `plant` fitness with the tips' skeleton bands 2 and 1
# median edges wide (`shoot_band_edges`): does the fitness prefer a tree?
# Usage: rescore.sh MORPHOGEN WORK_DIR [BEST.obj ...]
# Builds the tree-fitness-probe's shapes and decimate (experiments/scripts/tree-fitness-probe).
set -euo pipefail
exe=$(realpath "$1") work=$2; shift 2
root=$(cd "$(dirname "$0")/../../.." && pwd)
mkdir -p "$work" && cd "$work"
probe=$root/experiments/scripts/tree-fitness-probe
[ -x shapes ] || g++ -std=c++20 -O2 -I"$root" -isystem /usr/include/eigen3 "$probe/shapes.cpp" -o shapes
[ -x decimate ] || g++ -std=c++20 -O2 -isystem /usr/include/eigen3 "$probe/decimate.cpp" -o decimate -lgmp -lmpfr
for e in 2 1; do
  python3 -c "import json,sys; c=json.load(open('$root/configs/tree.json')); c['fitness']['shoot_band_edges']=$e.0; json.dump(c,open('bands$e.json','w'))"
done
# limbs fork top spread crown shoots (the architecture-maps study's ten trees; three decimate badly)
meshes=()
while read -r L F T S C N; do
  n=tree-$L-$F-$S-$C-$N
  [ -f $n-1000.obj ] || { ./shapes tree "$L" "$F" "$T" "$S" "$C" "$N" $n.obj >/dev/null && ./decimate $n.obj 1000 $n-1000.obj >/dev/null; }
  meshes+=("$n-1000.obj")
done <<'T'
8 5 12.7 5.5 2.2 10
5 5 12.7 4.5 2.5 10
6 5.2 12.7 5.5 2.2 10
6 5.2 12.7 4 2.7 10
4 5 12.7 4 2.5 10
3 5 12.7 3.5 2.7 10
6 5.2 12.7 4 2.7 6
T
echo "| mesh | vertices | fitness, bands of 2 edges (tips) | bands of 1 edge (tips) | limbs |"
echo "|---|---|---|---|---|"
for m in "${meshes[@]}" "$@"; do
  python3 - "$exe" "$m" <<'PY'
import json, subprocess, sys
exe, mesh = sys.argv[1:]
row = []
for e in (2, 1):
    d = json.loads(subprocess.run([exe, "score", "--mesh", mesh, "--config", f"bands{e}.json", "--json"],
                                  capture_output=True, text=True, check=True).stdout)
    row.append(f"{d['fitness']:.1f} ({d['fitness_terms']['tips']:.0f})")
print(f"| {mesh} | {d['vertices']} | {row[0]} | {row[1]} | {d['architecture']['limbs']} |")
PY
done
