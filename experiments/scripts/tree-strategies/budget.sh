#!/usr/bin/env bash
# configs/tree.json at a vertex budget of 2,000 (tree2000.json); 2,100 births
# (20 generations) unless GENERATIONS is given.
# Usage: budget.sh MORPHOGEN OUT_DIR SEED [THREADS] [GENERATIONS]
set -euo pipefail
exe=$1 out=$2 seed=$3 threads=${4:-2} generations=${5:-20}
here=$(dirname "$0")
mkdir -p "$out"
/usr/bin/time -f "seed $seed wall %e s" "$exe" evolve "$here/tree2000.json" --seed "$seed" --threads "$threads" --generations "$generations" --out "$out/b2000_s$seed" --force --no-report
