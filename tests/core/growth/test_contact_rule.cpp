// growth.collisions "touch" (docs/algorithm.md §5.7.1): the measure, the
// rule on a hand-worked slab (contacts, crossings, tangled fans, flips), its
// keys, growth against the reference implementation of §1.4 in both modes,
// and the fail-safe: a genome whose mesh self-intersects goes back to its
// last clean step.
#include "core/base/config_reader.hpp"
#include "core/growth/contact/contact_geometry.hpp"
#include "core/growth/contact/contact_grid.hpp"
#include "core/growth/contact/contact_guard.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/growth/growth.hpp"
#include "core/growth/contact/self_intersection_check.hpp"
#include "core/mesh/face_pair.hpp"
#include "tests/support/phase_recorder.hpp"
#include "tests/support/reference_compare.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <set>
#include <thread>

using namespace morphogen;
using namespace morphogen::testing;

namespace {

// Random boxes in [-3, 3]^3 of the sizes the rule lists (faces grown by r),
// and random coordinates for queries, from one seeded stream.
class RandomBoxes {
public:
    explicit RandomBoxes(unsigned seed) : random_(seed) {}
    double coordinate() { return where_(random_); }
    Box3 operator()() {
        const Vec3 lo(where_(random_), where_(random_), where_(random_));
        return Box3{lo, lo + Vec3(size_(random_), size_(random_), size_(random_))};
    }

private:
    std::mt19937 random_;
    std::uniform_real_distribution<double> where_{-3.0, 3.0}, size_{0.05, 0.9};
};

// A closed slab: a 3 x 3 grid of vertices on top (z = 1, vertex i + 3j at
// (i, j)) and one below (z = 0, vertex 9 + i + 3j), each square cut along
// (i, j)-(i+1, j+1), the rims joined by walls; outward oriented. Vertex 4 is
// the top's centre T, vertex 13 the bottom's centre B.
TriMesh slab(const Vec3& bottom_centre = Vec3(1, 1, 0)) {
    MeshArrays arrays;
    for (const double z : {1.0, 0.0})
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) arrays.positions.emplace_back(i, j, z);
    arrays.positions[13] = bottom_centre;
    const auto top = [](int i, int j) { return i + 3 * j; };
    const auto bottom = [](int i, int j) { return 9 + i + 3 * j; };
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            arrays.faces.push_back({top(i, j), top(i + 1, j), top(i + 1, j + 1)});
            arrays.faces.push_back({top(i, j), top(i + 1, j + 1), top(i, j + 1)});
            arrays.faces.push_back({bottom(i, j), bottom(i + 1, j + 1), bottom(i + 1, j)});
            arrays.faces.push_back({bottom(i, j), bottom(i, j + 1), bottom(i + 1, j + 1)});
        }
    const int rim[8][2] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};  // counter-clockwise
    for (int k = 0; k < 8; ++k) {
        const auto [pi, pj] = rim[k];
        const auto [qi, qj] = rim[(k + 1) % 8];
        arrays.faces.push_back({bottom(pi, pj), bottom(qi, qj), top(qi, qj)});
        arrays.faces.push_back({bottom(pi, pj), top(qi, qj), top(pi, pj)});
    }
    return TriMesh::from_arrays(std::move(arrays), "slab");
}

struct Neighbours {
    std::vector<int> offsets, list;
};
Neighbours neighbours_of(const TriMesh& mesh) {
    Neighbours n;
    n.offsets.push_back(0);
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        mesh.for_each_neighbour(v, [&](int u) { n.list.push_back(u); });
        n.offsets.push_back(static_cast<int>(n.list.size()));
    }
    return n;
}

// Proposes `moves` (vertex, new position) on `mesh` and settles them with
// contact distance 0.1: the refused vertices.
std::vector<int> refused_of(TriMesh mesh, const std::vector<std::pair<int, Vec3>>& moves) {
    const std::vector<Vec3> before = mesh.positions();
    for (const auto& [v, p] : moves) mesh.positions()[v] = p;
    const std::vector<Vec3> proposed = mesh.positions();
    const Neighbours n = neighbours_of(mesh);
    ContactGuard guard;
    std::vector<int> touching;
    guard.settle_move(mesh, before, n.offsets, n.list, 0.1, touching);
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        const bool refused = std::find(touching.begin(), touching.end(), v) != touching.end();
        CHECK(mesh.position(v) == (refused ? before[v] : proposed[v]));
    }
    return touching;
}

