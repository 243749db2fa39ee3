#!/usr/bin/env bash
# A curriculum by its starting material: 1,000 random genomes at
# configs/tree.json's settings (gallery), the 30 most slender of those that
# grew to twice the seed's height (height / width), then tree.json's GA from
# them (--from, 6,100 births). Usage: stalk_seeds.sh MORPHOGEN OUT_DIR SEED [THREADS]
set -euo pipefail
exe=$1 out=$2 seed=$3 threads=${4:-2}
mkdir -p "$out"
gal="$out/gallery_s$seed" picked="$out/stalks_s$seed"
start=$(date +%s.%N)
"$exe" gallery --config configs/tree.json --count 1000 --seed $((seed * 100000)) --out "$gal" --format none --threads "$threads" > /dev/null
rm -rf "$picked" && mkdir -p "$picked"
python3 - "$gal/summary.csv" <<'PY' > "$picked/seeds.txt"
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if float(r["height"]) >= 3.56 and float(r["width"]) > 0]
rows.sort(key=lambda r: -float(r["height"]) / float(r["width"]))
for r in rows[:30]:
    print(r["seed"], round(float(r["height"]), 2), round(float(r["width"]), 2))
PY
while read -r s h w; do
  "$exe" grow --config configs/tree.json --random "$s" --save-genome "$picked/stalk_$s.genome.json" -o "$picked/stalk_$s.obj" > /dev/null
done < "$picked/seeds.txt"
"$exe" evolve configs/tree.json --seed "$seed" --threads "$threads" --from "$picked" --out "$out/run_s$seed" --force --no-report
end=$(date +%s.%N)
echo "seed $seed wall $(python3 -c "print(round($end-$start,1))") s"
