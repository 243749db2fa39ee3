#include "core/base/errors.hpp"
#include "core/growth/seeds/seeds.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/test_meshes.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace morphogen;
using namespace morphogen::testing;

namespace {
double signed_volume(const TriMesh& m) {
    double v = 0;
    for (const Face& f : m.faces()) v += m.position(f[0]).dot(m.position(f[1]).cross(m.position(f[2])));
    return v / 6;
}
}  // namespace

TEST_CASE("built-in seeds: valid, outward, radius, resting on the ground", "[seeds]") {
    for (const std::string& name : builtin_seed_names()) {
        const Seed seed = make_seed(name, 2.5);
        INFO(name);
        CHECK(seed.mesh.check().empty());
        CHECK(signed_volume(seed.mesh) > 0);
        double lowest = 1e9;
        Vec3 centre = Vec3::Zero();
        for (const Vec3& p : seed.mesh.positions()) {
            lowest = std::min(lowest, p.z());
            centre += p;
        }
        centre /= seed.mesh.num_vertices();
        CHECK(lowest == 0.0);
        for (const Vec3& p : seed.mesh.positions()) CHECK((p - centre).norm() == Approx(2.5));
        for (int v = 0; v < seed.mesh.num_vertices(); ++v) {
            // On a regular solid the area-weighted normal points away from the centre.
            CHECK(seed.directions[v].dot((seed.mesh.position(v) - centre).normalized()) == Approx(1.0));
        }
    }
}

TEST_CASE("built-in seed order is pinned", "[seeds]") {
    // The order decides the split and flip order; docs/algorithm.md §3.2 lists it.
    const TriMesh ico = builtin_seed_mesh("icosahedron", 1.0);
    REQUIRE(ico.num_vertices() == 12);
    REQUIRE(ico.num_faces() == 20);
    CHECK(ico.face(0) == Face{0, 11, 5});
    CHECK(ico.face(7) == Face{11, 10, 2});
    CHECK(ico.face(19) == Face{9, 8, 1});
    const double phi = (1 + std::sqrt(5.0)) / 2, r = std::sqrt(1 + phi * phi);
    CHECK(ico.position(0).x() == Approx(-1 / r));
    CHECK(ico.position(0).y() == Approx(phi / r));
    CHECK(ico.position(4).z() == Approx(2 * phi / r));  // (0,-1,phi) lifted by phi/r
    const TriMesh oct = builtin_seed_mesh("octahedron", 1.0);
    CHECK(oct.face(0) == Face{0, 2, 4});
    CHECK(oct.face(7) == Face{0, 3, 5});
    CHECK(oct.position(5).z() == 0.0);
    const TriMesh tet = builtin_seed_mesh("tetrahedron", 1.0);
    CHECK(tet.face(3) == Face{1, 3, 2});
}

TEST_CASE("seed files: accepted when closed and outward, refused clearly otherwise", "[seeds]") {
    const TempDir tmp("seeds");
    const std::string cube_vertices =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
    const std::string cube_faces =
        "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
    const std::string good = tmp.file("seed-cube.obj");
    write_text(good, cube_vertices + cube_faces);
    const Seed seed = make_seed(good, 123.0);  // radius is ignored for files
    CHECK(seed.mesh.num_vertices() == 8);
    CHECK(seed.mesh.position(6) == Vec3(1, 1, 1));

    const std::string open = tmp.file("seed-open.obj");
    write_text(open, cube_vertices + cube_faces.substr(0, cube_faces.rfind("f 4 5 8")));
    CHECK_THROWS_WITH(make_seed(open, 1), Catch::Contains(open) && Catch::Contains("open"));

    std::string inward_faces;
    for (std::size_t i = 0; i < cube_faces.size();) {  // reverse every face
        const std::size_t end = cube_faces.find('\n', i);
        int a, b, c;
        std::sscanf(cube_faces.c_str() + i, "f %d %d %d", &a, &b, &c);
        inward_faces += "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(b) + "\n";
        i = end + 1;
    }
    const std::string inward = tmp.file("seed-inward.obj");
    write_text(inward, cube_vertices + inward_faces);
    CHECK_THROWS_WITH(make_seed(inward, 1), Catch::Contains(inward) && Catch::Contains("inward"));

    const std::string nonmanifold = tmp.file("seed-nonmanifold.obj");
    write_text(nonmanifold, cube_vertices + cube_faces + "f 1 2 3\n");
    CHECK_THROWS_WITH(make_seed(nonmanifold, 1), Catch::Contains(nonmanifold));

    CHECK_THROWS_WITH(make_seed(tmp.file("no-such-seed.obj"), 1), Catch::Contains("no-such-seed.obj"));
    const std::string garbage = tmp.file("seed-garbage.obj");
    write_text(garbage, "v 0 0 zero\n");
    CHECK_THROWS_WITH(make_seed(garbage, 1), Catch::Contains(garbage));
}

TEST_CASE("make_seed of growth keys: the seed growth.seed_mesh names, at growth.seed_radius", "[seeds]") {
    GrowthParams growth;
    growth.seed_mesh = "tetrahedron";
    growth.seed_radius = 3.0;
    const Seed seed = make_seed(growth), expected = make_seed("tetrahedron", 3.0);
    CHECK(seed.mesh.positions() == expected.mesh.positions());
    CHECK(seed.mesh.faces() == expected.mesh.faces());
    CHECK(seed.directions == expected.directions);
}
