#!/usr/bin/env bash
# `archive RUN --pack DIR` end to end on a tiny MAP-Elites run and a tiny GA
# run: the same run gives the same bytes (every file, written twice); a pack
# refuses a used directory and loses nothing; then, where Blender is
# installed (scripts/setup.sh installs it), blender_pack_check.py imports
# every GLB and scatter.glb and checks names, LODs, triangles, scale, extras
# and wind data.
# Usage: pack_test.sh MORPHOGEN SOURCE_DIR [blender]. Exit 77 (skipped) only
# when asked for the Blender check and Blender is not installed.
set -euo pipefail
exe=$1
src=$2
mode=${3:-bytes}
if [ "$mode" = blender ] && ! command -v blender >/dev/null; then
  echo "SKIPPED: blender is not installed (scripts/setup.sh installs it)"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

"$exe" evolve "$src/tests/app/fixtures/engine_elites.json" --out elites >/dev/null 2>&1
"$exe" evolve "$src/tests/app/fixtures/engine_best.json" --out ga >/dev/null 2>&1

if [ "$mode" = bytes ]; then
  for run in elites ga; do
    "$exe" archive $run --pack ${run}_a --lods 3 --wind --height 2 >/dev/null
    "$exe" archive $run --pack ${run}_b --lods 3 --wind --height 2 >/dev/null
    diff -r ${run}_a ${run}_b
    ls ${run}_a/plant_*.glb >/dev/null
    test -f ${run}_a/scatter.glb
    test -f ${run}_a/manifest.json
  done
  # A used directory is refused (exit 3: an I/O error) and keeps its files.
  mkdir used && echo mine >used/notes.txt
  status=0
  "$exe" archive elites --pack used 2>err.txt || status=$?
  if [ "$status" -ne 3 ] || ! grep -q "not empty" err.txt || [ "$(cat used/notes.txt)" != mine ] ||
     [ "$(ls used)" != notes.txt ]; then
    echo "a used directory: exit $status, $(cat err.txt), now holds: $(ls used)" >&2
    exit 1
  fi
  # A GA run without --pack is still refused.
  if "$exe" archive ga --out ga_elites 2>/dev/null; then
    echo "archive of a GA run without --pack was not refused" >&2
    exit 1
  fi
  echo "same bytes: $(ls elites_a | wc -l) + $(ls ga_a | wc -l) files"
  exit 0
fi

"$exe" archive elites --pack elites_pack --lods 3 --wind --height 2 >/dev/null
"$exe" archive ga --pack ga_pack --lods 2 >/dev/null
"$exe" archive elites --pack plain_pack --top 3 >/dev/null
# One Blender start for the three packs.
blender -b --factory-startup --python-exit-code 1 --python "$src/tests/engine/blender_pack_check.py" -- \
  elites_pack ga_pack plain_pack >blender.log 2>&1 || { cat blender.log; exit 1; }
grep -E "^(blender|_WIND)" blender.log
