#!/usr/bin/env bash
# Sets up, builds, and runs the main job: the paper's canopy experiment
# (configs/canopy.json) into runs/. Extra arguments go to `morphogen evolve`,
# e.g. scripts/run.sh --generations 20 --out runs/try
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh release morphogen  # the executable alone; scripts/test.sh builds the tests
exec build/morphogen evolve configs/canopy.json "$@"
