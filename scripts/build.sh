#!/usr/bin/env bash
# Configures and builds morphogen. Usage: scripts/build.sh [release|sanitize] [TARGET...]
#   release  (default) optimised build in build/
#   sanitize ASan + UBSan build in build-sanitize/
#   TARGET   only these CMake targets (default: everything, tests included),
#            e.g. scripts/build.sh release morphogen
set -euo pipefail
cd "$(dirname "$0")/.."
kind=${1:-release}
shift || true
targets=()
for t in "$@"; do targets+=(--target "$t"); done
case "$kind" in
  release)  dir=build;          flags=(-DCMAKE_BUILD_TYPE=Release) ;;
  # -g1: line tables, enough for the sanitizers' stack traces, at a third
  # less compile time than full debug information. -O2, not -O1: at -O1 some
  # results differ in their last bit from the optimised build's, and the
  # release fixtures (tests/app/test_release_fixtures.cpp) compare bytes.
  sanitize) dir=build-sanitize; flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG"
                                       -DMORPHOGEN_SANITIZE=ON) ;;
  *) echo "usage: $0 [release|sanitize]" >&2; exit 2 ;;
esac
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S . -B "$dir" "${generator[@]}" "${flags[@]}" >/dev/null
cmake --build "$dir" --parallel "$(nproc)" "${targets[@]}"
