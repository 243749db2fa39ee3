#include "network_kernel.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace morphogen::kernel {

#ifndef KERNEL_GROUP
#define KERNEL_GROUP 6
#endif
namespace {

// Four doubles: one AVX2 register (two SSE2 registers in the baseline clone).
using v4 = double __attribute__((vector_size(32)));
using u4 = std::uint64_t __attribute__((vector_size(32)));
constexpr int lanes = 4;
static_assert(block % lanes == 0);

// Broadcasts are written as scalar * vector (never v4{x,x,x,x}): GCC 12 turns
// the latter, inlined into the AVX2 clone, into two instructions.
[[gnu::always_inline]] inline v4 load(const double* p) {
    v4 v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
}
[[gnu::always_inline]] inline void store(double* p, v4 v) { __builtin_memcpy(p, &v, sizeof v); }

// sigmoid(a) = 1 / (1 + e^x), x = -a, in one division. Cody-Waite reduction
// x = n ln2 + r (|r| <= ln2/2), e^r = (q + p) / (q - p) with Cephes' Pade
// coefficients (p = r P(r^2), q = Q(r^2); ~1 ulp), so
//   sigmoid = (q - p) / ((q - p) + 2^n (q + p)).
// n is rounded with the 1.5*2^52 shifter, whose low mantissa bits then hold n
// as an integer (AVX2 has no double->int64 conversion); 2^n is built in the
// exponent bits. x is clamped to [-700, 700], where 2^n (q + p) stays finite:
// beyond it the sigmoid differs from the exact one by less than 1e-304.
template <class T, class Bits>
[[gnu::always_inline]] inline T sigmoid_generic(T a) {
    constexpr double log2e = 1.4426950408889634074;
    constexpr double ln2_hi = 6.93147180369123816490e-01;
    constexpr double ln2_lo = 1.90821492927058770002e-10;
    constexpr double shifter = 0x1.8p52;
    T x = -a;
    x = x < -700.0 ? T{} - 700.0 : x;
    x = x > 700.0 ? T{} + 700.0 : x;
    const T t = x * log2e + shifter;
    const T n = t - shifter;
    const T r = (x - n * ln2_hi) - n * ln2_lo;
    const T rr = r * r;
    const T p = r * ((1.26177193074810590878e-4 * rr + 3.02994407707441961300e-2) * rr + 9.99999999999999999910e-1);
    const T q = ((3.00198505138664455042e-6 * rr + 2.52448340349684104192e-3) * rr + 2.27265548208155028766e-1) * rr +
                2.00000000000000000009e0;
    const Bits scale = (std::bit_cast<Bits>(t) + 1023) << 52;
    const T numerator = q - p;
    return numerator / (numerator + std::bit_cast<T>(scale) * (q + p));
}

[[gnu::always_inline]] inline v4 sigmoid(v4 a) { return sigmoid_generic<v4, u4>(a); }

// out[j][v] = sigmoid(bias_j + sum_k W[j][k] * in[k][v]) for one block; in and
// out are feature-major (`block` values per feature). Four neurons at a time
// keep 4 x 8 accumulators (8 registers) live while streaming the inputs once.
[[gnu::always_inline]] inline void dense_sigmoid(const Layer& layer, const double* in, double* out) {
    constexpr int B = block, R = block / lanes, G = KERNEL_GROUP;
    const int I = layer.inputs, O = layer.outputs;
    int j = 0;
    for (; j + G <= O; j += G) {
        v4 acc[G][R];
        for (int jj = 0; jj < G; ++jj)
            for (int r = 0; r < R; ++r) acc[jj][r] = v4{} + layer.bias[j + jj];
        const double* w = layer.weights + static_cast<std::ptrdiff_t>(j) * I;
        for (int k = 0; k < I; ++k) {
            v4 x[R];
            for (int r = 0; r < R; ++r) x[r] = load(in + k * B + r * lanes);
            for (int jj = 0; jj < G; ++jj)
                for (int r = 0; r < R; ++r) acc[jj][r] += w[jj * I + k] * x[r];
        }
        for (int jj = 0; jj < G; ++jj)
            for (int r = 0; r < R; ++r) store(out + (j + jj) * B + r * lanes, sigmoid(acc[jj][r]));
    }
    for (; j < O; ++j) {
        v4 acc[R];
        for (int r = 0; r < R; ++r) acc[r] = v4{} + layer.bias[j];
        const double* w = layer.weights + static_cast<std::ptrdiff_t>(j) * I;
        for (int k = 0; k < I; ++k) {
            for (int r = 0; r < R; ++r) acc[r] += w[k] * load(in + k * B + r * lanes);
        }
        for (int r = 0; r < R; ++r) store(out + j * B + r * lanes, sigmoid(acc[r]));
    }
}

// Writes rows[0..3][k] (4 vertices, `features` each) to out[k * stride + v]:
// 4 x 4 tiles transposed in registers, the last features one by one.
[[gnu::always_inline]] inline void transpose_into(const double* const rows[lanes], int features, double* out,
                                                  int stride) {
    int k = 0;
    for (; k + lanes <= features; k += lanes) {
        const v4 r0 = load(rows[0] + k), r1 = load(rows[1] + k), r2 = load(rows[2] + k), r3 = load(rows[3] + k);
        const v4 t0 = __builtin_shufflevector(r0, r1, 0, 4, 2, 6);
        const v4 t1 = __builtin_shufflevector(r0, r1, 1, 5, 3, 7);
        const v4 t2 = __builtin_shufflevector(r2, r3, 0, 4, 2, 6);
        const v4 t3 = __builtin_shufflevector(r2, r3, 1, 5, 3, 7);
        store(out + (k + 0) * stride, __builtin_shufflevector(t0, t2, 0, 1, 4, 5));
        store(out + (k + 1) * stride, __builtin_shufflevector(t1, t3, 0, 1, 4, 5));
        store(out + (k + 2) * stride, __builtin_shufflevector(t0, t2, 2, 3, 6, 7));
        store(out + (k + 3) * stride, __builtin_shufflevector(t1, t3, 2, 3, 6, 7));
    }
    for (; k < features; ++k)
        for (int v = 0; v < lanes; ++v) out[k * stride + v] = rows[v][k];
}

}  // namespace

