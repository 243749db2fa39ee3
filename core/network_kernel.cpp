#include "network_kernel.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace morphogen::kernel {

namespace {

// Four doubles: one AVX2 register (two SSE2 registers in the baseline clone).
using v4 = double __attribute__((vector_size(32)));
using u4 = std::uint64_t __attribute__((vector_size(32)));
constexpr int lanes = 4;
static_assert(block % lanes == 0);

[[gnu::always_inline]] inline v4 splat(double x) { return v4{x, x, x, x}; }
[[gnu::always_inline]] inline v4 load(const double* p) {
    v4 v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
}
[[gnu::always_inline]] inline void store(double* p, v4 v) { __builtin_memcpy(p, &v, sizeof v); }

// Cody-Waite reduction x = n ln2 + r, |r| <= ln2/2, then a degree-13 Taylor
// polynomial (truncation < 2e-17 relative) and 2^n built in the exponent bits.
// The rounding uses the 1.5*2^52 shifter, whose low mantissa bits then hold n
// as an integer: no double->int64 conversion, which AVX2 lacks.
template <class T, class Bits>
[[gnu::always_inline]] inline T exp_generic(T x) {
    constexpr double log2e = 1.4426950408889634074;
    constexpr double ln2_hi = 6.93147180369123816490e-01;
    constexpr double ln2_lo = 1.90821492927058770002e-10;
    constexpr double shifter = 0x1.8p52;
    x = x < -708.0 ? T{} - 708.0 : x;
    x = x > 709.0 ? T{} + 709.0 : x;
    const T t = x * log2e + shifter;
    const T n = t - shifter;
    const T r = (x - n * ln2_hi) - n * ln2_lo;
    T p = T{} + 1.0 / 6227020800.0;  // 1/13!
    p = p * r + 1.0 / 479001600.0;
    p = p * r + 1.0 / 39916800.0;
    p = p * r + 1.0 / 3628800.0;
    p = p * r + 1.0 / 362880.0;
    p = p * r + 1.0 / 40320.0;
    p = p * r + 1.0 / 5040.0;
    p = p * r + 1.0 / 720.0;
    p = p * r + 1.0 / 120.0;
    p = p * r + 1.0 / 24.0;
    p = p * r + 1.0 / 6.0;
    p = p * r + 0.5;
    p = p * r + 1.0;
    p = p * r + 1.0;
    const Bits scale = (std::bit_cast<Bits>(t) + 1023) << 52;
    return p * std::bit_cast<T>(scale);
}

[[gnu::always_inline]] inline v4 sigmoid(v4 a) { return 1.0 / (1.0 + exp_generic<v4, u4>(-a)); }

// out[j][v] = sigmoid(bias_j + sum_k W[j][k] * in[k][v]) for one block; in and
// out are feature-major (`block` values per feature). Four neurons at a time
// keep 4 x 8 accumulators (8 registers) live while streaming the inputs once.
[[gnu::always_inline]] inline void dense_sigmoid(const Layer& layer, const double* in, double* out) {
    constexpr int B = block, R = block / lanes;
    const int I = layer.inputs, O = layer.outputs;
    int j = 0;
    for (; j + 4 <= O; j += 4) {
        v4 acc[4][R];
        for (int jj = 0; jj < 4; ++jj)
            for (int r = 0; r < R; ++r) acc[jj][r] = splat(layer.bias[j + jj]);
        const double* w = layer.weights + static_cast<std::ptrdiff_t>(j) * I;
        for (int k = 0; k < I; ++k) {
            v4 x[R];
            for (int r = 0; r < R; ++r) x[r] = load(in + k * B + r * lanes);
            for (int jj = 0; jj < 4; ++jj) {
                const v4 wk = splat(w[jj * I + k]);
                for (int r = 0; r < R; ++r) acc[jj][r] += wk * x[r];
            }
        }
        for (int jj = 0; jj < 4; ++jj)
            for (int r = 0; r < R; ++r) store(out + (j + jj) * B + r * lanes, sigmoid(acc[jj][r]));
    }
    for (; j < O; ++j) {
        v4 acc[R];
        for (int r = 0; r < R; ++r) acc[r] = splat(layer.bias[j]);
        const double* w = layer.weights + static_cast<std::ptrdiff_t>(j) * I;
        for (int k = 0; k < I; ++k) {
            const v4 wk = splat(w[k]);
            for (int r = 0; r < R; ++r) acc[r] += wk * load(in + k * B + r * lanes);
        }
        for (int r = 0; r < R; ++r) store(out + j * B + r * lanes, sigmoid(acc[r]));
    }
}

}  // namespace

double exp_vectorizable(double x) { return exp_generic<double, std::uint64_t>(x); }

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
        for (int v = 0; v < B; ++v) {
            const double* src = input + (v0 + std::min(v, n - 1)) * I;
            for (int k = 0; k < I; ++k) in[k * B + v] = src[k];
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
