// Side-by-side timing of two builds of core/growth/network/network_kernel.cpp, for deciding
// kernel changes on a shared, noisy machine: both run in one process,
// alternating in short rounds, and the median of the per-round speed ratios
// is reported. An A/A run gives 1.00 to 1.05 (the two copies' placement in
// memory), so run both orders. Built and run by kernel_ab.sh, which compiles
// each kernel with its namespace renamed.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <vector>

// The kernel interface (core/growth/network/network_kernel.hpp), once per renamed namespace.
#define DECLARE_KERNEL(NS)                                                                                   \
    namespace morphogen::NS {                                                                                \
    struct Layer {                                                                                           \
        int inputs = 0, outputs = 0;                                                                         \
        const double* weights = nullptr;                                                                     \
        const double* bias = nullptr;                                                                        \
    };                                                                                                       \
    void evaluate(const std::vector<Layer>&, const double*, double*, std::ptrdiff_t, std::vector<double>&); \
    }
DECLARE_KERNEL(kernel_a)
DECLARE_KERNEL(kernel_b)

namespace {

double cpu_seconds() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    using namespace morphogen;
    const int rounds = argc > 1 ? std::atoi(argv[1]) : 300;
    const int sizes[3] = {45, 30, 15};  // the default network
    const int vertices = 2000, calls = 3;
    std::mt19937_64 random(1);
    std::uniform_real_distribution<double> weight(-2.0, 2.0), input(0.0, 1.0);
    std::vector<double> weights[2], biases[2];
    std::vector<kernel_a::Layer> layers_a;
    std::vector<kernel_b::Layer> layers_b;
    for (int l = 0; l < 2; ++l) {
        weights[l].resize(static_cast<std::size_t>(sizes[l]) * sizes[l + 1]);
        biases[l].resize(sizes[l + 1]);
        for (double& w : weights[l]) w = weight(random);
        for (double& b : biases[l]) b = 3.0 * weight(random);
        layers_a.push_back({sizes[l], sizes[l + 1], weights[l].data(), biases[l].data()});
        layers_b.push_back({sizes[l], sizes[l + 1], weights[l].data(), biases[l].data()});
    }
    std::vector<double> in(static_cast<std::size_t>(45) * vertices), out_a(15 * vertices), out_b(15 * vertices);
    std::vector<double> scratch_a, scratch_b;
    for (double& x : in) x = input(random);

    kernel_a::evaluate(layers_a, in.data(), out_a.data(), vertices, scratch_a);
    kernel_b::evaluate(layers_b, in.data(), out_b.data(), vertices, scratch_b);
    double difference = 0.0;
    for (std::size_t i = 0; i < out_a.size(); ++i) difference = std::max(difference, std::abs(out_a[i] - out_b[i]));

    std::vector<double> time_a, time_b, ratio;
    for (int r = 0; r < rounds; ++r) {
        const double t0 = cpu_seconds();
        for (int c = 0; c < calls; ++c) kernel_a::evaluate(layers_a, in.data(), out_a.data(), vertices, scratch_a);
        const double t1 = cpu_seconds();
        for (int c = 0; c < calls; ++c) kernel_b::evaluate(layers_b, in.data(), out_b.data(), vertices, scratch_b);
        const double t2 = cpu_seconds();
        time_a.push_back(t1 - t0);
        time_b.push_back(t2 - t1);
        ratio.push_back((t1 - t0) / (t2 - t1));
    }
    const double evaluations = static_cast<double>(calls) * vertices;
    std::printf("A: best %.2f, median %.2f M vertices/s | B: best %.2f, median %.2f M vertices/s\n",
                evaluations / *std::min_element(time_a.begin(), time_a.end()) * 1e-6,
                evaluations / median(time_a) * 1e-6,
                evaluations / *std::min_element(time_b.begin(), time_b.end()) * 1e-6,
                evaluations / median(time_b) * 1e-6);
    std::printf("B / A speed, median of %d rounds: %.3f   (largest output difference %.1e)\n", rounds, median(ratio),
                difference);
}