double sigmoid_vectorizable(double a) { return sigmoid_generic<double, std::uint64_t>(a); }

[[gnu::target_clones("arch=x86-64-v3", "default")]]
void evaluate(const std::vector<Layer>& layers, const double* input, double* output, std::ptrdiff_t count,
              std::vector<double>& scratch) {
    constexpr int B = block;
    int widest = 0;
    for (const Layer& l : layers) widest = std::max({widest, l.inputs, l.outputs});
    scratch.resize(2 * static_cast<std::size_t>(widest) * B);
    double* const buffer[2] = {scratch.data(), scratch.data() + static_cast<std::ptrdiff_t>(widest) * B};
    const int I = layers.front().inputs, O = layers.back().outputs;

    for (std::ptrdiff_t v0 = 0; v0 < count; v0 += B) {
        const int n = static_cast<int>(std::min<std::ptrdiff_t>(B, count - v0));
        // Transpose the block to feature-major; a short last block repeats its last vertex.
        double* in = buffer[0];
        for (int group = 0; group < B; group += lanes) {
            const double* rows[lanes];
            for (int v = 0; v < lanes; ++v) rows[v] = input + (v0 + std::min(group + v, n - 1)) * I;
            transpose_into(rows, I, in + group, B);
        }
        int current = 0;
        for (const Layer& layer : layers) {
            dense_sigmoid(layer, buffer[current], buffer[1 - current]);
            current = 1 - current;
        }
        const double* result = buffer[current];
        for (int v = 0; v < n; ++v)
            for (int j = 0; j < O; ++j) output[(v0 + v) * O + j] = result[j * B + v];
    }
}

}  // namespace morphogen::kernel
