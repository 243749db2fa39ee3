#!/usr/bin/env bash
# Whether two binaries grow the same plants with growth.collisions "touch":
# GENOMES random genomes (generation 0, seed 1) scored by configs/tree.json's
# fitness, in three settings (tree.json itself, the default settings in the
# paper's and the branching mode); prints each setting and whether the two
# lineage.csv files (every genome's fitness and descriptors) are identical.
# Usage: same_decisions.sh OLD_MORPHOGEN NEW_MORPHOGEN [GENOMES]
set -euo pipefail
old=${1:?usage: same_decisions.sh OLD NEW [GENOMES]}
new=${2:?usage: same_decisions.sh OLD NEW [GENOMES]}
genomes=${3:-200}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
root=$(cd "$(dirname "$0")/../../.." && pwd)
for setting in tree paper branching; do
  python3 - "$root/configs/tree.json" "$setting" "$genomes" > "$work/c.json" <<'PY'
import json, sys
config = json.load(open(sys.argv[1]))
config.pop("$schema", None)
if sys.argv[2] != "tree":
    config["growth"] = {"mode": sys.argv[2], "collisions": "touch"}
config["evolution"]["population"] = int(sys.argv[3])
config["run"] = {"seed": 1, "generations": 0, "threads": 1, "name": "same"}
print(json.dumps(config))
PY
  for b in old new; do
    binary=$old; [ $b = new ] && binary=$new
    "$binary" evolve "$work/c.json" --out "$work/$b" --force --no-report --no-limits > /dev/null 2>&1
  done
  if cmp -s "$work/old/lineage.csv" "$work/new/lineage.csv"; then verdict=identical; else verdict=DIFFERENT; fi
  echo "$setting: $genomes genomes, lineage.csv $verdict ($(wc -l < "$work/new/lineage.csv") lines)"
done
