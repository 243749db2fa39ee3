#!/usr/bin/env bash
# Same results across two builds of morphogen (a refactor's check): for each
# shipped config, a fresh run of OLD and of NEW, and NEW resuming OLD's run
# stopped halfway, must be equal up to clocks and config format
# (compare_runs.py). Usage: same_results.sh OLD_EXE NEW_EXE WORK_DIR
set -euo pipefail
old=$1 new=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
configs=$(cd "$here/../../../configs" && pwd)
mkdir -p "$work"
status=0
# config:generations, small enough to run in a minute or two on 2 cores.
for item in quick:6 canopy:4 map_elites:6 tree:2 tree_map:2; do
  name=${item%%:*} gens=${item##*:} half=$(( ${item##*:} / 2 ))
  rm -rf "$work/$name"-*
  "$old" evolve "$configs/$name.json" --out "$work/$name-old" --generations "$gens" --no-report >/dev/null 2>&1
  "$new" evolve "$configs/$name.json" --out "$work/$name-new" --generations "$gens" --no-report >/dev/null 2>&1
  "$old" evolve "$configs/$name.json" --out "$work/$name-resumed" --generations "$half" --no-report >/dev/null 2>&1
  "$new" resume "$work/$name-resumed" --generations "$gens" --no-report >/dev/null 2>&1
  for other in new resumed; do
    if python3 "$here/compare_runs.py" "$work/$name-old" "$work/$name-$other" > "$work/$name-$other.diff"; then
      echo "$name: old fresh == new $other"
    else
      echo "$name: old fresh != new $other"; sed 's/^/    /' "$work/$name-$other.diff"; status=1
    fi
  done
done
exit $status
