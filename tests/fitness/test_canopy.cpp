// Canopy (docs/algorithm.md §10.1): known answers, the exact-edge rule, and the
// z-buffer agreeing cell for cell with CGAL ray shooting.
#include "fitness/functions/canopy.hpp"
#include "fitness/measures.hpp"
#include "core/growth/genome_grower.hpp"
#include "tests/fitness/mesh_builders.hpp"
#include "tests/support/sanitizers.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <iterator>
#include <sstream>
#include <random>

using namespace morphogen;
using morphogen::test::make_box;
using morphogen::test::make_bumpy;
using morphogen::test::make_square;
using morphogen::test::merge;

namespace {
// "" if equal, else the first cells only one side has (keeps failures readable).
std::string difference(const std::vector<CellIndex>& zbuffer, const std::vector<CellIndex>& rays) {
    std::vector<CellIndex> only_z, only_r;
    std::set_difference(zbuffer.begin(), zbuffer.end(), rays.begin(), rays.end(), std::back_inserter(only_z));
    std::set_difference(rays.begin(), rays.end(), zbuffer.begin(), zbuffer.end(), std::back_inserter(only_r));
    std::ostringstream out;
    for (const auto& [name, cells] : {std::pair{"z-buffer only", &only_z}, std::pair{"rays only", &only_r}}) {
        if (cells->empty()) continue;
        out << cells->size() << " " << name << ":";
        for (std::size_t k = 0; k < std::min<std::size_t>(cells->size(), 8); ++k)
            out << " (" << (*cells)[k].first << "," << (*cells)[k].second << ")";
        out << "; ";
    }
    return out.str();
}
}  // namespace

TEST_CASE("canopy of a 1x1 box with top at z=11 is 1.0", "[fitness][canopy]") {
    const MeshArrays box = make_box({0, 0, 0}, {1, 1, 11});
    CHECK(canopy_area(box.view(), {10.0, 0.1}) == 1.0);
    CHECK(canopy_cells(box.view(), {10.0, 0.1}).size() == 100);
    CHECK(canopy_area(box.view(), {11.0, 0.1}) == 0.0);  // H must exceed the height
    CHECK(canopy_area(box.view(), {10.0, 0.5}) == 1.0);
    CHECK(canopy_area(box.view(), {10.0, 0.25}) == 1.0);
}

TEST_CASE("a cell centre on a triangle's edge counts as inside", "[fitness][canopy]") {
    // The top's sides run exactly through the centres of the outer cells.
    const double c = 0.1;
    const double lo = cell_centre(0, c), hi = cell_centre(9, c);
    const MeshArrays box = make_box({lo, lo, 0}, {hi, hi, 11});
    CHECK(canopy_cells(box.view(), {10.0, c}).size() == 100);
    // A single triangle whose vertices are cell centres: its hypotenuse passes
    // through the centres (i, 4 - i) (cell 0.25: centres are exact in binary).
    const double q = 0.25;
    MeshArrays triangle;
    triangle.positions = {{cell_centre(0, q), cell_centre(0, q), 12}, {cell_centre(4, q), cell_centre(0, q), 12},
                          {cell_centre(0, q), cell_centre(4, q), 12}};
    triangle.faces = {{0, 1, 2}};
    CHECK(canopy_cells(triangle.view(), {10.0, q}).size() == 15);  // 5+4+3+2+1
    CHECK(canopy_cells_by_rays(triangle.view(), {10.0, q}).size() == 15);
    // Orientation of the triangle does not matter.
    triangle.faces = {{0, 2, 1}};
    CHECK(canopy_cells(triangle.view(), {10.0, q}).size() == 15);
}

