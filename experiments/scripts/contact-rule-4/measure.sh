#!/usr/bin/env bash
# The whole of experiments/2026-11-27-contact-rule-4.md's measurement, in
# order, with the machine's load before each part: same decisions (lineage.csv
# on GENOMES random genomes in three settings), the same bytes for "allow",
# "prevent" and "touch", the bench side by side (PAIRS interleaved pairs at
# configs/tree.json, then genome by genome), and CPU-sample shares.
# Usage: measure.sh OLD_MORPHOGEN NEW_MORPHOGEN [GENOMES [PAIRS]]
set -euo pipefail
old=${1:?usage: measure.sh OLD NEW [GENOMES [PAIRS]]}
new=${2:?usage: measure.sh OLD NEW [GENOMES [PAIRS]]}
genomes=${3:-300}
pairs=${4:-5}
scripts=$(cd "$(dirname "$0")/.." && pwd)
load() { echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"; }
load; "$scripts/contact-rule-3/same_decisions.sh" "$old" "$new" "$genomes"
load; "$scripts/touch-rewind/same_bytes.sh" "$old" "$new" 1 2 3
load; python3 "$scripts/contact-rule-2/side_by_side.py" "$old" "$new" "$pairs" tree
for binary in "$old" "$new" "$old" "$new"; do
  load; python3 "$scripts/contact-rule-4/profile_share.py" "$binary"
done
load
