#!/usr/bin/env bash
# Whether two morphogen binaries grow the same bytes: `morphogen grow
# --random S` for a few seeds, with growth.collisions "allow", "prevent" and
# "touch", in both modes (60 steps; touch also at configs/tree.json), written
# as exact PLY; prints "same" or "DIFFERENT" per file.
# Usage: same_bytes.sh OLD_MORPHOGEN NEW_MORPHOGEN [SEEDS...]
set -euo pipefail
old=${1:?usage: same_bytes.sh OLD NEW [SEEDS...]}
new=${2:?usage: same_bytes.sh OLD NEW [SEEDS...]}
shift 2
seeds=("$@")
[ $# -eq 0 ] && seeds=(1 2 3)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for mode in paper branching; do
  for rule in allow prevent touch; do
    echo "{\"growth\": {\"mode\": \"$mode\", \"collisions\": \"$rule\", \"steps\": 60}}" > "$work/$mode-$rule.json"
  done
done
cp configs/tree.json "$work/tree.json"
sed -i 's/"\$schema": "schema.json",//' "$work/tree.json"
for config in "$work"/*.json; do
  for s in "${seeds[@]}"; do
    name=$(basename "$config" .json)-$s
    nice -n 10 "$old" grow --config "$config" --random "$s" --ply-double -o "$work/old-$name.ply" > /dev/null
    nice -n 10 "$new" grow --config "$config" --random "$s" --ply-double -o "$work/new-$name.ply" > /dev/null
    if cmp -s "$work/old-$name.ply" "$work/new-$name.ply"; then echo "same      $name"; else echo "DIFFERENT $name"; fi
  done
done
