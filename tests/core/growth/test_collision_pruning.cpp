// The collision guard's pruning (docs/algorithm.md §5.7, docs/performance.md
// "Collision-aware growth"): what it skips must be proven apart, so that it
// decides exactly as the plain rule, pair by pair, would.
#include "evolution/rng.hpp"
#include "core/growth/contact/collision.hpp"
#include "core/growth/growth.hpp"
#include "core/growth/seeds/seeds.hpp"
#include "core/mesh/face_listing.hpp"
#include "core/mesh/face_pair.hpp"
#include "core/mesh/fan_certificate.hpp"
#include "tests/support/test_genomes.hpp"
#include "tests/support/test_meshes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace morphogen;
using namespace morphogen::testing;

namespace {

// A bipyramid: the fan of vertex 0 over the ring 1..n, closed below by vertex n+1.
TriMesh bipyramid(const std::vector<Vec3>& ring, const Vec3& top, const Vec3& bottom) {
    MeshArrays m;
    const int n = static_cast<int>(ring.size());
    m.positions.push_back(top);
    m.positions.insert(m.positions.end(), ring.begin(), ring.end());
    m.positions.push_back(bottom);
    for (int k = 0; k < n; ++k) {
        const int a = 1 + k, b = 1 + (k + 1) % n;
        m.faces.push_back({0, a, b});
        m.faces.push_back({n + 1, b, a});
    }
    return TriMesh::from_arrays(std::move(m), "bipyramid");
}

// The plain rule of §5.7 for one settle: every pair of faces whose boxes
// meet, one of them moved this round, by brute force.
void settle_by_brute_force(TriMesh& mesh, const std::vector<Vec3>& before) {
    std::vector<Vec3>& x = mesh.positions();
    const int V = mesh.num_vertices(), F = mesh.num_faces();
    const std::vector<Vec3> proposed = x;
    std::vector<double> scale(V);
    std::vector<char> changed(V);
    for (int v = 0; v < V; ++v) scale[v] = changed[v] = x[v] != before[v];
    for (int round = 0;; ++round) {
        std::vector<char> active(F), hit(V);
        const auto box = [&](int f) { return Box3::of(x[mesh.face(f)[0]], x[mesh.face(f)[1]], x[mesh.face(f)[2]]); };
        for (int f = 0; f < F; ++f)
            for (const int v : mesh.face(f)) active[f] |= changed[v];
        bool found = false;
        const auto mark = [&](int f) {
            for (const int v : mesh.face(f)) hit[v] = 1;
            found = true;
        };
        for (int i = 0; i < F; ++i) {
            if (!active[i]) continue;
            const IndexedTriangle ti = IndexedTriangle::of(x, mesh.face(i));
            if (triangle_degenerate(ti.p[0], ti.p[1], ti.p[2])) mark(i);
            for (int j = 0; j < F; ++j) {
                if (j == i || (active[j] && j < i) || !box(i).overlaps(box(j))) continue;
                if (faces_intersect(ti, IndexedTriangle::of(x, mesh.face(j)))) {
                    mark(i);
                    mark(j);
                }
            }
        }
        if (!found) return;
        std::fill(changed.begin(), changed.end(), 0);
        for (int v = 0; v < V; ++v) {
            if (!hit[v] || scale[v] == 0.0) continue;
            scale[v] = round < CollisionGuard::kHalvings ? 0.5 * scale[v] : 0.0;
            x[v] = scale[v] == 0.0 ? before[v] : Vec3(before[v] + scale[v] * (proposed[v] - before[v]));
            changed[v] = 1;
        }
    }
}

}  // namespace

