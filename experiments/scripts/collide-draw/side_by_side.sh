#!/usr/bin/env bash
# collide_fraction with and without §6.3's centred draw, the same code
# otherwise: builds HEAD in a git worktree with branching_shoot_bias set to 0
# (random genomes drawn around 0, as before the centred draw), then runs
# `bench --threads 1 --repeat 3` at tree_map.json's and tree.json's settings
# with both builds, alternating, PAIRS times.
# Usage: side_by_side.sh MORPHOGEN WORKTREE_DIR [PAIRS]   (from the repository's root)
set -euo pipefail
exe=$1 tree=$2 pairs=${3:-2}
if [ ! -x "$tree/build/morphogen" ]; then
  git worktree add --detach "$tree" HEAD
  centre="$tree/core/growth/random_genome_centre.hpp"
  sed -i 's/branching_shoot_bias = 5.0/branching_shoot_bias = 0.0/' "$centre"
  # a renamed or re-valued constant would silently bench the centred draw twice
  grep -q 'branching_shoot_bias = 0.0' "$centre" || { echo "side_by_side.sh: cannot set the centre to 0 in $centre" >&2; exit 1; }
  (cd "$tree" && scripts/build.sh release morphogen >/dev/null)
fi
echo "| config | draw | collide_fraction | mean final vertices |"
echo "|---|---|---|---|"
for config in configs/tree_map.json configs/tree.json; do
  for _ in $(seq "$pairs"); do
    for pair in "centred:$exe" "centre 0:$tree/build/morphogen"; do
      "${pair#*:}" bench --config "$config" --threads 1 --repeat 3 --json | python3 -c "
import json, sys
d = json.load(sys.stdin)
print(f\"| {sys.argv[1]} | {sys.argv[2]} | {d['collide_fraction']:.2f} | {d['mean_final_vertices']:.0f} |\")" "$config" "${pair%%:*}"
    done
  done
done