// Growth with "touch" for `steps` steps in `mode`, defaults otherwise.
GrowthParams touch_params(GrowthMode mode, int steps) {
    GrowthParams params;
    params.steps = steps;
    params.mode = mode;
    params.collisions = Collisions::touch;
    return params;
}

// The exact rule of §5.7 by brute force over every pair of faces (no grid,
// no certificates): whether the mesh self-intersects.
bool self_intersects_brute_force(const TriMesh& mesh) {
    const std::vector<Vec3>& x = mesh.positions();
    const std::vector<Face>& faces = mesh.faces();
    for (std::size_t f = 0; f < faces.size(); ++f) {
        if (triangle_degenerate(x[faces[f][0]], x[faces[f][1]], x[faces[f][2]])) return true;
        const IndexedTriangle a = IndexedTriangle::of(x, faces[f]);
        for (std::size_t g = f + 1; g < faces.size(); ++g)
            if (faces_intersect(a, IndexedTriangle::of(x, faces[g]))) return true;
    }
    return false;
}

bool same_state(const GrowthState& a, const GrowthState& b) {
    return a.steps_done == b.steps_done && a.mesh.faces() == b.mesh.faces() &&
           a.mesh.positions() == b.mesh.positions() && a.directions == b.directions && a.outputs == b.outputs &&
           a.active == b.active && a.touched == b.touched;
}

// Genome 73 of random_test_genome, branching mode, default settings: its
// 200-step mesh self-intersects (hand-picked with
// experiments/scripts/touch-rewind/rewind_rate.cpp; its step 176 is the
// first that does).
constexpr std::uint64_t kRewoundGenome = 73;

}  // namespace

TEST_CASE("the contact measure: distance to a triangle, and the corners of the nearest point", "[contact]") {
    const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    const auto check = [&](const Vec3& p, double squared, unsigned corners) {
        const TriangleDistance d = distance_to_triangle(p, a, b, c);
        CHECK(d.squared == Approx(squared));
        CHECK(d.corners == corners);
    };
    check(Vec3(0.5, 0.5, 0.3), 0.09, 0b111);  // above the face
    check(Vec3(-1, -1, 0), 2.0, 0b001);       // nearest corner a
    check(Vec3(1, -0.5, 0), 0.25, 0b011);     // nearest side a-b
    check(Vec3(2, 2, 0), 2.0, 0b110);         // nearest side b-c
    check(Vec3(0, 3, 1), 2.0, 0b100);         // nearest corner c
    CHECK(distance_to_triangle(Vec3(1, 1, 1), a, Vec3(1, 0, 0), Vec3(2, 0, 0)).squared == Approx(2.0));  // collinear
}

TEST_CASE("the contact grid finds every listed box a query meets, marked and late ones included", "[contact]") {
    // Random boxes of the sizes the rule lists (faces grown by r), a third of
    // them marked; then some ids listed again elsewhere (a split's or a flip's
    // faces) and a few new ones. Every query is checked against brute force
    // over each id's latest box; an id may come more than once, never wrongly.
    RandomBoxes random_box(7);
    std::vector<Box3> boxes(300);
    std::vector<char> marks(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        boxes[i] = random_box();
        marks[i] = i % 3 == 0;
    }
    ContactGrid grid;
    grid.build(boxes, 0.6, marks);
    for (int id = 0; id < 60; ++id) {  // listed again: the latest box counts (and is marked)
        boxes[id * 5] = random_box();
        marks[id * 5] = 1;
        grid.insert(id * 5, boxes[id * 5]);
    }
    for (int k = 0; k < 5; ++k) {  // new ids, some far outside the built bounds
        boxes.push_back(k % 2 == 0 ? random_box() : Box3{Vec3(9, 9, 9), Vec3(9.5, 9.5, 9.5)});
        marks.push_back(1);
        grid.insert(static_cast<int>(boxes.size()) - 1, boxes.back());
    }
    for (int q = 0; q < 400; ++q) {
        const Vec3 p(random_box.coordinate() * 1.2 + (q % 7 == 0 ? 6.0 : 0.0), random_box.coordinate(),
                     random_box.coordinate());
        const Box3 query{p, p + Vec3(0.1, 0.05, 0.02) * (q % 4)};
        for (const bool marked_only : {false, true}) {
            std::set<int> found;
            grid.for_each_meeting(query, [&](int id) { found.insert(id); }, marked_only);
            std::set<int> expected;
            for (std::size_t i = 0; i < boxes.size(); ++i)
                if (boxes[i].overlaps(query) && (!marked_only || marks[i])) expected.insert(static_cast<int>(i));
            // Every meeting box is found; a found one meets the query up to
            // the outward rounding to floats.
            for (const int id : expected) CHECK(found.count(id) == 1);
            for (const int id : found) {
                CHECK((!marked_only || marks[id]));
                CHECK(boxes[id].inflated(1e-5).overlaps(query));
            }
        }
    }
}

