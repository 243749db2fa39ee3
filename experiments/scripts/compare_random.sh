#!/usr/bin/env bash
# GA against random search at an equal budget of evaluations, over several
# seeds (experiments/2026-11-21-ga-vs-random-search.md). The GA's budget is
# population * (generations + 1) births; random search grows that many random
# genomes and keeps the best.
# usage: experiments/scripts/compare_random.sh [CONFIG] [GENERATIONS] [SEEDS...]
#   defaults: configs/canopy.json 40 1 2 3   -> results in out/compare/
set -euo pipefail
cd "$(dirname "$0")/../.."
config=${1:-configs/canopy.json}
generations=${2:-40}
shift $(( $# > 2 ? 2 : $# ))
seeds=("$@")
[ ${#seeds[@]} -gt 0 ] || seeds=(1 2 3)
exe=build/morphogen
out=out/compare
mkdir -p "$out"
population=$("$exe" validate --resolved "$config" | python3 -c 'import json,sys; print(json.loads(sys.stdin.read().split("\n",1)[1])["evolution"]["population"])' 2>/dev/null || echo 100)
budget=$(( population * (generations + 1) ))

best_of_csv() {  # column-named maximum of a CSV
  python3 - "$1" "$2" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r[sys.argv[2]]]
print(max(float(r[sys.argv[2]]) for r in rows))
PY
}

echo "| seed | GA best after $budget births | random search best of $budget | GA / random |"
echo "|---|---|---|---|"
for s in "${seeds[@]}"; do
  "$exe" evolve "$config" --seed "$s" --generations "$generations" --out "$out/ga-$s" --force > "$out/ga-$s.log" 2>&1
  "$exe" gallery --config "$config" --count "$budget" --seed $(( s * 1000000 )) --out "$out/random-$s" \
    --format none > "$out/random-$s.log" 2>&1 || true
  ga=$(tail -n 1 "$out/ga-$s/history.csv" | cut -d, -f3)
  random=$(best_of_csv "$out/random-$s/summary.csv" fitness)
  python3 -c "print(f'| $s | {float($ga):.2f} | {float($random):.2f} | {float($ga)/float($random):.2f} |')"
done
