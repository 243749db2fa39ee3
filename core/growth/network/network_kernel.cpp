#include "core/growth/network/network_kernel.hpp"

#include "core/growth/network/vector4.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace morphogen::kernel {

namespace {

static_assert(block % lanes == 0);

// Broadcasts are written as scalar * vector (never v4{x,x,x,x}): GCC 12 turns
// the latter, inlined into the AVX2 clone, into two instructions.

// sigmoid(a) = 1 / (1 + e^-a) = 1 / (1 + 2^b) in one division, from
// b = -a log2(e), which the layers compute directly (their weights and biases
// come scaled by -log2(e)): so the reduction needs no multiplication.
// b = n + y with n = round(b) and y = b - n exact, |y| <= 1/2; then
// 2^y = (q + p) / (q - p), p = y P(y^2), q = Q(y^2), a [5/5] rational fitted
// for least maximum error (Remez; 8e-19 relative, far below a double's
// rounding: see docs/performance.md), and
//   sigmoid = (q - p) / ((q - p) + 2^n (q + p)).
// n is rounded with the 1.5*2^52 + 1023 shifter, whose low mantissa bits then
// hold n + 1023 as an integer (AVX2 has no double->int64 conversion): shifted
// left by 52 they are the exponent bits of 2^n.
// b is clamped to [-1010, 1010] (|a| <= 700), where 2^n (q + p) stays
// finite: beyond it the sigmoid differs from the exact one by less than
// 1e-304. The clamps compile to vmaxpd/vminpd because this file is built with
// -ffinite-math-only (nothing here is NaN or infinite: the genome and the
// inputs are checked finite).
template <class T, class Bits>
[[gnu::always_inline]] inline T sigmoid_scaled_generic(T b) {
    constexpr double shifter = 0x1.8p52 + 1023;
    b = b > -1010.0 ? b : T{} - 1010.0;
    b = b < 1010.0 ? b : T{} + 1010.0;
    const T t = b + shifter;
    const T n = t - shifter;
    const T y = b - n;
    const T x = y * y;
    const T p = y * ((0.0230933634307872029594 * x + 20.2020597632429332954) * x + 1513.906112640028138708);
    const T q = (x + 233.1841151404872565892) * x + 4368.209682154514190153;
    const Bits scale = std::bit_cast<Bits>(t) << 52;
    const T numerator = q - p;
    return numerator / (numerator + std::bit_cast<T>(scale) * (q + p));
}

[[gnu::always_inline]] inline v4 sigmoid_scaled(v4 b) { return sigmoid_scaled_generic<v4, u4>(b); }

// Pre-activations of neurons j0..j0+G-1 for one block:
// out[j][v] = bias_j + sum_k W[j][k] * in[k][v], in and out feature-major
// (`block` values per feature). The G x (block / lanes) accumulators stay in
// registers while the inputs stream once.
// GCC 12 warns that acc "may be used uninitialized" where it is only being
// set (a false positive of its vector lowering); the pragma is scoped to this.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
template <int G>
[[gnu::always_inline]] inline void dense_group(const Layer& layer, int j0, const double* in, double* out) {
    constexpr int B = block, R = block / lanes;
    const int I = layer.inputs;
    v4 acc[G][R];
    for (int jj = 0; jj < G; ++jj)
        for (int r = 0; r < R; ++r) acc[jj][r] = v4{} + layer.bias[j0 + jj];
    const double* w = layer.weights + static_cast<std::ptrdiff_t>(j0) * I;
    // Unrolled by 3 (the default layers have 45 and 30 inputs): the loop's
    // own two instructions per 12 FMAs measured 4-5 % of the kernel
    // (kernel_ab, both orders; unrolling by 5 gains nothing more).
#pragma GCC unroll 3
    for (int k = 0; k < I; ++k) {
        v4 x[R];
        for (int r = 0; r < R; ++r) x[r] = load(in + k * B + r * lanes);
        for (int jj = 0; jj < G; ++jj)
            for (int r = 0; r < R; ++r) acc[jj][r] += w[jj * I + k] * x[r];
    }
    for (int jj = 0; jj < G; ++jj)
        for (int r = 0; r < R; ++r) store(out + (j0 + jj) * B + r * lanes, acc[jj][r]);
}
#pragma GCC diagnostic pop

// One layer for one block: the products in groups of at most 6 neurons, as
// even as possible (15 = 5+5+5, 30 = 6+6+6+6+6: a lone remainder neuron would leave
// the FMA units waiting on latency), then the sigmoid over the whole layer in
// one loop.
[[gnu::always_inline]] inline void dense_sigmoid(const Layer& layer, const double* in, double* out) {
    constexpr int max_group = 6;
    const int O = layer.outputs;
    const int groups = (O + max_group - 1) / max_group;
    const int base = O / groups, extra = O % groups;
    int j = 0;
    for (int g = 0; g < groups; ++g) {
        const int size = base + (g < extra ? 1 : 0);
        switch (size) {
            case 6: dense_group<6>(layer, j, in, out); break;
            case 5: dense_group<5>(layer, j, in, out); break;
            case 4: dense_group<4>(layer, j, in, out); break;
            case 3: dense_group<3>(layer, j, in, out); break;
            case 2: dense_group<2>(layer, j, in, out); break;
            default: dense_group<1>(layer, j, in, out); break;
        }
        j += size;
    }
    for (int i = 0; i < O * block; i += lanes) store(out + i, sigmoid_scaled(load(out + i)));
}

// 4 x 4 transpose in registers: out[i][j] = in[j][i].
[[gnu::always_inline]] inline void transpose4(const v4 in[lanes], v4 out[lanes]) {
    const v4 t0 = __builtin_shufflevector(in[0], in[1], 0, 4, 2, 6);
    const v4 t1 = __builtin_shufflevector(in[0], in[1], 1, 5, 3, 7);
    const v4 t2 = __builtin_shufflevector(in[2], in[3], 0, 4, 2, 6);
    const v4 t3 = __builtin_shufflevector(in[2], in[3], 1, 5, 3, 7);
    out[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
    out[1] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    out[2] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
    out[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}

// Vertex rows -> feature-major: rows[v][k] (4 vertices, `features` each) to
// block[k * block + v].
[[gnu::always_inline]] inline void rows_to_block(const double* const rows[lanes], int features, double* out) {
    int k = 0;
    for (; k + lanes <= features; k += lanes) {
        v4 in[lanes], t[lanes];
        for (int v = 0; v < lanes; ++v) in[v] = load(rows[v] + k);
        transpose4(in, t);
        for (int i = 0; i < lanes; ++i) store(out + (k + i) * block, t[i]);
    }
    for (; k < features; ++k)
        for (int v = 0; v < lanes; ++v) out[k * block + v] = rows[v][k];
}

// Feature-major -> vertex rows: block[k * block + v] to rows[v][k].
[[gnu::always_inline]] inline void block_to_rows(const double* in, int features, double* const rows[lanes]) {
    int k = 0;
    for (; k + lanes <= features; k += lanes) {
        v4 t[lanes], out[lanes];
        for (int i = 0; i < lanes; ++i) t[i] = load(in + (k + i) * block);
        transpose4(t, out);
        for (int v = 0; v < lanes; ++v) store(rows[v] + k, out[v]);
    }
    for (; k < features; ++k)
        for (int v = 0; v < lanes; ++v) rows[v][k] = in[k * block + v];
}

// The whole network over `count` vertices, block by block; rows_of(v0, n)
// returns the inputs of vertices v0..v0+n-1, vertex after vertex.
template <class RowsOf>
[[gnu::always_inline]] inline void evaluate_blocks(const std::vector<Layer>& layers, RowsOf rows_of, double* output,
                                                   std::ptrdiff_t count, std::vector<double>& scratch) {
    constexpr int B = block;
    int widest = 0;
    for (const Layer& l : layers) widest = std::max({widest, l.inputs, l.outputs});
    const int I = layers.front().inputs, O = layers.back().outputs;
    // Two activation buffers, then room for one block of input rows.
    // Aligned to a cache line: malloc gives 16 bytes, and a 32-byte load
    // that straddles two lines costs two loads.
    constexpr std::size_t line = 64 / sizeof(double);
    scratch.resize(2 * static_cast<std::size_t>(widest) * B + static_cast<std::size_t>(I) * B + line);
    const std::uintptr_t address = reinterpret_cast<std::uintptr_t>(scratch.data());
    double* const base = scratch.data() + (-(address / sizeof(double)) & (line - 1));
    double* const buffer[2] = {base, base + static_cast<std::ptrdiff_t>(widest) * B};
    double* const row_space = base + 2 * static_cast<std::ptrdiff_t>(widest) * B;

    for (std::ptrdiff_t v0 = 0; v0 < count; v0 += B) {
        const int n = static_cast<int>(std::min<std::ptrdiff_t>(B, count - v0));
        const double* input = rows_of(v0, n, row_space);
        // Transpose the block to feature-major; a short last block repeats its last vertex.
        double* in = buffer[0];
        for (int group = 0; group < B; group += lanes) {
            const double* rows[lanes];
            for (int v = 0; v < lanes; ++v) rows[v] = input + std::min(group + v, n - 1) * I;
            rows_to_block(rows, I, in + group);
        }
        int current = 0;
        for (const Layer& layer : layers) {
            dense_sigmoid(layer, buffer[current], buffer[1 - current]);
            current = 1 - current;
        }
        const double* result = buffer[current];
        if (n == B) {
            for (int group = 0; group < B; group += lanes) {
                double* rows[lanes];
                for (int v = 0; v < lanes; ++v) rows[v] = output + (v0 + group + v) * O;
                block_to_rows(result + group, O, rows);
            }
        } else {
            for (int v = 0; v < n; ++v)
                for (int j = 0; j < O; ++j) output[(v0 + v) * O + j] = result[j * B + v];
        }
    }
}

}  // namespace

double sigmoid_vectorizable(double a) { return sigmoid_scaled_generic<double, std::uint64_t>(a * weight_scale); }

[[gnu::target_clones("arch=x86-64-v3", "default")]]
void evaluate(const std::vector<Layer>& layers, const double* input, double* output, std::ptrdiff_t count,
              std::vector<double>& scratch) {
    const std::ptrdiff_t I = layers.front().inputs;
    evaluate_blocks(
        layers, [&](std::ptrdiff_t v0, int, double*) { return input + v0 * I; }, output, count, scratch);
}

[[gnu::target_clones("arch=x86-64-v3", "default")]]
void evaluate(const std::vector<Layer>& layers, const InputSource& source, double* output, std::ptrdiff_t count,
              std::vector<double>& scratch) {
    evaluate_blocks(
        layers,
        [&](std::ptrdiff_t v0, int n, double* rows) {
            source.fill(source.context, v0, n, rows);
            return static_cast<const double*>(rows);
        },
        output, count, scratch);
}

}  // namespace morphogen::kernel
