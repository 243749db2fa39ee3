// Pictures in colours from growth history: `render` draws a GLB's COLOR_0
// (--no-colour the plain green, byte for byte what a plain GLB gives), and a
// coloured plant's picture spans more hues than the plain one's.
#include "core/io/mesh_io.hpp"
#include "report/render.hpp"
#include "tests/app/evolve_test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

// In the namespace rather than `using` it: this file shares a unity batch.
namespace morphogen::test {
namespace {

// Hue bins of 10 degrees that hold at least 1 % of a picture's clearly
// coloured pixels (saturation above 0.15; the white background, the grey
// plate and the captions are not).
std::set<int> hue_bins(const Image& image) {
    std::vector<int> count(36, 0);
    int coloured = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            const double r = p[0] / 255.0, g = p[1] / 255.0, b = p[2] / 255.0;
            const double hi = std::max({r, g, b}), lo = std::min({r, g, b});
            if (hi <= 0 || (hi - lo) / hi < 0.15) continue;
            const double d = hi - lo;
            double hue = hi == r ? std::fmod((g - b) / d + 6.0, 6.0) : hi == g ? (b - r) / d + 2.0 : (r - g) / d + 4.0;
            ++count[static_cast<std::size_t>(std::clamp(static_cast<int>(hue * 6.0), 0, 35))];
            ++coloured;
        }
    std::set<int> bins;
    for (int i = 0; i < 36; ++i)
        if (count[static_cast<std::size_t>(i)] * 100 >= coloured) bins.insert(i);
    return bins;
}

}  // namespace

TEST_CASE("render draws a GLB's vertex colours: more hues than the plain green; --no-colour is the plain picture",
          "[render][colour][cli]") {
    TempDir dir("render-colour");
    const std::string tree = q(std::string(MORPHOGEN_SOURCE_DIR) + "/configs/tree.json");
    for (const std::string& mode : {std::string(" --random 4 --steps 200"), " --config " + tree + " --random 5"}) {
        INFO(mode);
        REQUIRE(run_morphogen("grow" + mode + " --colour -o " + q(dir.path / "coloured.glb")).code == 0);
        REQUIRE(run_morphogen("grow" + mode + " -o " + q(dir.path / "plain.glb")).code == 0);

        const ColouredMesh coloured = read_coloured_mesh((dir.path / "coloured.glb").string());
        const ColouredMesh plain = read_coloured_mesh((dir.path / "plain.glb").string());
        REQUIRE(coloured.colours.size() == 4 * coloured.mesh.positions.size());
        CHECK(plain.colours.empty());
        RenderOptions options;
        options.size = 200;
        const std::set<int> many = hue_bins(render_mesh(coloured.mesh.view(), options, coloured.colours));
        const std::set<int> one = hue_bins(render_mesh(plain.mesh.view(), options));
        INFO("coloured: " << many.size() << " hue bins, plain: " << one.size());
        CHECK(one.size() <= 2);
        CHECK(many.size() >= one.size() + 3);
        // Hues the plain green never takes: bark's reds and browns (below 50 degrees).
        CHECK(std::any_of(many.begin(), many.end(), [](int bin) { return bin < 5; }));
        CHECK(std::none_of(one.begin(), one.end(), [](int bin) { return bin < 5; }));

        // The command: colours by default; --no-colour draws the same mesh in
        // the plain green, byte for byte as the renderer without colours.
        fs::create_directories(dir.path / "c");
        fs::copy_file(dir.path / "coloured.glb", dir.path / "c" / "plant.glb", fs::copy_options::overwrite_existing);
        REQUIRE(run_morphogen("render " + q(dir.path / "c" / "plant.glb") + " -o " + q(dir.path / "c.png")).code == 0);
        REQUIRE(run_morphogen("render --no-colour " + q(dir.path / "c" / "plant.glb") + " -o " + q(dir.path / "n.png")).code == 0);
        const std::vector<std::string> caption{"plant"};
        render_contact_sheet(std::span(&coloured.mesh, 1), caption, (dir.path / "p.png").string(), RenderOptions{});
        CHECK(read_text(dir.path / "c.png") != read_text(dir.path / "p.png"));
    }
}

TEST_CASE("render refuses colours that are not 4 per vertex", "[render][colour]") {
    MeshArrays triangle;
    triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    triangle.faces = {{0, 1, 2}};
    const std::vector<float> three(9, 0.5f);
    CHECK_THROWS_WITH(render_mesh(triangle.view(), RenderOptions{}, three), Catch::Contains("4 per vertex"));
}

}  // namespace morphogen::test