TEST_CASE("the contact grid built again after late inserts forgets them", "[contact]") {
    // A build resets only the cells late entries went into when the grid
    // keeps its size: after inserts of new ids, a build of the same boxes
    // over the same bounds (the same cells) must find exactly its own boxes,
    // and so must one over other bounds (other cells).
    RandomBoxes random_box(11);
    std::vector<Box3> boxes(200);
    for (Box3& box : boxes) box = random_box();
    boxes[0] = Box3{Vec3(-4, -4, -4), Vec3(-3.9, -3.9, -3.9)};  // fixes the bounds for both builds
    boxes[1] = Box3{Vec3(4, 4, 4), Vec3(4.1, 4.1, 4.1)};
    ContactGrid grid;
    for (const double shift : {0.0, 0.0, 2.5}) {
        std::vector<Box3> listed = boxes;
        for (Box3& box : listed) box = Box3{box.lo.array() + shift, box.hi.array() + shift};
        grid.build(listed, 0.6);
        for (int q = 0; q < 300; ++q) {
            const Vec3 p =
                Vec3(random_box.coordinate(), random_box.coordinate(), random_box.coordinate()).array() + shift;
            const Box3 query{p, p + Vec3(0.3, 0.2, 0.1)};
            std::set<int> found;
            grid.for_each_meeting(query, [&](int id) { found.insert(id); });
            std::set<int> expected;
            for (std::size_t i = 0; i < listed.size(); ++i)
                if (listed[i].overlaps(query)) expected.insert(static_cast<int>(i));
            CHECK(found == expected);
        }
        // Late ids after this build, all over the grid: the next build must
        // not report them.
        for (int k = 0; k < 40; ++k) grid.insert(static_cast<int>(listed.size()) + k, random_box());
    }
}

TEST_CASE("touch on a hand-worked slab: exactly the vertices of a contact stay", "[contact]") {
    const TriMesh flat = slab();
    // T comes down to 0.05 above B (within 0.1 of the bottom's faces around
    // B, nearest point B): T stays; a top corner moving up is free.
    CHECK(refused_of(flat, {{4, Vec3(1, 1, 0.05)}, {0, Vec3(0, 0, 1.05)}}) == std::vector<int>{4});
    // B rises through the top sheet and ends 0.5 above it: not near at the
    // end, but its path crosses the face (1,1)-(2,1)-(2,2) inside.
    CHECK(refused_of(flat, {{13, Vec3(1.2, 1.1, 1.5)}}) == std::vector<int>{13});
    // The same vertex rising half way, inside the slab: nothing near.
    CHECK(refused_of(flat, {{13, Vec3(1.2, 1.1, 0.5)}}).empty());
    // The whole top comes down to 0.05 above the bottom: every top vertex
    // is 0.05 from the bottom faces right below it. The bottom does not move.
    std::vector<std::pair<int, Vec3>> sheet;
    for (int v = 0; v < 9; ++v) sheet.emplace_back(v, flat.position(v) - Vec3(0, 0, 0.95));
    CHECK(refused_of(flat, sheet) == std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8});
}

TEST_CASE("touch: a face moving onto a still vertex stays, all three corners", "[contact]") {
    // B raised to 0.9 below the centroid of the top face (1,1)-(2,1)-(2,2)
    // (vertices 4, 5, 8). That face comes down by 0.05: B, which does not
    // move, is now 0.05 from it, so its three corners stay, though none of
    // them comes near a face itself.
    const std::vector<std::pair<int, Vec3>> face_down{
        {4, Vec3(1, 1, 0.95)}, {5, Vec3(2, 1, 0.95)}, {8, Vec3(2, 2, 0.95)}};
    CHECK(refused_of(slab(Vec3(5.0 / 3, 4.0 / 3, 0.9)), face_down) == std::vector<int>{4, 5, 8});
    // With B flat on the bottom the same move is free.
    CHECK(refused_of(slab(), face_down).empty());
}

