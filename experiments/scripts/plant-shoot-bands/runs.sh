#!/usr/bin/env bash
# configs/tree.json's GA on one seed, one thread each, 6,100 births: from
# random genomes (OUT_DIR/ga_sSEED), then from each GENOME (--from; OUT_DIR/NAME_sSEED,
# NAME the genome's folder under examples/, e.g. bred-tree, bred-tree-by-eye).
# Usage: runs.sh MORPHOGEN OUT_DIR SEED [GENOME ...]
set -euo pipefail
exe=$1 out=$2 seed=$3; shift 3
mkdir -p "$out"
/usr/bin/time -f "ga seed $seed wall %e s" "$exe" evolve configs/tree.json --seed "$seed" --threads 1 \
  --out "$out/ga_s$seed" --force --no-report
for genome in "$@"; do
  name=$(basename "$(dirname "$genome")")
  /usr/bin/time -f "$name seed $seed wall %e s" "$exe" evolve configs/tree.json --seed "$seed" --threads 1 \
    --from "$genome" --out "$out/${name}_s$seed" --force --no-report
done
