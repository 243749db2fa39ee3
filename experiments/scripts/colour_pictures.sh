#!/usr/bin/env bash
# The pictures of docs/images/*-colour-*.png: the shipped configs' bests and a
# map's elites in colour with leaves. Evolves each shipped config for a short
# budget (G generations), grows its final best with --colour --leaves and
# draws them on one sheet; then the tree_map run's 10 fittest elites.
# Usage: colour_pictures.sh MORPHOGEN OUT_DIR
set -euo pipefail
exe=$1
out=$2
src=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$out"
glbs=()
for spec in quick:25 canopy:20 map_elites:20 tree:15 tree_map:15; do
  config=${spec%%:*} generations=${spec##*:}
  run=$out/$config
  [ -d "$run" ] || "$exe" evolve "$src/configs/$config.json" --generations "$generations" --no-report --out "$run" >/dev/null
  best=$(ls "$run"/best/gen_*.genome.json | tail -1)
  mkdir -p "$out/bests"
  "$exe" grow --config "$src/configs/$config.json" --genome "$best" --colour --leaves -o "$out/bests/$config.glb" >/dev/null
  glbs+=("$out/bests/$config.glb")
done
"$exe" render "${glbs[@]}" --columns 5 --size 300 -o "$src/docs/images/bests-colour-leaves.png"
"$exe" archive "$out/tree_map" --top 10 --colour --leaves --out "$out/elites" >/dev/null
"$exe" render "$out"/elites/*.glb --columns 5 --size 240 -o "$src/docs/images/tree-map-colour-leaves.png"
"$exe" archive "$out/tree_map" --png "$src/docs/images/tree-map-colour.png"
