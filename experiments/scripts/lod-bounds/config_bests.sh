#!/usr/bin/env bash
# Grows the best of each shipped config (configs/*.json but schema.json) as a
# PLY, for lod_bounds: runs each config for GENERATIONS generations (default:
# the config's own; the study used 25 for quick.json and 3 for the others on
# a shared 2-core machine), then grows the last best-of-generation genome.
# usage: experiments/scripts/lod-bounds/config_bests.sh OUT_DIR [GENERATIONS]
set -euo pipefail
root="$(cd "$(dirname "$0")/../../.." && pwd)"
out="$1"
mkdir -p "$out"
for config in "$root"/configs/*.json; do
    name="$(basename "$config" .json)"
    [[ "$name" == schema ]] && continue
    gens=()
    [[ -n "${2:-}" && "$name" != quick ]] && gens=(--generations "$2")
    "$root/build/morphogen" evolve "$config" "${gens[@]}" --threads 1 --no-report --force --out "$out/run-$name" >/dev/null
    best="$(ls "$out/run-$name"/best/gen_*.genome.json | tail -1)"
    "$root/build/morphogen" grow --config "$config" --genome "$best" -o "$out/best-$name.ply" --ply-double
done