TEST_CASE("touch: a move that tangles a fan stays, though nothing is near", "[contact]") {
    // Vertex 5 = (2,1,1), in T's ring, jumps over T to (0.5, 1.2, 1.4): no
    // face comes within 0.1 of anything (the top is 0.4 below it) and no
    // path crosses a face, but T's ring no longer winds once around T.
    CHECK(refused_of(slab(), {{5, Vec3(0.5, 1.2, 1.4)}}) == std::vector<int>{5});
    // A smaller step, inside T's ring, is free.
    CHECK(refused_of(slab(), {{5, Vec3(1.8, 1.1, 1.2)}}).empty());
}

TEST_CASE("touch: a flip into another face is refused, a free one allowed", "[contact]") {
    // Whether faces 0 = (0,1,4) and 1 = (0,4,3), which share the diagonal
    // 0-4, may become (3,0,1) and (1,4,3) in `mesh` (nothing moved this step).
    const auto flip_allowed = [](TriMesh mesh) {
        const Neighbours n = neighbours_of(mesh);
        ContactGuard guard;
        std::vector<int> touching;
        const std::vector<Vec3> still = mesh.positions();
        guard.settle_move(mesh, still, n.offsets, n.list, 0.1, touching);
        return guard.allows(mesh, 0, 1, Face{3, 0, 1}, Face{1, 4, 3});
    };
    CHECK(flip_allowed(slab()));  // both new faces lie on the top
    // Vertex 3 pulled below the bottom: the new face (3,0,1) would cross
    // the bottom faces, which share no vertex with it.
    TriMesh pulled = slab();
    pulled.positions()[3] = Vec3(0, 1, -1);
    CHECK_FALSE(flip_allowed(pulled));
}

TEST_CASE("growth.contact_distance: read with touch, refused otherwise and out of range", "[contact][config]") {
    const auto read = [](const char* text, GrowthParams* out = nullptr) {
        const nlohmann::json section = nlohmann::json::parse(text);
        ConfigIssues issues;
        ObjectReader reader(&section, "growth", issues);
        const GrowthParams p = read_growth_params(reader);
        if (out != nullptr) *out = p;
        std::string all;
        for (const auto& issue : issues.list()) all += issue.path + ": " + issue.message + "\n";
        return all;
    };
    GrowthParams p;
    CHECK(read(R"({"collisions": "touch"})", &p).empty());
    CHECK(p.collisions == Collisions::touch);
    CHECK(p.contact_distance == 0.2);
    CHECK(read(R"({"collisions": "touch", "contact_distance": 0.25})", &p).empty());
    CHECK(p.contact_distance == 0.25);
    CHECK_THAT(read(R"({"contact_distance": 0.25})"), Catch::Contains("growth.contact_distance: is used only with"));
    CHECK_THAT(read(R"({"collisions": "prevent", "contact_distance": 0.25})"), Catch::Contains("growth.contact_distance"));
    CHECK_THAT(read(R"({"collisions": "touch", "contact_distance": 0})"), Catch::Contains("growth.contact_distance"));
    CHECK_THAT(read(R"({"collisions": "touch", "contact_distance": -1})"), Catch::Contains("growth.contact_distance"));
    CHECK_THAT(read(R"({"collisions": "touch", "contact_distance": "near"})"), Catch::Contains("growth.contact_distance"));
}

TEST_CASE("touch: the engine grows what the reference implementation grows, paper mode", "[contact][reference]") {
    GrowthParams params = touch_params(GrowthMode::paper, 40);
    params.contact_distance = GENERATE(0.1, 0.3);
    const auto grown = require_same_as_reference(params, 300);
    // The rule acted: some vertex stopped for good.
    int stopped = 0;
    for (const GrowthState& state : grown) stopped += static_cast<int>(std::count(state.touched.begin(), state.touched.end(), 1));
    CHECK(stopped > 0);
}

TEST_CASE("touch: the engine grows what the reference implementation grows, branching mode", "[contact][reference]") {
    GrowthParams params = touch_params(GrowthMode::branching, 40);
    params.contact_distance = GENERATE(0.1, 0.3);
    require_same_as_reference(params, 400);
}

