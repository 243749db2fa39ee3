#!/usr/bin/env bash
# Where one thread's time goes in `morphogen bench` at configs/tree.json's
# settings, by perf's samples (CPU time, so less hurt by a busy machine than
# the bench's wall-clock phases): the collision work's share (the contact
# guard, its grid, fan certificates, distances, the flip guard's exact tests)
# against everything else but the bench's own FMA peak probe.
# Usage: profile_share.sh MORPHOGEN [REPEAT]
set -euo pipefail
morphogen=${1:?usage: profile_share.sh MORPHOGEN [REPEAT]}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
root=$(cd "$(dirname "$0")/../../.." && pwd)
grep -v '"\$schema"' "$root/configs/tree.json" > "$work/tree.json"
perf record -q -o "$work/perf.data" "$morphogen" bench --config "$work/tree.json" --json --threads 1 \
  --repeat "${2:-3}" > /dev/null 2>&1
perf report -i "$work/perf.data" --no-children --percent-limit 0.2 --stdio 2>/dev/null | grep "%" > "$work/report.txt"
head -12 "$work/report.txt"
python3 - "$work/report.txt" <<'PY'
import re, sys
collide = rest = 0.0
for line in open(sys.argv[1]):
    m = re.match(r"\s+([\d.]+)%\s+\S+\s+\S+\s+\[.\]\s+(.*)", line)
    if not m:
        continue
    share, symbol = float(m.group(1)), m.group(2)
    if re.search(r"fma_rounds|scalbn|kallsyms", symbol):
        continue
    if re.search(r"Contact|fan_certified|certified_along|distance_to_triangle|beside_plane|faces_intersect|"
                 r"IndexedTriangle|face_box|outward|triangle_degenerate", symbol):
        collide += share
    else:
        rest += share
print(f"collision {collide:.1f} %, the rest {rest:.1f} %, collision / (collision + rest) = {collide / (collide + rest):.3f}")
PY