TEST_CASE("a certified fan has no intersecting pair and no degenerate face", "[collision]") {
    // Rings around the top vertex: flat, tilted, folded (winding twice, or
    // with a spoke turned back), with coordinates on a coarse lattice (exact
    // coplanarity and collinearity) or not. The certificate must never hold
    // where a pair of the fan intersects by the exact rule.
    RandomStream stream(11, 0);
    int certified = 0, intersecting = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const int n = 3 + static_cast<int>(stream.uniform() * 7);
        const int winding = stream.bernoulli(0.2) ? 2 : 1;
        const double height = stream.bernoulli(0.5) ? 0.02 : 0.8;
        const bool lattice = stream.bernoulli(0.3);
        std::vector<Vec3> ring;
        for (int k = 0; k < n; ++k) {
            double angle = 2.0 * std::numbers::pi * winding * (k + stream.uniform(-0.45, 0.45)) / n;
            if (stream.bernoulli(0.05)) angle += std::numbers::pi;
            const double radius = stream.uniform(0.2, 1.5);
            Vec3 p(radius * std::cos(angle), radius * std::sin(angle), stream.uniform(-height, height));
            if (lattice) p = (p * 4.0).array().round() / 4.0;
            ring.push_back(p);
        }
        TriMesh mesh;
        try {
            mesh = bipyramid(ring, {0, 0, 0}, {0.01, 0.02, -3});
        } catch (const std::exception&) {
            continue;  // a ring with a repeated lattice point
        }
        std::vector<Vec3> spokes;
        const bool fan_ok = fan_certified(mesh, 0, spokes);
        bool any = false;
        for (int f = 0; f < mesh.num_faces(); f += 2) {
            const IndexedTriangle a = IndexedTriangle::of(mesh.positions(), mesh.face(f));
            any |= triangle_degenerate(a.p[0], a.p[1], a.p[2]);
            for (int g = f + 2; g < mesh.num_faces(); g += 2)
                any |= faces_intersect(a, IndexedTriangle::of(mesh.positions(), mesh.face(g)));
        }
        INFO("trial " << trial);
        REQUIRE(!(fan_ok && any));
        certified += fan_ok;
        intersecting += any;
    }
    CHECK(certified > 5000);      // it proves most ordinary fans
    CHECK(intersecting > 2000);   // and meets many that do intersect
}

TEST_CASE("partner lists hold exactly the faces whose listing boxes meet, less those the rule leaves out",
          "[collision]") {
    RandomStream stream(5, 0);
    const auto random_box = [&] {
        const Vec3 lo(stream.uniform(0, 10), stream.uniform(0, 10), stream.uniform(0, 10));
        return Box3{lo, lo + Vec3(stream.uniform(0, 2), stream.uniform(0, 2), stream.uniform(0, 0.1))};
    };
    FaceListing listing;
    std::vector<Box3> boxes;
    for (int f = 0; f < 300; ++f) {
        boxes.push_back(random_box());
        listing.relist(f, boxes.back());
    }
    // A rule fixed for each pair, as "shares no vertex" is while neither face changes.
    const auto keep = [](int f, int g) { return (f + g) % 3 != 0; };
    for (int round = 0; round < 30; ++round) {
        listing.refresh(keep);
        for (int f = 0; f < listing.size(); ++f) {
            std::vector<int> got(listing.partners(f).begin(), listing.partners(f).end()), want;
            for (int g = 0; g < listing.size(); ++g)
                if (g != f && boxes[g].overlaps(boxes[f]) && keep(f, g)) want.push_back(g);
            std::sort(got.begin(), got.end());
            REQUIRE(got == want);  // no repeats, none missing, symmetric by construction of want
        }
        // Some faces move, and some are appended, as in growth.
        for (int k = 0; k < 20; ++k) {
            const int f = static_cast<int>(stream.uniform() * listing.size());
            boxes[f] = random_box();
            listing.relist(f, boxes[f]);
        }
        boxes.push_back(random_box());
        listing.relist(listing.size(), boxes.back());
    }
}

TEST_CASE("the guard settles a move as the plain rule does, step after step", "[collision]") {
    // A grown mesh, then random moves large enough to fold it: the guard,
    // with its lists kept from move to move, against brute force.
    GrowthParams params;
    params.steps = 25;
    params.max_vertices = 200;
    const Network network(random_test_genome({45, 30, 15}, 3));
    GrowthWorkspace workspace;
    TriMesh mesh = Grower(network, params).grow(make_seed("icosahedron", 1.0), workspace).mesh;
    REQUIRE(mesh.num_vertices() > 60);
    RandomStream stream(9, 0);
    CollisionGuard guard;
    int shortened = 0;
    for (int move = 0; move < 40; ++move) {
        const std::vector<Vec3> before = mesh.positions();
        const double reach = move % 4 == 0 ? 1.0 : 0.1;
        for (Vec3& p : mesh.positions())
            if (stream.bernoulli(0.7)) p += reach * Vec3(stream.uniform(-1, 1), stream.uniform(-1, 1), stream.uniform(-1, 1));
        TriMesh plain = mesh;
        settle_by_brute_force(plain, before);
        const std::uint64_t was = guard.shortened;
        guard.settle_move(mesh, before);
        shortened += guard.shortened > was;
        INFO("move " << move);
        REQUIRE(mesh.positions() == plain.positions());
    }
    CHECK(shortened > 10);
}
