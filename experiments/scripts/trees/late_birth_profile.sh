#!/usr/bin/env bash
# Where a late tree.json birth's CPU time goes: a copy of a finished run is
# resumed for GENERATIONS more generations on one thread under
# `perf record --call-graph dwarf`, and the inclusive shares of growth's and
# the fitness's parts are printed (experiments/2026-11-28-architecture-maps.md,
# "A whole run against the previous config").
#
# usage: experiments/scripts/trees/late_birth_profile.sh RUN_DIR [GENERATIONS]
#   RUN_DIR: a finished configs/tree.json run (left untouched); GENERATIONS
#   default 2 (200 births, about 15 s of one core). Needs perf.
set -euo pipefail
cd "$(dirname "$0")/../../.."
run=$1 more=${2:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$run" "$work/run"
done_generations=$(( $(wc -l < "$work/run/history.csv") - 2 ))
perf record -F 199 --call-graph dwarf,16384 -o "$work/perf.data" build/morphogen resume "$work/run" \
  --generations $(( done_generations + more )) --threads 1 --no-report > "$work/log.txt" 2>&1
perf report -i "$work/perf.data" --children --sort symbol 2>/dev/null \
  | grep -E '^ +[0-9.]+% +[0-9.]+%' | sed 's/  */ /g' \
  | grep -E 'GrowthProblem::evaluate_mesh|Grower::grow -|settle_move|ContactGuard::allows|SelfIntersectionCheck::intersects|Grower::think|kernel::evaluate|compute_exposure|diffuse_signal|Grower::branch|flip_pass|Fitness::evaluate|light_per_face|mesh_self_intersects|measure_architecture'
