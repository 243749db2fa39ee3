#!/usr/bin/env bash
# The share of random genomes whose grown mesh self-intersects (CGAL's check,
# the fitness "self_intersecting"), for each collision rule, mode and size.
# Usage: self_intersection_rate.sh MORPHOGEN [GENOMES] [RULES...]
# MODES and SIZES (environment) pick rows, e.g. MODES=branching SIZES=default.
# One evolve run per row: GENOMES random genomes (generation 0, init_range 2,
# seed 1), scored 1 when self-intersecting; prints a Markdown table row each.
set -euo pipefail
morphogen=${1:?usage: self_intersection_rate.sh MORPHOGEN [GENOMES] [RULES...]}
genomes=${2:-1000}
shift $(( $# >= 2 ? 2 : 1 ))
rules=("$@")
[ $# -eq 0 ] && rules=(allow touch)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| mode | settings | collisions | self-intersecting | rate | mean vertices | seconds |"
echo "|---|---|---|---|---|---|---|"
for mode in ${MODES:-paper branching}; do
  for size in ${SIZES:-default tree}; do
    for rule in "${rules[@]}"; do
      growth="\"mode\": \"$mode\", \"collisions\": \"$rule\""
      # CONTACT (environment): growth.contact_distance of the "touch" rows.
      [ "$rule" = touch ] && [ -n "${CONTACT:-}" ] && growth="$growth, \"contact_distance\": $CONTACT"
      [ "$size" = tree ] && growth="$growth, \"steps\": 150, \"max_vertices\": 1000"
      cat > "$work/c.json" <<JSON
{"growth": {$growth}, "fitness": {"type": "self_intersecting"},
 "evolution": {"population": $genomes}, "run": {"seed": 1, "generations": 0, "threads": 1, "name": "rate"}}
JSON
      start=$(date +%s.%N)
      "$morphogen" evolve "$work/c.json" --out "$work/run" --force --no-report --no-limits > "$work/out.txt" 2>&1
      vertices=$(grep -o "mean vertices [0-9.]*" "$work/out.txt" | tail -1 | cut -d" " -f3)
      seconds=$(echo "$(date +%s.%N) - $start" | bc)
      bad=$(awk -F, 'NR > 1 && $5 + 0 > 0.5 { n++ } END { print n + 0 }' "$work/run/lineage.csv")
      printf "| %s | %s | %s | %d of %d | %.1f %% | %s | %.0f |\n" "$mode" "$size" "$rule" "$bad" "$genomes" \
        "$(echo "100 * $bad / $genomes" | bc -l)" "$vertices" "$seconds"
    done
  done
done
