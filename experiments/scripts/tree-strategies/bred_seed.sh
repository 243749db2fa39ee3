#!/usr/bin/env bash
# configs/tree.json's GA started from one genome bred by hand (--from GENOME:
# the genome itself and 99 of its mutants in generation 0), 6,100 births.
# Usage: bred_seed.sh MORPHOGEN OUT_DIR SEED GENOME [THREADS]
set -euo pipefail
exe=$1 out=$2 seed=$3 genome=$4 threads=${5:-2}
mkdir -p "$out"
/usr/bin/time -f "seed $seed wall %e s" "$exe" evolve configs/tree.json --seed "$seed" --threads "$threads" --from "$genome" --out "$out/bred_s$seed" --force --no-report
