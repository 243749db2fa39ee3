#!/usr/bin/env bash
# CTest "scripts: scaling": scripts/scaling.sh on a small config, 2 cores'
# worth: it must print the machine's limit and a row for every layout, every
# run exiting 0 with the same lineage.csv.
set -u
exe=$1 root=$2 out=$3
rm -rf "$out"
cat > "$out.json" <<'JSON'
{"network": {"outputs": 4, "hidden": [4]}, "growth": {"steps": 8, "max_vertices": 200},
 "fitness": {"type": "height"}, "evolution": {"population": 8, "lag": 4, "mutation_rate": 0.2},
 "run": {"seed": 7, "export_every": 1}}
JSON
report=$(MORPHOGEN=$exe OUT=$out "$root/scripts/scaling.sh" "$out.json" 3 2 2>&1)
echo "$report"
echo "$report" | grep -q "machine limit: 2 single-thread processes" || { echo "no machine limit"; exit 1; }
rows=$(echo "$report" | grep -c "| same |")
! echo "$report" | grep -q "DIFFERS\|failed" || { echo "a layout failed or differs"; exit 1; }
expected=2
command -v "${MPIRUN:-mpirun}" > /dev/null && expected=4
[ "$rows" = "$expected" ] || { echo "$rows layouts agree, expected $expected"; exit 1; }
