#!/usr/bin/env bash
# Builds the LOD study's driver against the release build's libraries
# (scripts/build.sh release morphogen first). Prints the driver's path.
set -euo pipefail
root="$(cd "$(dirname "$0")/../../.." && pwd)"
out="${1:-$root/build/lod_bounds}"
b="$root/build"
ccache g++ -O3 -DNDEBUG -std=c++20 -fno-math-errno -frounding-math -DCGAL_USE_GMPXX=1 -DEIGEN_DONT_PARALLELIZE \
    -Wno-maybe-uninitialized -I"$root" -I/usr/include/eigen3 \
    -c "$root/experiments/scripts/lod-bounds/lod_bounds.cpp" -o "$out.o"
g++ "$out.o" \
    "$b/engine/libmorphogen_engine.a" "$b/growth/libmorphogen_growth.a" "$b/evolution/libmorphogen_evolution.a" \
    "$b/io/libmorphogen_io.a" "$b/mesh/libmorphogen_mesh.a" "$b/base/libmorphogen_base.a" \
    -ltinygltf -lgmpxx -lmpfr -lgmp -lpthread -o "$out"
echo "$out"
