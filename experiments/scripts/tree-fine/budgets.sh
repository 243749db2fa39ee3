#!/usr/bin/env bash
# The two bred plants (examples/bred-tree, examples/bred-tree-by-eye) grown
# at larger budgets: configs/tree_map.json's network, growth and fitness with
# max_vertices and steps replaced; each scored (`score --json`: fitness,
# tips, limbs with length / thickness, first fork, clean) and drawn in colour.
# Usage: budgets.sh MORPHOGEN OUT_DIR   (from the repository's root)
set -euo pipefail
exe=$1 out=$2
budgets=(1000:150 1000:300 2000:300 3000:250 4000:250 4000:300 4000:400)
mkdir -p "$out"

# The config of each budget.
for budget in "${budgets[@]}"; do
  python3 - "${budget%:*}" "${budget#*:}" "$out/c${budget/:/_}.json" <<'PY'
import json, sys
c = json.load(open("configs/tree_map.json"))
c = {k: c[k] for k in ("network", "growth", "fitness")}
c["growth"].update(max_vertices=int(sys.argv[1]), steps=int(sys.argv[2]))
json.dump(c, open(sys.argv[3], "w"))
PY
done

echo "| plant | max_vertices | steps | vertices | height | fitness | tips | limbs (length / thickness) | first fork / height | clean |"
echo "|---|---|---|---|---|---|---|---|---|---|"
glbs=()
for example in bred-tree bred-tree-by-eye; do
  for budget in "${budgets[@]}"; do
    config="$out/c${budget/:/_}.json" glb="$out/${example}_${budget/:/_}.glb"
    "$exe" grow --config "$config" --genome "examples/$example/tree.genome.json" --colour -o "$glb" >/dev/null
    "$exe" score --config "$config" --mesh "$glb" --json | python3 -c "
import json, sys
d = json.load(sys.stdin); a = d['architecture']
ratios = [round(l / t, 1) for l, t in zip(a['limb_lengths'], a['limb_thicknesses'])]
fork = a['first_fork_height'] / d['height'] if a['first_fork_height'] else float('nan')
print(f\"| $example | ${budget%:*} | ${budget#*:} | {d['vertices']} | {d['height']:.1f} | {d['fitness']:.1f} | \"
      f\"{d['fitness_terms']['tips']:.0f} | {a['limbs']} {ratios} | {fork:.2f} | {'no' if d['self_intersecting'] else 'yes'} |\")"
    glbs+=("$glb")
  done
done
"$exe" render -o "$out/budgets.png" --columns 7 --size 256 "${glbs[@]}" >/dev/null
