#!/usr/bin/env bash
# What this machine (or an allocation) gives morphogen, before a week-long run:
#   1. the machine's own limit: N single-thread `bench` processes at once,
#      against one alone (cores that share FMA units or memory bandwidth give
#      less than N);
#   2. evolution of CONFIG from scratch with 1 and N threads;
#   3. MPI layouts of N worker threads: N+1 processes x 1 thread, ..., 2 x N;
# each as births/s, speed-up over one thread, and efficiency against the
# limit; and whether every run wrote the same lineage.csv (it must).
#
# usage: scripts/scaling.sh [CONFIG] [GENERATIONS] [N]
#   defaults: configs/canopy.json 10 (all cores)
# env: MORPHOGEN (default build/morphogen), MPIRUN (default mpirun; layouts are
# skipped without it), OUT (default out/scaling)
set -u
cd "$(dirname "$0")/.."
config=${1:-configs/canopy.json}
gens=${2:-10}
n=${3:-$(nproc)}
exe=${MORPHOGEN:-build/morphogen}
mpirun=${MPIRUN:-mpirun}
out=${OUT:-out/scaling}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

now() { date +%s.%N; }
calc() { python3 -c "print(f'{$1:.3g}')"; }

"$exe" bench --json --threads 1 --genomes 16 --repeat 1 > "$out/solo.json"
pids=()
for i in $(seq "$n"); do
  "$exe" bench --json --threads 1 --genomes 16 --repeat 1 > "$out/limit$i.json" & pids+=($!)
done
wait "${pids[@]}"
limit=$(python3 - "$out" "$n" <<'PY'
import json, sys
out, n = sys.argv[1], int(sys.argv[2])
key = "vertex_steps_per_s_1t"
solo = json.load(open(f"{out}/solo.json"))[key]
print(f"{sum(json.load(open(f'{out}/limit{i}.json'))[key] for i in range(1, n + 1)) / solo:.3g}")
PY
)
echo "machine limit: $n single-thread processes at once = ${limit}x one"
echo
echo "| layout | births/s | speed-up over 1 thread | of the limit | lineage.csv |"
echo "|---|---|---|---|---|"
one=""
reference=""
run() {  # PROCESSES THREADS (processes 0: a plain run)
  local dir="$out/np$1_t$2" t0 t1 births rate check
  rm -rf "$dir"
  t0=$(now)
  if [ "$1" = 0 ]; then
    "$exe" evolve "$config" --out "$dir" --generations "$gens" --threads "$2" --no-report > "$dir.log" 2>&1
  else
    "$mpirun" --oversubscribe --bind-to none -np "$1" "$exe" evolve "$config" --out "$dir" --generations "$gens" \
      --threads "$2" --no-report > "$dir.log" 2>&1
  fi
  local rc=$?
  t1=$(now)
  if [ $rc != 0 ]; then echo "| $(label "$1" "$2") | failed (exit $rc, $dir.log) | | | |"; return; fi
  births=$(( $(wc -l < "$dir/lineage.csv") - 1 ))
  rate=$(calc "$births/($t1-$t0)")
  [ -z "$one" ] && one=$rate
  check=$(md5sum < "$dir/lineage.csv" | cut -c1-8)
  [ -z "$reference" ] && reference=$check
  [ "$check" = "$reference" ] && check="same" || check="DIFFERS ($check)"
  echo "| $(label "$1" "$2") | $rate | $(calc "$rate/$one") | $(calc "$rate/$one/$limit") | $check |"
}
label() {
  local threads="$2 threads"
  [ "$2" = 1 ] && threads="1 thread"
  [ "$1" = 0 ] && echo "$threads" || echo "$1 processes x $threads"
}

run 0 1
run 0 "$n"
if command -v "$mpirun" > /dev/null; then
  t=1
  while [ "$t" -le "$n" ]; do
    run $(( n / t + 1 )) "$t"
    t=$(( t * 2 ))
  done
else
  echo "($mpirun not found: MPI layouts skipped)"
fi
