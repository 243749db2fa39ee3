#!/usr/bin/env bash
# Whole runs of the previous tree.json (experiments/scripts/trees/tree-2026-11-24.json)
# with the binary of issue 36's day, and of configs/tree.json with this
# checkout's build, started together, one thread each, one pair per seed
# (experiments/2026-11-28-architecture-maps.md, "A whole run against the previous config").
#
# usage: experiments/scripts/trees/whole_run_side_by_side.sh OLD_MORPHOGEN SEED...
#   OLD_MORPHOGEN: a release build of 84797b7 (the binary of 2026-11-27,
#   before the issue's work). Runs go to out/side-by-side/ (OUT=... to change);
#   prints one line per run with its wall, user and system seconds.
#   Cost: per seed about 30-40 minutes of one core for the old run and 6-12 for the new.
set -euo pipefail
cd "$(dirname "$0")/../../.."
old_exe=$(realpath "$1")
shift
new_exe=$PWD/build/morphogen
out=${OUT:-out/side-by-side}
mkdir -p "$out"
cp configs/schema.json "$out/"
cp experiments/scripts/trees/tree-2026-11-24.json "$out/old.json"
cp configs/tree.json "$out/new.json"
for seed in "$@"; do
  for which in old new; do
    exe=$new_exe; [ "$which" = old ] && exe=$old_exe
    /usr/bin/time -f "$which seed $seed: %e s wall, %U s user, %S s sys" -o "$out/$which-$seed.time" \
      "$exe" evolve "$out/$which.json" --seed "$seed" --threads 1 --out "$out/$which-$seed" --force --no-report \
      > "$out/$which-$seed.log" 2>&1 &
  done
  wait
  cat "$out/old-$seed.time" "$out/new-$seed.time"
done
