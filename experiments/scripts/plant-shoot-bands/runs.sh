#!/usr/bin/env bash
# configs/tree.json's GA, from random genomes and from examples/bred-tree's
# genome, on one seed, one thread each, 6,100 births.
# Usage: runs.sh MORPHOGEN OUT_DIR SEED
set -euo pipefail
exe=$1 out=$2 seed=$3
mkdir -p "$out"
/usr/bin/time -f "ga seed $seed wall %e s" "$exe" evolve configs/tree.json --seed "$seed" --threads 1 \
  --out "$out/ga_s$seed" --force --no-report
/usr/bin/time -f "bred seed $seed wall %e s" "$exe" evolve configs/tree.json --seed "$seed" --threads 1 \
  --from examples/bred-tree/tree.genome.json --out "$out/bred_s$seed" --force --no-report
