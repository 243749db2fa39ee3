#!/usr/bin/env bash
# What the signals cost: morphogen bench (1 thread) on the same 32 random
# genomes at tree.json's growth settings without and with them (VARIANTS:
# default "allow signals"; also "exposure", "diffusion": one signal each), alternated
# `PAIRS` times (default 3) so the machine's load hits both alike. Prints per
# run: think and gather seconds per million vertex-steps and their share of the wall time.
set -euo pipefail
cd "$(dirname "$0")/../../.."
HERE=experiments/scripts/tip-signals
for pair in $(seq "${PAIRS:-3}"); do
    for variant in ${VARIANTS:-allow signals}; do
        build/morphogen bench --config "$HERE/tree_$variant.json" --genomes 32 --repeat 5 --threads 1 --json |
            python3 -c "
import json, sys
r = json.load(sys.stdin)
per = 1e6 / r['vertex_steps']
print('$variant', 'vertex_steps', r['vertex_steps'], 'wall_s', round(r['wall_s_1t'], 4),
      'think_s/Mvs', round(r['think_s'] * per, 3), 'gather_s/Mvs', round(r['gather_s'] * per, 3),
      'wall_s/Mvs', round(r['wall_s_1t'] * per, 3),
      'think_frac', round(r['think_s'] / r['wall_s_1t'], 3), 'gather_frac', round(r['gather_s'] / r['wall_s_1t'], 3))"
    done
done