TEST_CASE("canopy skips vertical triangles and low meshes, and takes the max", "[fitness][canopy]") {
    MeshArrays wall;
    wall.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 20}};
    wall.faces = {{0, 1, 2}};
    CHECK(canopy_area(wall.view(), {10.0, 0.1}) == 0.0);
    CHECK(canopy_area(make_box({0, 0, 0}, {5, 5, 9}).view(), {10.0, 0.1}) == 0.0);
    // A low square under a high one: H is the maximum, so the low one adds nothing.
    const MeshArrays two = merge(make_square(0, 0, 1, 1, 12), make_square(0, 0, 2, 1, 5));
    CHECK(canopy_area(two.view(), {10.0, 0.1}) == 1.0);
    // A sloped triangle counts only where it is above the height.
    MeshArrays slope;
    slope.positions = {{0, 0, 0}, {2, 0, 20}, {2, 1, 20}, {0, 1, 0}};
    slope.faces = {{0, 1, 2}, {0, 2, 3}};
    CHECK(canopy_area(slope.view(), {10.0, 0.1}) == Approx(1.0).margin(1e-12));
    CHECK(canopy_area(MeshArrays{}.view(), {10.0, 0.1}) == 0.0);
}

TEST_CASE("canopy refuses malformed views and absurd grids", "[fitness][canopy]") {
    MeshArrays bad = make_box({0, 0, 0}, {1, 1, 11});
    bad.faces.push_back({0, 1, 99});
    CHECK_THROWS_AS(canopy_area(bad.view(), {}), std::invalid_argument);
    const MeshArrays big = make_box({0, 0, 0}, {1000, 1000, 11});
    CHECK_THROWS_AS(canopy_area(big.view(), {10.0, 1e-3}), std::length_error);
}

TEST_CASE("z-buffer and AABB ray shooting agree cell for cell on bumpy meshes", "[fitness][canopy]") {
    for (unsigned seed = 1; seed <= 24; ++seed) {
        const MeshArrays mesh = make_bumpy(seed, seed % 2 ? 3 : 2);
        const CanopyParams params{seed % 3 ? 10.0 : 7.5, seed % 4 == 0 ? 0.25 : 0.1};
        const auto fast = canopy_cells(mesh.view(), params);
        const auto rays = canopy_cells_by_rays(mesh.view(), params);
        INFO("seed " << seed << ": " << fast.size() << " vs " << rays.size() << " cells");
        CHECK(!fast.empty());
        CHECK(difference(fast, rays) == "");
        CHECK(canopy_area(mesh.view(), params) == Approx(fast.size() * params.cell * params.cell));
    }
}

TEST_CASE("z-buffer and ray shooting agree when vertices sit on cell centres", "[fitness][canopy]") {
    // xy snapped to the centre lattice: many centres fall exactly on edges and vertices.
    for (unsigned seed = 101; seed <= 108; ++seed) {
        MeshArrays mesh = make_bumpy(seed, 2);
        for (Vec3& p : mesh.positions) {
            p.x() = cell_centre(static_cast<std::int64_t>(std::floor(p.x() / 0.1)), 0.1);
            p.y() = cell_centre(static_cast<std::int64_t>(std::floor(p.y() / 0.1)), 0.1);
        }
        const CanopyParams params{10.0, 0.1};
        INFO("seed " << seed);
        CHECK(difference(canopy_cells(mesh.view(), params), canopy_cells_by_rays(mesh.view(), params)) == "");
    }
}

TEST_CASE("z-buffer and ray shooting agree on grown meshes", "[fitness][canopy][grown]") {
    GrowthParams growth;
    growth.steps = 120;
    const GenomeGrower grower(NetworkParams{}, growth);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> uniform(-2.0, 2.0);
    int above = 0;
    const int genomes = morphogen::testing::whole_or_under_sanitizers(12, 4);
    for (int g = 0; g < genomes; ++g) {
        Genome genome{grower.layers(), {}};
        genome.params.resize(parameter_count(genome.layers));
        for (double& p : genome.params) p = uniform(rng);
        GrowthWorkspace workspace;
        const GrowthState state = grower.grow(genome.params, workspace);
        for (double height : {2.0, 5.0, 10.0}) {
            const CanopyParams params{height, 0.1};
            const auto fast = canopy_cells(state.mesh.view(), params);
            above += !fast.empty();
            INFO("genome " << g << ", height " << height);
            CHECK(difference(fast, canopy_cells_by_rays(state.mesh.view(), params)) == "");
        }
    }
    CHECK(above > 0);
}

