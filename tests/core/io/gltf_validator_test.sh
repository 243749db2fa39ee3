#!/usr/bin/env bash
# Every kind of GLB morphogen writes passes the Khronos glTF validator
# (tools/gltf, installed by scripts/setup.sh) with 0 errors and 0 warnings:
# grow's plain and engine-ready GLBs (with and without wind and levels of
# detail), the growth animation, a run's best of generation and archive's
# elites (also with levels of detail), the best of generation with
# run.export_glb (GA with levels of detail and wind, MAP-Elites with wind
# only), and species packs (every plant_<id>.glb and scatter.glb) of a
# MAP-Elites and a GA run, with and without levels of detail and wind; each
# wind preset (--wind-preset color, uv, godot) alone, all three with levels
# of detail, and a pack with all three; foliage cards (--leaves) alone and
# with all of these.
# Usage: gltf_validator_test.sh MORPHOGEN SOURCE_DIR. Exit 77 (skipped) only
# when node is not installed.
set -euo pipefail
exe=$1
src=$2
if ! command -v node >/dev/null; then
  echo "SKIPPED: node is not installed (scripts/setup.sh installs nodejs and the validator)"
  exit 77
fi
if [ ! -d "$src/tools/gltf/node_modules/gltf-validator" ]; then
  echo "the Khronos validator is missing: run scripts/setup.sh (npm ci in tools/gltf)" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

"$exe" grow --random 3 --steps 60 -o plain.glb --animate animation.glb --frames 8 >/dev/null
# The animation is plain whatever the mesh beside it asks for.
"$exe" grow --random 4 --steps 200 -o lods_wind.glb --lods 3 --wind --animate animation_beside_lods.glb --frames 6 >/dev/null
"$exe" grow --random 3 --steps 60 -o height.glb --height 2.5 >/dev/null
"$exe" grow --random 3 --steps 60 -o wind.glb --wind >/dev/null
"$exe" grow --random 3 --steps 60 -o height_wind.glb --height 4 --wind >/dev/null
"$exe" grow --random 3 --steps 200 -o lods.glb --lods 3 >/dev/null
"$exe" grow --random 3 --steps 200 -o lods_height_wind.glb --lods 4 --height 4 --wind >/dev/null
for preset in color uv godot; do
  "$exe" grow --random 3 --steps 60 -o "preset_$preset.glb" --wind --wind-preset $preset >/dev/null
done
"$exe" grow --random 4 --steps 120 -o presets_lods.glb --lods 2 --wind --wind-preset color,uv,godot >/dev/null
# --colour: COLOR_0 in both growth modes, beside levels of detail and the presets it may join.
"$exe" grow --random 3 --steps 60 -o colour.glb --colour >/dev/null
"$exe" grow --random 4 --steps 200 -o colour_lods_wind.glb --colour --lods 3 --wind --wind-preset uv,godot >/dev/null
"$exe" grow --config "$src/configs/tree.json" --random 5 --steps 120 -o colour_branching.glb --colour >/dev/null
if "$exe" grow --random 3 --steps 10 -o refused.glb --colour --wind --wind-preset color 2>refused.txt; then
  echo "--colour with --wind-preset color was not refused" >&2
  exit 1
fi
grep -q -- "--colour and --wind-preset color both write COLOR_0" refused.txt
# --leaves: the cards' primitive, leaf material and embedded texture, alone,
# with levels of detail, wind and every preset (uv moves the leaf's UVs to
# TEXCOORD_2), with colour, in the branching mode, in archive and a pack.
"$exe" grow --random 3 --steps 200 -o leaves.glb --leaves >/dev/null
"$exe" grow --random 4 --steps 200 -o leaves_lods_wind.glb --leaves --leaf-size 0.1 --leaf-density 1 --lods 3 --wind \
  --wind-preset uv,godot --colour --height 3 >/dev/null
"$exe" grow --random 4 --steps 120 -o leaves_color_preset.glb --leaves --wind --wind-preset color >/dev/null
"$exe" grow --config "$src/configs/tree_map.json" --random 5 -o leaves_branching.glb --leaves --lods 2 >/dev/null
node -e 'const b=require("fs").readFileSync(process.argv[1]); const n=b.readUInt32LE(12);
  const j=JSON.parse(b.subarray(20, 20 + n)); if (j.meshes[0].primitives.length !== 2 || j.materials[1].alphaMode !== "MASK" ||
  !j.images || j.images[0].mimeType !== "image/png") process.exit(1);' leaves_lods_wind.glb

"$exe" evolve "$src/tests/app/fixtures/engine_elites.json" --out run >/dev/null 2>&1
"$exe" archive run --out plain_elites >/dev/null
"$exe" archive run --out engine_elites --height 1.5 --wind >/dev/null
"$exe" archive run --out lod_elites --lods 2 --wind >/dev/null
"$exe" archive run --out colour_elites --lods 2 --colour >/dev/null
"$exe" archive run --out leaf_elites --lods 2 --wind --leaves >/dev/null
"$exe" evolve "$src/tests/app/fixtures/engine_best.json" --out engine_run >/dev/null 2>&1
# run.export_glb of a MAP-Elites run: wind, no levels of detail.
sed 's/"export_every": 1}/"export_every": 1, "export_glb": {"wind": true}}/' \
  "$src/tests/app/fixtures/engine_elites.json" >elites_wind.json
"$exe" evolve elites_wind.json --out elites_wind_run >/dev/null 2>&1
sed 's/"export_every": 1}/"export_every": 1, "export_glb": {"colour": true}}/' \
  "$src/tests/app/fixtures/engine_elites.json" >elites_colour.json
"$exe" evolve elites_colour.json --out elites_colour_run >/dev/null 2>&1
node -e 'const b=require("fs").readFileSync(process.argv[1]); const n=b.readUInt32LE(12);
  const j=JSON.parse(b.subarray(20, 20 + n)); if (!("COLOR_0" in j.meshes[0].primitives[0].attributes)) process.exit(1);' \
  elites_colour_run/best/gen_0000.glb
"$exe" archive run --pack pack_plain >/dev/null
"$exe" archive run --pack pack_lods_wind --lods 3 --wind --height 2 >/dev/null
"$exe" archive engine_run --pack pack_ga_lods --lods 2 >/dev/null
"$exe" archive engine_run --pack pack_ga_wind --wind --wind-preset color --wind-preset uv,godot >/dev/null
"$exe" archive run --pack pack_leaves --leaves --lods 2 --wind >/dev/null
for pack in pack_plain pack_lods_wind pack_ga_lods pack_ga_wind pack_leaves; do
  test -f "$pack/manifest.json"
  test -f "$pack/scatter.glb"
done

node "$src/tools/gltf/validate.js" ./*.glb run/best/*.glb plain_elites/*.glb engine_elites/*.glb lod_elites/*.glb colour_elites/*.glb leaf_elites/*.glb \
  engine_run/best/*.glb elites_wind_run/best/*.glb elites_colour_run/best/*.glb pack_*/*.glb
