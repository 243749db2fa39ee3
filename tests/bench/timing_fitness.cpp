// Timings of the canopy and of every descriptor measure on a bumpy blob and on
// grown meshes (docs/fitness.md). Not part of the suite (ctest label "bench"):
// build/tests/bench_timings '[fitness]'
#include "core/growth/genome_grower.hpp"
#include "fitness/functions/canopy.hpp"
#include "fitness/descriptors.hpp"
#include "fitness/measures.hpp"
#include "tests/fitness/mesh_builders.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <random>
#include <utility>

using namespace morphogen;
using morphogen::test::make_bumpy;

TEST_CASE("canopy evaluation time", "[bench][fitness]") {
    auto time_ms = [](MeshView mesh, int runs) {
        const auto start = std::chrono::steady_clock::now();
        double sum = 0;
        for (int r = 0; r < runs; ++r) sum += canopy_area(mesh, {10.0, 0.1});
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        return std::pair{ms / runs, sum / runs};
    };
    const MeshArrays blob = make_bumpy(5, 4);  // 2562 vertices, 5120 faces
    const auto [blob_ms, blob_area] = time_ms(blob.view(), 200);
    WARN("bumpy blob, " << blob.positions.size() << " vertices: " << blob_ms << " ms per canopy (area " << blob_area
                        << ")");
    // Grown meshes (default growth: 200 steps, up to 4000 vertices).
    const GenomeGrower grower(NetworkParams{}, GrowthParams{});
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> uniform(-2.0, 2.0);
    for (int g = 0; g < 4; ++g) {
        Genome genome{grower.layers(), {}};
        genome.params.resize(parameter_count(genome.layers));
        for (double& p : genome.params) p = uniform(rng);
        GrowthWorkspace workspace;
        const auto start = std::chrono::steady_clock::now();
        const GrowthState state = grower.grow(genome.params, workspace);
        const double grow_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const auto [ms, area] = time_ms(state.mesh.view(), 100);
        WARN("grown, " << state.mesh.num_vertices() << " vertices, height " << mesh_height(state.mesh.view())
                       << ": " << ms << " ms per canopy (area " << area << "); growth took " << grow_ms << " ms");
    }
}

TEST_CASE("descriptor measure times", "[bench][fitness]") {
    const MeshArrays blob = make_bumpy(5, 4);  // 2562 vertices, 5120 faces
    for (const DescriptorMeasure& m : descriptor_measures()) {
        const int runs = 50;
        const auto start = std::chrono::steady_clock::now();
        double sum = 0;
        for (int r = 0; r < runs; ++r) sum += m.measure(blob.view(), {10.0, 0.1});
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        WARN(m.name << ": " << ms / runs << " ms (value " << sum / runs << ")");
    }
}
