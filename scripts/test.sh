#!/usr/bin/env bash
# Sets up, builds and runs every test: the optimised build, then the same
# tests under AddressSanitizer + UndefinedBehaviorSanitizer. Tests labelled
# "slow" and the timings (label "bench") are left out: ctest --test-dir build
# -L slow (or -L bench) runs them. The page
# tests (label "browser": JavaScript in Chromium) run once, on the optimised
# build; the server and the report they drive run under the sanitizers in
# test_breed and test_app. So do the tests labelled "optimised" (the Blender
# import, the scaling script's timings): tests/CMakeLists.txt says why. Tests whose point is scale run a part of their
# work under the sanitizers (tests/support/sanitizers.hpp); the optimised
# build above runs them whole.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh release
ctest --test-dir build --output-on-failure --parallel "$(nproc)" -LE "slow|bench"
scripts/build.sh sanitize
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)" -LE "slow|bench|browser|optimised"
