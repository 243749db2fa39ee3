#!/usr/bin/env bash
# Novelty search with local competition (evolution.algorithm "nslc") over
# tips x limbs x first fork height, tree.json's growth and fitness, 6,100 births.
# Usage: nslc.sh MORPHOGEN OUT_DIR SEED [THREADS]
set -euo pipefail
exe=$1 out=$2 seed=$3 threads=${4:-2}
here=$(dirname "$0")
mkdir -p "$out"
/usr/bin/time -f "seed $seed wall %e s" "$exe" evolve "$here/nslc.json" --seed "$seed" --threads "$threads" --out "$out/nslc_s$seed" --force --no-report
