#!/usr/bin/env bash
# Compares two versions of the network kernel side by side (see kernel_ab.cpp).
# usage: experiments/scripts/kernel_ab/kernel_ab.sh OLD_KERNEL.cpp NEW_KERNEL.cpp [ROUNDS]
# e.g.   git show HEAD:core/growth/network/network_kernel.cpp > /tmp/old.cpp
#        experiments/scripts/kernel_ab/kernel_ab.sh /tmp/old.cpp core/growth/network/network_kernel.cpp
# FLAGS_A / FLAGS_B add compiler flags to one side (e.g. FLAGS_B=-falign-loops=64).
# An A/A run (the same file twice) gives 1.00 to 1.05 depending on where the
# two copies land in memory: run both orders and take the geometric mean.
set -euo pipefail
if [[ $# -lt 2 ]]; then
    echo "usage: $0 OLD_KERNEL.cpp NEW_KERNEL.cpp [ROUNDS]" >&2
    exit 2
fi
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# The flags core/growth/CMakeLists.txt gives the kernel file, plus the project's.
flags=(-O3 -DNDEBUG -std=c++20 -fno-math-errno -ffp-contract=fast -ffinite-math-only -fno-signed-zeros
       -Wno-psabi -I"$root")
g++ "${flags[@]}" ${FLAGS_A:-} -Dkernel=kernel_a -c "$1" -o "$work/a.o"
g++ "${flags[@]}" ${FLAGS_B:-} -Dkernel=kernel_b -c "$2" -o "$work/b.o"
g++ -O2 -std=c++20 "$here/kernel_ab.cpp" "$work/a.o" "$work/b.o" -o "$work/kernel_ab"
"$work/kernel_ab" "${3:-300}"
