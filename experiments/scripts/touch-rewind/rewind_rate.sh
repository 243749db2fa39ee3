#!/usr/bin/env bash
# Builds rewind_rate.cpp against a release build's libraries and runs it for
# both modes at the default settings and at configs/tree.json's sizes.
# Usage: rewind_rate.sh [N] (from the repository root, after
# scripts/build.sh release morphogen).
set -euo pipefail
n=${1:-1000}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
g++ -std=c++20 -O2 -I. -I/usr/include/eigen3 experiments/scripts/touch-rewind/rewind_rate.cpp \
  build/growth/libmorphogen_growth.a build/io/libmorphogen_io.a build/mesh/libmorphogen_mesh.a \
  build/base/libmorphogen_base.a -ltinygltf -lgmp -lmpfr -lpthread -o "$out/rewind_rate"
echo "| mode | settings | rewound | rate | steps lost (median) | steps lost (max) | mean vertices | seconds |"
echo "|---|---|---|---|---|---|---|---|"
for row in "paper default" "paper tree" "branching default" "branching tree" "branching tree.json"; do
  nice -n 10 "$out/rewind_rate" $row "$n" | tee "$out/log" >&2
  tail -1 "$out/log"
done