TEST_CASE("touch: a refused vertex stays where it was and goes dormant", "[contact]") {
    for (const GrowthMode mode : {GrowthMode::paper, GrowthMode::branching}) {
        const GrowthParams params = touch_params(mode, 60);
        std::uint64_t refused = 0;
        for (std::uint64_t g = 1; g <= 6; ++g) {
            const Network network(random_test_genome({45, 30, 15}, g));
            const Grower grower(network, params);
            GrowthWorkspace workspace;
            GrowthState state = grower.start(make_seed("icosahedron", 1.0));
            for (int t = 0; t < params.steps; ++t) {
                const std::vector<Vec3> before(state.mesh.positions());
                grower.step(state, workspace);
                for (const int v : workspace.touching) {
                    INFO("genome " << g << " step " << t << " vertex " << v);
                    CHECK(state.mesh.position(v) == before[v]);
                    if (mode == GrowthMode::branching) CHECK(state.active[v] == 0);
                    else CHECK(state.touched[v] == 1);
                }
                // Paper mode: a vertex that touched never moves again.
                if (mode == GrowthMode::paper)
                    for (std::size_t v = 0; v < before.size(); ++v)
                        if (state.touched[v] == 1) CHECK(state.mesh.position(static_cast<int>(v)) == before[v]);
                refused += workspace.touching.size();
            }
        }
        CHECK(refused > 0);
    }
}

TEST_CASE("touch: a grown mesh depends on the genome and the parameters alone", "[contact]") {
    // Growing is per genome (one thread each): the same genome gives the same
    // bytes with a fresh workspace, with one that grew other genomes first,
    // and on two threads at once.
    for (const GrowthMode mode : {GrowthMode::paper, GrowthMode::branching}) {
        const GrowthParams params = touch_params(mode, 80);
        const Seed seed = make_seed("icosahedron", 1.0);
        const auto grow = [&](std::uint64_t g, GrowthWorkspace& workspace) {
            const Network network(random_test_genome({45, 30, 15}, g));
            return Grower(network, params).grow(seed, workspace);
        };
        const auto same = [](const GrowthState& a, const GrowthState& b) {
            return a.mesh.faces() == b.mesh.faces() && a.mesh.positions() == b.mesh.positions() &&
                   a.active == b.active && a.touched == b.touched;
        };
        for (std::uint64_t g = 1; g <= 4; ++g) {
            GrowthWorkspace fresh, used;
            const GrowthState alone = grow(g, fresh);
            grow(g + 100, used);
            CHECK(same(alone, grow(g, used)));
            GrowthState threaded[2];
            std::thread other([&] {
                GrowthWorkspace workspace;
                threaded[1] = grow(g, workspace);
            });
            GrowthWorkspace workspace;
            threaded[0] = grow(g, workspace);
            other.join();
            CHECK(same(alone, threaded[0]));
            CHECK(same(alone, threaded[1]));
        }
    }
}

TEST_CASE("the whole-mesh check agrees with brute force over every pair", "[contact][fail-safe]") {
    // Meshes grown with "allow" (many self-intersect) and "touch" in both
    // modes, at a few lengths.
    int intersecting = 0, clean = 0;
    SelfIntersectionCheck check;
    for (const Collisions collisions : {Collisions::allow, Collisions::touch})
        for (const GrowthMode mode : {GrowthMode::paper, GrowthMode::branching})
            for (std::uint64_t g = 1; g <= 6; ++g) {
                GrowthParams params = touch_params(mode, 30 + 10 * static_cast<int>(g));
                params.collisions = collisions;
                params.max_vertices = 600;
                const Network network(random_test_genome({45, 30, 15}, g));
                GrowthWorkspace workspace;
                const TriMesh mesh = Grower(network, params).grow(make_seed("icosahedron", 1.0), workspace).mesh;
                const bool expected = self_intersects_brute_force(mesh);
                INFO("genome " << g);
                CHECK(check.intersects(mesh) == expected);
                ++(expected ? intersecting : clean);
            }
    // Both answers were exercised.
    CHECK(intersecting > 0);
    CHECK(clean > 0);
}

