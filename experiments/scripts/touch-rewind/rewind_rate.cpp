// experiments/2026-11-27-touch-rewind.md: how often "touch"'s fail-safe
// rewinds a random genome, and by how many steps.
// Grows genomes [1, N] of tests/support's random_test_genome (init range 2,
// as the collision tests) with growth.collisions "touch" through
// GenomeGrower (the fail-safe included) and prints one line per rewound
// genome (seed, k, steps) and a summary row: rewound count and rate, the
// steps lost (median, max), the mean final vertices, the seconds.
// Build and run: experiments/scripts/touch-rewind/rewind_rate.sh
#include "core/growth/genome_grower.hpp"
#include "tests/support/test_genomes.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace morphogen;

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: rewind_rate paper|branching default|tree|tree.json N\n");
        return 2;
    }
    const std::string mode = argv[1], size = argv[2];
    const int n = std::atoi(argv[3]);
    GrowthParams params;
    params.collisions = Collisions::touch;
    if (mode == "branching") params.mode = GrowthMode::branching;
    if (size == "tree" || size == "tree.json") {  // configs/tree.json's sizes
        params.steps = 150;
        params.max_vertices = 1000;
    }
    if (size == "tree.json") {  // and its signals (branching mode only)
        params.exposure = true;
        params.signal_diffusion = 8;
    }
    const GenomeGrower grower(NetworkParams{}, params);
    GrowthWorkspace workspace;
    std::vector<int> lost;
    double vertices = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int g = 1; g <= n; ++g) {
        const GrowthState state = grower.grow(Network(testing::random_test_genome(grower.layers(), g)), workspace);
        vertices += state.mesh.num_vertices();
        if (state.steps_done < params.steps) {
            lost.push_back(params.steps - state.steps_done);
            std::printf("genome %d: k = %d of %d\n", g, state.steps_done, params.steps);
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::sort(lost.begin(), lost.end());
    const int median = lost.empty() ? 0 : lost[lost.size() / 2], most = lost.empty() ? 0 : lost.back();
    std::printf("| %s | %s | %zu of %d | %.1f %% | %d | %d | %.0f | %.0f |\n", mode.c_str(), size.c_str(), lost.size(), n,
                100.0 * static_cast<double>(lost.size()) / n, median, most, vertices / n, seconds);
    return 0;
}
