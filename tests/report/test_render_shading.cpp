// Smooth shading in pictures: normals interpolated across each face (more
// shades than faces, no steps at facet edges on a sphere), creases kept (a
// cube's faces stay one shade each), and corner_normals itself.
#include "report/corner_normals.hpp"
#include "report/render.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <map>
#include <set>

// In the namespace rather than `using` it: this file shares a unity batch.
namespace morphogen::test {
namespace {

// An octahedron split `rounds` times into four by its edge midpoints, pushed
// onto the unit sphere and stood on the ground: 8 * 4^rounds faces.
MeshArrays shading_sphere(int rounds) {
    MeshArrays m;
    m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (int r = 0; r < rounds; ++r) {
        std::map<std::pair<int, int>, int> middle;
        const auto mid = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            auto [it, fresh] = middle.try_emplace(key, static_cast<int>(m.positions.size()));
            if (fresh) m.positions.push_back((m.positions[a] + m.positions[b]).normalized());
            return it->second;
        };
        std::vector<Face> faces;
        for (const Face& f : m.faces) {
            const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
            faces.insert(faces.end(), {{f[0], ab, ca}, {ab, f[1], bc}, {ca, bc, f[2]}, {ab, bc, ca}});
        }
        m.faces = std::move(faces);
    }
    for (Vec3& v : m.positions) v.z() += 1;
    return m;
}

MeshArrays shading_box() {
    MeshArrays m;
    for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 2 : 0);
    m.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
               {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return m;
}

bool plant_green(const std::uint8_t* p) { return p[1] > p[0] + 20 && p[1] > p[2] + 20; }

// Distinct colours of a picture's plant pixels.
std::size_t shades(const Image& image) {
    std::set<std::array<std::uint8_t, 3>> seen;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (const std::uint8_t* p = image.pixel(x, y); plant_green(p)) seen.insert({p[0], p[1], p[2]});
    return seen.size();
}

// Of the pairs of side-by-side plant pixels, the share with the same colour.
double same_neighbours(const Image& image) {
    int pairs = 0, same = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x + 1 < image.width; ++x) {
            const std::uint8_t *p = image.pixel(x, y), *q = image.pixel(x + 1, y);
            if (!plant_green(p) || !plant_green(q)) continue;
            ++pairs;
            same += p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
        }
    REQUIRE(pairs > 1000);
    return static_cast<double>(same) / pairs;
}

}  // namespace

TEST_CASE("pictures shade smoothly: more shades than faces, no steps between facets", "[render][shading]") {
    RenderOptions smooth;
    smooth.size = 200;
    smooth.supersample = 1;  // no edge blending: a flat face is one colour
    RenderOptions flat = smooth;
    flat.crease_deg = 0;
    // 32 faces: flat shading has at most one shade per face; smooth far more.
    const MeshArrays coarse = shading_sphere(1);
    const std::size_t flat_shades = shades(render_mesh(coarse.view(), flat));
    const std::size_t smooth_shades = shades(render_mesh(coarse.view(), smooth));
    INFO("flat " << flat_shades << " shades, smooth " << smooth_shades);
    CHECK(flat_shades <= 32);
    CHECK(smooth_shades >= 3 * flat_shades);
    // 512 faces: flat shading paints each facet in one colour, so most
    // neighbours match; smooth shading is a gradient across the facets.
    const MeshArrays fine = shading_sphere(3);
    const double flat_same = same_neighbours(render_mesh(fine.view(), flat));
    const double smooth_same = same_neighbours(render_mesh(fine.view(), smooth));
    INFO("same-coloured neighbours: flat " << flat_same << ", smooth " << smooth_same);
    CHECK(flat_same > 0.7);
    CHECK(smooth_same < 0.6 * flat_same);
}

TEST_CASE("smooth shading keeps creases: a box's faces stay one shade each", "[render][shading]") {
    RenderOptions options;
    options.size = 160;
    options.supersample = 1;
    const MeshArrays box = shading_box();
    CHECK(shades(render_mesh(box.view(), options)) <= 3);  // three faces are seen
    options.crease_deg = 180;  // no creases: the box shades as a blob
    CHECK(shades(render_mesh(box.view(), options)) > 20);
    options.crease_deg = -1;
    CHECK_THROWS_WITH(render_mesh(box.view(), options), Catch::Contains("crease"));
}

TEST_CASE("corner_normals: vertex normals on smooth surfaces, face normals at creases", "[render][shading]") {
    const MeshArrays box = shading_box();
    for (const auto& corners : corner_normals(box.view(), 60)) {
        CHECK(corners[0].isApprox(corners[1]));  // each face of a box is its own smoothing group
        CHECK(corners[0].isApprox(corners[2]));
        CHECK(std::abs(corners[0].cwiseAbs().maxCoeff() - 1) < 1e-12);  // an axis
    }
    const MeshArrays sphere = shading_sphere(2);
    const std::vector<std::array<Vec3, 3>> normals = corner_normals(sphere.view(), 60);
    for (std::size_t f = 0; f < sphere.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {  // close to the sphere's own normal at the vertex
            const Vec3 radial = (sphere.positions[sphere.faces[f][k]] - Vec3(0, 0, 1)).normalized();
            CHECK(normals[f][k].dot(radial) > 0.99);
            CHECK(std::abs(normals[f][k].norm() - 1) < 1e-12);
        }
    MeshArrays broken = sphere;
    broken.positions[0].x() = std::nan("");
    const std::vector<std::array<Vec3, 3>> skipped = corner_normals(broken.view(), 60);
    for (std::size_t f = 0; f < broken.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) CHECK(skipped[f][k].allFinite());
}

}  // namespace morphogen::test
