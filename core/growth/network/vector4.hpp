#pragma once
// Four doubles as one GCC vector: one AVX2 register in the x86-64-v3 clones
// of the kernels, two SSE2 registers in their baseline clones. Shared by the
// network and gather kernels; include only from files built with -Wno-psabi
// (32-byte vector arguments never cross those files' boundaries).
#include <cstdint>

namespace morphogen::kernel {

using v4 = double __attribute__((vector_size(32)));
using u4 = std::uint64_t __attribute__((vector_size(32)));
inline constexpr int lanes = 4;

// Unaligned load and store of four doubles.
[[gnu::always_inline]] inline v4 load(const double* p) {
    v4 v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
}
[[gnu::always_inline]] inline void store(double* p, v4 v) { __builtin_memcpy(p, &v, sizeof v); }

}  // namespace morphogen::kernel
