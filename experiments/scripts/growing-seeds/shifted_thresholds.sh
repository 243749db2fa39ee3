#!/usr/bin/env bash
# The grow share of N random genomes whose output thresholds of w[0] and w[3]
# are rewritten by a Python expression of the drawn value x ("x - 5": centred
# at -5; "-4": set to -4), drawn by a build without the centre (before
# 8d2a332). Usage: shifted_thresholds.sh MORPHOGEN CONFIG FIRST N EXPR [CHANNELS]
# CHANNELS: a Python tuple of output channels, default "(0, 3)".
set -euo pipefail
exe=$1 config=$2 first=$3 count=$4 expr=$5 channels=${6:-"(0, 3)"}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for ((s = first; s < first + count; s++)); do
  "$exe" grow --config "$config" --random "$s" --steps 0 -o "$out/x.obj" --save-genome "$out/g.json" > /dev/null
  python3 - "$out/g.json" "$expr" "$channels" <<'PY'
import json, sys
path, expr, channels = sys.argv[1], sys.argv[2], eval(sys.argv[3])
g = json.load(open(path)); p = g["params"]; L = g["layers"]
start = sum(L[l] * (L[l - 1] + 1) for l in range(1, len(L) - 1))  # the output layer
for j in channels:
    t = start + j * (L[-2] + 1) + L[-2]  # neuron j's threshold follows its weights
    x = p[t]
    p[t] = eval(expr)
json.dump(g, open(path, "w"))
PY
  "$exe" grow --config "$config" --genome "$out/g.json" -o "$out/x.obj"
done | sed -n 's/.*: \([0-9]*\) vertices.*height \([0-9.e+-]*\),.*/\1 \2/p' |
  awk '{n++; if ($2 >= 3.56) g++; v += $1} END {printf "%d of %d grow to twice the seed (mean vertices %.0f)\n", g, n, v / n}'
