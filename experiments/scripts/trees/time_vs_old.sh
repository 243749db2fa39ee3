#!/usr/bin/env bash
# The time of the first births of configs/tree.json against the previous
# tree.json (experiments/scripts/trees/tree-2026-11-24.json) grown by the
# binary of its day, alternating, each on one thread, twice
# (experiments/2026-11-27-trees-with-limbs.md, "Time against the previous config").
#
# usage: experiments/scripts/trees/time_vs_old.sh OLD_MORPHOGEN [GENERATIONS]
#   (default 1: generations 0 and 1, 200 births each); prints one line per run
#   with the wall and user (CPU) seconds. Work in a temporary directory.
set -euo pipefail
cd "$(dirname "$0")/../../.."
old_exe=$1 generations=${2:-1}
new_exe=$PWD/build/morphogen
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp configs/schema.json "$work/"
cp experiments/scripts/trees/tree-2026-11-24.json "$work/old.json"
cp configs/tree.json "$work/new.json"
cd "$work"
for i in 1 2; do
  for which in old new; do
    exe=$new_exe; [ "$which" = old ] && exe=$old_exe
    /usr/bin/time -f "$which $i: %e s wall, %U s user" -o time.txt nice -n 10 "$exe" evolve "$which.json" \
      --generations "$generations" --threads 1 --out "$which$i" --force --no-report > /dev/null 2>&1
    cat time.txt
  done
done