TEST_CASE("touch's fail-safe: a self-intersecting growth goes back to its last clean step", "[contact][fail-safe]") {
    const GrowthParams params = touch_params(GrowthMode::branching, 200);
    const Network network(random_test_genome({45, 30, 15}, kRewoundGenome));
    const Seed seed = make_seed("icosahedron", 1.0);
    GrowthWorkspace workspace;
    // Without the fail-safe (Grower alone) the mesh self-intersects.
    REQUIRE(self_intersects_brute_force(Grower(network, params).grow(seed, workspace).mesh));

    const GrowthState rewound = GenomeGrower(NetworkParams{}, params).grow(network, workspace);
    const int k = rewound.steps_done;
    INFO("k = " << k);
    REQUIRE(k < params.steps);
    // Exactly the state growing the genome for k steps gives, clean by the
    // exact rule; step k + 1 is the first that self-intersects.
    GrowthParams shorter = params;
    shorter.steps = k;
    GrowthWorkspace fresh;
    CHECK(same_state(rewound, Grower(network, shorter).grow(seed, fresh)));
    CHECK_FALSE(self_intersects_brute_force(rewound.mesh));
    shorter.steps = k + 1;
    CHECK(self_intersects_brute_force(Grower(network, shorter).grow(seed, fresh).mesh));
    SelfIntersectionCheck check;
    for (int steps = 0; steps <= k; steps += 1 + k / 8) {
        shorter.steps = steps;
        INFO("after " << steps << " steps");
        CHECK_FALSE(check.intersects(Grower(network, shorter).grow(seed, fresh).mesh));
    }
}

TEST_CASE("touch's fail-safe: observers see exactly the steps of the growth returned", "[contact][fail-safe]") {
    const GrowthParams params = touch_params(GrowthMode::branching, 200);
    const GenomeGrower grower(NetworkParams{}, params);
    GrowthWorkspace workspace;
    for (const std::uint64_t g : {kRewoundGenome, std::uint64_t{1}}) {  // rewound, and clean
        const Network network(random_test_genome(grower.layers(), g));
        const GrowthState unobserved = grower.grow(network, workspace);
        std::vector<int> seen;
        std::vector<int> steps_done;
        PhaseRecorder phases;
        const GrowthState observed = grower.grow(
            network, workspace,
            [&](const GrowthState& state, int t) {
                seen.push_back(t);
                steps_done.push_back(state.steps_done);
            },
            &phases);
        INFO("genome " << g << ", k = " << unobserved.steps_done);
        CHECK(same_state(observed, unobserved));
        const int k = unobserved.steps_done;
        CHECK((g == kRewoundGenome ? k < params.steps : k == params.steps));
        REQUIRE(seen.size() == static_cast<std::size_t>(k));
        for (int t = 0; t < k; ++t) {
            CHECK(seen[t] == t);
            CHECK(steps_done[t] == t + 1);
        }
        // Beside a step observer, phases see the steps returned and no more.
        CHECK(phases.count(PhaseRecorder::Hook::begin, GrowthPhase::think) == k);
        CHECK(phases.count(PhaseRecorder::Hook::begin, GrowthPhase::settle) == k);
        // Alone (bench's clock), they see the work done: one growth of every
        // step, then the check (and the search for k) as one more settle.
        PhaseRecorder clock;
        CHECK(same_state(grower.grow(network, workspace, {}, &clock), unobserved));
        CHECK(clock.count(PhaseRecorder::Hook::begin, GrowthPhase::think) == params.steps);
        CHECK(clock.count(PhaseRecorder::Hook::begin, GrowthPhase::settle) == params.steps + 1);
        CHECK(clock.count(PhaseRecorder::Hook::end, GrowthPhase::settle) == params.steps + 1);
    }
}

TEST_CASE("touch's fail-safe leaves \"allow\" and \"prevent\" alone", "[contact][fail-safe]") {
    // The same genome grown through GenomeGrower and through Grower alone:
    // the same state, however it self-intersects.
    for (const Collisions collisions : {Collisions::allow, Collisions::prevent}) {
        GrowthParams params = touch_params(GrowthMode::branching, 60);
        params.collisions = collisions;
        const Network network(random_test_genome({45, 30, 15}, kRewoundGenome));
        GrowthWorkspace a, b;
        CHECK(same_state(GenomeGrower(NetworkParams{}, params).grow(network, a),
                         Grower(network, params).grow(make_seed("icosahedron", 1.0), b)));
    }
}
