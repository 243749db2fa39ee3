#!/usr/bin/env bash
# Builds morphogen's libFuzzer targets (fuzz/) and runs each for a while.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
#   SECONDS_PER_TARGET  default 60
#   TARGET              config genome mesh checkpoint (default: all four)
# Environment: FUZZ_TIMEOUT (seconds one input may run before it counts as a
# hang, default 10), FUZZ_RSS_MB (memory limit, default 2048).
#
# Installs clang 14, its libFuzzer runtime and libomp where missing
# (idempotent), builds build-fuzz/ with clang++ and
# -fsanitize=fuzzer,address,undefined (-DMORPHOGEN_FUZZ=ON), then runs the
# targets one after another, one process at a time (-fork=1), seeded from
# tests/corpus/<target>/. A finding does not stop a target: crashes, sanitizer
# reports, undocumented exceptions, hangs (-timeout) and out-of-memory inputs
# are all saved in build-fuzz/findings/<target>/ and fuzzing goes on. New
# interesting inputs collect in build-fuzz/corpus/<target>/.
# Exit status: 0 no findings, 1 findings, 2 bad usage or build failure.
# docs/limits.md, "Fuzzing", says what a finding is and what to do with one.
set -euo pipefail
cd "$(dirname "$0")/.."

all_targets=(config genome mesh checkpoint)
seconds=${1:-60}
[[ "$seconds" =~ ^[0-9]+$ ]] && [ "$seconds" -gt 0 ] || { echo "usage: $0 [SECONDS_PER_TARGET] [TARGET...]" >&2; exit 2; }
shift $(( $# > 0 ? 1 : 0 ))
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")
for t in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $t "* ]] || { echo "fuzz: unknown target '$t' (targets: ${all_targets[*]})" >&2; exit 2; }
done
timeout_s=${FUZZ_TIMEOUT:-10}
rss_mb=${FUZZ_RSS_MB:-2048}

# --- packages: the base set, then clang and libFuzzer (as scripts/setup.sh does)
scripts/setup.sh
packages=(clang-14 libclang-rt-14-dev libomp-14-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "fuzz: need root or sudo to install: ${missing[*]}" >&2; exit 2; }
    sudo=(sudo)
  fi
  echo "fuzz: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -qq
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# --- build
dir=build-fuzz
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S . -B "$dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++-14 \
  -DMORPHOGEN_FUZZ=ON -DMORPHOGEN_BUILD_TESTS=OFF >/dev/null || exit 2
build_targets=()
for t in "${targets[@]}"; do build_targets+=(--target "fuzz_$t"); done
cmake --build "$dir" --parallel "$(nproc)" "${build_targets[@]}" || exit 2

# --- triage: one line per distinct finding, "count  kind: first report line"
# (numbers and quoted text blanked, so one defect hit with many inputs counts
# once), followed by an example file. Crashes are rerun to read their report.
triage() {
  local t=$1 findings=$2 f kind line
  for f in $(ls -t "$findings" | head -200); do
    case "$f" in
      timeout-*) line="hang: ran longer than ${timeout_s}s" ;;
      oom-*) line="out of memory: above ${rss_mb} MB" ;;
      slow-unit-*) continue ;;
      *)
        line=$(timeout $((timeout_s * 3)) "$dir/fuzz/fuzz_$t" -timeout="$timeout_s" -rss_limit_mb="$rss_mb" \
                 "$findings/$f" 2>&1 | grep -m1 -E 'fuzz finding:|runtime error:|ERROR: AddressSanitizer|ERROR: libFuzzer|SUMMARY:' \
                 | sed -E "s/^.*(fuzz finding:|runtime error:|ERROR: AddressSanitizer|ERROR: libFuzzer)/\\1/" || true)
        [ -n "$line" ] || line="crash: no report (rerun $findings/$f)" ;;
    esac
    kind=$(printf '%s' "$line" | sed -E "s/'[^']*'/'...'/g; s/0x[0-9a-f]+/0x.../g; s/[0-9]+/N/g" | cut -c1-220)
    printf '%s\t%s\n' "$kind" "$findings/$f"
  done | sort | awk -F'\t' '{n[$1]++; if (!($1 in ex)) ex[$1]=$2} END {for (k in n) printf "%6d  %s\n        e.g. %s\n", n[k], k, ex[k]}'
}

# --- run
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
total_findings=0
summary=()
for t in "${targets[@]}"; do
  work="$dir/corpus/$t" findings="$dir/findings/$t" log="$dir/logs/$t.log"
  mkdir -p "$work" "$findings" "$dir/logs"
  seeds="tests/corpus/$t"
  if [ "$t" = mesh ]; then
    # The mesh target reads a format byte first (fuzz/fuzz_mesh.cpp).
    seeds="$dir/seeds/mesh"
    rm -rf "$seeds" && mkdir -p "$seeds"
    for f in tests/corpus/mesh/*; do
      case "${f,,}" in
        *.obj) tag=o ;; *.ply) tag=p ;; *.off) tag=f ;; *.stl) tag=s ;; *) continue ;;
      esac
      { printf '%s' "$tag"; cat "$f"; } > "$seeds/$(basename "$f")"
    done
  fi
  dict=fuzz/json.dict
  [ "$t" = mesh ] && dict=fuzz/mesh.dict
  before=$(find "$findings" -type f | wc -l)
  echo "fuzz: $t for ${seconds}s (timeout ${timeout_s}s per input, log $log)"
  set +e
  "$dir/fuzz/fuzz_$t" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_total_time="$seconds" -timeout="$timeout_s" -rss_limit_mb="$rss_mb" \
    -dict="$dict" -artifact_prefix="$findings/" -print_final_stats=1 \
    "$work" "$seeds" >"$log" 2>&1
  rc=$?
  set -e
  after=$(find "$findings" -type f | wc -l)
  new=$((after - before))
  total_findings=$((total_findings + new))
  triage "$t" "$findings" >"$dir/logs/$t.findings.txt"
  # Fork mode's status lines: "#<execs>: cov: .. corp: .. exec/s: .. oom/timeout/crash: a/b/c time: ..s".
  status=$(grep -E '^#[0-9]+: cov:' "$log" | tail -1 || true)
  [ -n "$status" ] || status=$(tail -1 "$log")
  summary+=("$t: $new new finding(s), libFuzzer exit $rc; $status")
  [ ! -s "$dir/logs/$t.findings.txt" ] || summary+=("$(sed 's/^/  /' "$dir/logs/$t.findings.txt")")
done

echo
echo "fuzz summary (${seconds}s per target):"
printf '  %s\n' "${summary[@]}"
if [ "$total_findings" -gt 0 ]; then
  echo "fuzz: $total_findings finding(s) in $dir/findings/; reproduce one with $dir/fuzz/fuzz_TARGET FILE"
  exit 1
fi
echo "fuzz: no findings"
