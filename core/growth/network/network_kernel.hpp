#pragma once
// The fused network kernel: evaluates the whole network for a block of
// vertices at a time, keeping each layer's activations in a small buffer
// (product, bias and sigmoid in one pass), vectorised across the vertices of
// the block. Compiled twice (x86-64-v3 = AVX2+FMA, and baseline x86-64) and
// picked at run time, so the default build runs on any x86-64 CPU.
//
// Results agree with the paper's pseudocode to ~1e-15 relative; they are
// identical for any thread count on one machine, but a CPU with FMA rounds
// differently from one without (bits may differ between machines).
#include <cstddef>
#include <vector>

namespace morphogen::kernel {

// Vertices per block: 8 doubles = two AVX2 registers per neuron.
inline constexpr int block = 8;

// What the layers' weights and biases are multiplied by: the kernel computes
// b = -a log2(e) instead of the activation a, and sigmoid(a) = 1 / (1 + 2^b)
// needs no multiplication to reduce its argument.
inline constexpr double weight_scale = -1.4426950408889634074;  // -log2(e)

struct Layer {
    int inputs = 0, outputs = 0;
    const double* weights = nullptr;  // outputs x inputs, row-major (neuron j's row), times weight_scale
    const double* bias = nullptr;     // outputs: (-threshold - 0.5 * sum of weights) times weight_scale
};

// Evaluates `count` vertices. `input` holds each vertex's inputs contiguously
// (layers.front().inputs per vertex, vertex after vertex) and `output` gets
// each vertex's outputs the same way. `scratch` is resized as needed.
void evaluate(const std::vector<Layer>& layers, const double* input, double* output, std::ptrdiff_t count,
              std::vector<double>& scratch);

// Computes the inputs of vertices [first, first + count), count <= block,
// into `rows` (vertex after vertex) when the kernel reaches them.
struct InputSource {
    void (*fill)(const void* context, std::ptrdiff_t first, int count, double* rows) = nullptr;
    const void* context = nullptr;
};

// The same, with the inputs made block by block: they stay in the L1 cache
// instead of streaming a whole-mesh input array (3N doubles per vertex)
// through memory.
void evaluate(const std::vector<Layer>& layers, const InputSource& source, double* output, std::ptrdiff_t count,
              std::vector<double>& scratch);

// The kernel's sigmoid 1 / (1 + e^-a) for one value (no libm call, so loops
// over it vectorise); exposed for tests.
double sigmoid_vectorizable(double a);

}  // namespace morphogen::kernel
