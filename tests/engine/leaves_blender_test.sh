#!/usr/bin/env bash
# GLBs with foliage cards (--leaves) imported into Blender: two materials per
# level, the leaf one alpha-clipped, two-sided and textured, and the cards'
# and the body's triangles as the extras count them; with --colour, the
# colour attribute from COLOR_0 (blender_leaves_check.py).
# Usage: leaves_blender_test.sh MORPHOGEN SOURCE_DIR. Exit 77 (skipped) when
# Blender is not installed.
set -euo pipefail
exe=$1
src=$2
if ! command -v blender >/dev/null; then
  echo "SKIPPED: blender is not installed (scripts/setup.sh installs it)"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$exe" grow --random 4 --steps 200 -o paper.glb --leaves --lods 3 --wind --wind-preset uv >/dev/null
"$exe" grow --config "$src/configs/tree_map.json" --random 5 -o branching.glb --leaves --leaf-size 0.08 --lods 2 >/dev/null
# With --colour: COLOR_0 on the body, which Blender imports as a colour attribute.
"$exe" grow --config "$src/configs/tree_map.json" --random 5 -o colour.glb --colour --leaves --lods 2 >/dev/null
blender -b --factory-startup --python-exit-code 1 --python "$src/tests/engine/blender_leaves_check.py" -- \
  paper.glb branching.glb colour.glb >blender.log 2>&1 || { cat blender.log; exit 1; }
grep -E "^blender" blender.log
