#!/usr/bin/env bash
# How many of N random genomes (seeds FIRST..FIRST+N-1) grow to at least
# twice the seed's height (3.56) with a config. Usage:
#   grow_share.sh MORPHOGEN CONFIG FIRST N
set -euo pipefail
exe=$1 config=$2 first=$3 count=$4
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for ((s = first; s < first + count; s++)); do
  "$exe" grow --config "$config" --random "$s" -o "$out/x.obj"
done | sed -n 's/.*: \([0-9]*\) vertices.*height \([0-9.e+-]*\),.*/\1 \2/p' |
  awk '{n++; if ($2 >= 3.56) g++; v += $1} END {printf "%d of %d grow to twice the seed (mean vertices %.0f)\n", g, n, v / n}'
