// The diagnosis of experiments/2026-11-27-contact-rule-2.md: grows genomes
// with "touch" and, after every settle, split and flip, runs CGAL's check; at
// the first failure it lists the intersecting pairs and their corners.
// To run: copy to tests/fitness/, add it to test_fitness's sources in
// tests/CMakeLists.txt, build, then: [TREE=1] [PAPER=1] [N=300 | G=19,73]
// build/tests/test_fitness "[diag]".
#include "fitness/geometry/cgal_geometry.hpp"
#include "core/growth/genome_grower.hpp"
#include "core/growth/contact/contact_geometry.hpp"
#include "core/mesh/face_pair.hpp"
#include "tests/support/test_genomes.hpp"
#include <catch2/catch.hpp>
#include <cstdio>
using namespace morphogen;
using namespace morphogen::testing;
namespace {
struct Diag : GrowthObserver {
    GrowthParams p;
    std::vector<Vec3> before, proposed;
    bool bad_before = false;
    std::string first;  // phase where it first went bad
    int step = 0;
    long moving = 0, verts = 0;
    void begin(GrowthPhase ph, const GrowthState& s, const GrowthWorkspace&) override {
        if (ph == GrowthPhase::move) before = s.mesh.positions();
        if (ph == GrowthPhase::settle) proposed = s.mesh.positions();
    }
    void end(GrowthPhase ph, const GrowthState& s, const GrowthWorkspace& w) override {
        if (ph == GrowthPhase::settle) {
            for (int v = 0; v < s.mesh.num_vertices(); ++v) moving += s.mesh.position(v) != before[v];
            verts += s.mesh.num_vertices();
        }
        if (!first.empty()) return;
        if (ph != GrowthPhase::settle && ph != GrowthPhase::split && ph != GrowthPhase::flip) return;
        if (!mesh_self_intersects(s.mesh.view())) return;
        first = ph == GrowthPhase::settle ? "settle" : ph == GrowthPhase::split ? "split" : "flip";
        // classify pairs
        const auto& x = s.mesh.positions();
        const auto& F = s.mesh.faces();
        int shared = 0, apart = 0, near = 0, refusedc = 0;
        for (int f = 0; f < (int)F.size(); ++f)
            for (int g = f + 1; g < (int)F.size(); ++g) {
                auto tf = IndexedTriangle::of(x, F[f]), tg = IndexedTriangle::of(x, F[g]);
                if (!faces_intersect(tf, tg)) continue;
                int sh = 0;
                for (int a : F[f]) for (int b : F[g]) sh += a == b;
                if (sh) { ++shared; continue; }
                ++apart;
                double m = 1e9;
                for (int k = 0; k < 3; ++k) {
                    m = std::min(m, distance_to_triangle(x[F[f][k]], x[F[g][0]], x[F[g][1]], x[F[g][2]]).squared);
                    m = std::min(m, distance_to_triangle(x[F[g][k]], x[F[f][0]], x[F[f][1]], x[F[f][2]]).squared);
                }
                if (std::sqrt(m) < p.contact_distance) ++near;
                if (ph == GrowthPhase::settle && std::getenv("G")) {
                    auto P = IndexedTriangle::of(proposed, F[f]), Q = IndexedTriangle::of(proposed, F[g]);
                    auto B0 = IndexedTriangle::of(before, F[f]), B1 = IndexedTriangle::of(before, F[g]);
                    std::printf("  pair %d %d: at proposed %d at before %d; corners:", f, g, (int)faces_intersect(P, Q), (int)faces_intersect(B0, B1));
                    for (int k = 0; k < 6; ++k) {
                        int u = k < 3 ? F[f][k] : F[g][k - 3];
                        bool mv = proposed[u] != before[u];
                        bool ref = mv && x[u] == before[u];
                        std::printf(" %d%s", u, ref ? "R" : mv ? "M" : "S");
                    }
                    std::printf(" minvert-face dist %.3f\n", std::sqrt(m));
                }
                for (int k = 0; k < 3; ++k)
                    for (int v : {F[f][k], F[g][k]})
                        if (std::find(w.touching.begin(), w.touching.end(), v) != w.touching.end()) { ++refusedc; }
            }
        char buf[200];
        std::snprintf(buf, sizeof buf, " step %d shared %d apart %d near %d refusedcorners %d", step, shared, apart, near, refusedc);
        first += buf;
    }
};
}
TEST_CASE("diag contact", "[.][diag]") {
    GrowthParams params;
    params.mode = GrowthMode::branching;
    params.collisions = Collisions::touch;
    if (std::getenv("TREE")) { params.steps = 150; params.max_vertices = 1000; }
    if (std::getenv("PAPER")) params.mode = GrowthMode::paper;
    const int n = std::getenv("N") ? std::atoi(std::getenv("N")) : 300;
    GrowthWorkspace ws;
    int bad = 0; long mv = 0, vs = 0;
    std::vector<std::uint64_t> list;
    if (const char* gs = std::getenv("G")) { std::string t(gs); size_t pos = 0; while (pos < t.size()) { list.push_back(std::stoull(t.substr(pos))); pos = t.find(',', pos); if (pos == std::string::npos) break; ++pos; } }
    else for (int g = 1; g <= n; ++g) list.push_back(g);
    for (const std::uint64_t g : list) {
        Network net(random_test_genome({45, 30, 15}, g));
        Diag d; d.p = params;
        GenomeGrower grower(NetworkParams{}, params);
        grower.grow(net, ws, [&](const GrowthState&, int t) { d.step = t + 1; }, &d);
        mv += d.moving; vs += d.verts;
        if (!d.first.empty() || std::getenv("G")) { ++bad; std::printf("genome %lu: %s\n", (unsigned long)g, d.first.c_str()); }
    }
    std::printf("bad %d of %d; moving fraction %.3f\n", bad, n, double(mv) / vs);
}
