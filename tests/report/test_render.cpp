// The software renderer, contact sheets and the `render` subcommand.
#include "app/commands.hpp"
#include "core/base/errors.hpp"
#include "core/io/mesh_io.hpp"
#include "report/render.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

using namespace morphogen;
using morphogen::testing::TempDir;
namespace fs = std::filesystem;

namespace {

// Axis-aligned cube of edge 2*h standing on z = 0, outward faces.
MeshArrays cube(double h) {
    MeshArrays m;
    for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? 2 * h : 0);
    m.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
               {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return m;
}

MeshArrays icosahedron() {
    const double p = (1 + std::sqrt(5.0)) / 2;
    MeshArrays m;
    m.positions = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                   {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
    for (Vec3& v : m.positions) v.z() += p;  // stand on the ground
    m.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
               {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    return m;
}

// Width and height from a PNG's IHDR chunk (bytes 16..23, big-endian).
std::pair<std::uint32_t, std::uint32_t> png_size(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    REQUIRE(bytes.size() > 33);
    REQUIRE(bytes.substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
    REQUIRE(bytes.substr(12, 4) == "IHDR");
    const auto be32 = [&](std::size_t at) {
        std::uint32_t v = 0;
        for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(bytes[at + i]);
        return v;
    };
    CHECK(static_cast<unsigned char>(bytes[24]) == 8);  // bit depth
    CHECK(static_cast<unsigned char>(bytes[25]) == 2);  // colour type RGB
    return {be32(16), be32(20)};
}

bool is_white(const std::uint8_t* p) { return p[0] == 255 && p[1] == 255 && p[2] == 255; }
bool is_green(const std::uint8_t* p) { return p[1] > p[0] + 20 && p[1] > p[2] + 20; }

// Number of plant-green pixels in one size x size picture of a sheet.
int green_pixels(const Image& img, int x0, int y0, int size) {
    int n = 0;
    for (int y = y0; y < y0 + size; ++y)
        for (int x = x0; x < x0 + size; ++x) n += is_green(img.pixel(x, y));
    return n;
}

// Runs the CLI like main() does, minus the exit-code mapping.
int run_cli(std::vector<std::string> args) {
    CLI::App app;
    CommandRunner selected;
    add_render_command(app, selected);
    std::reverse(args.begin(), args.end());  // CLI11 takes the arguments reversed
    app.parse(args);
    REQUIRE(selected);
    return selected();
}

}  // namespace

TEST_CASE("a contact sheet PNG has the grid's size, a white background and shaded meshes", "[render]") {
    TempDir tmp;
    const std::vector<MeshArrays> meshes = {cube(1), icosahedron(), cube(0.5)};
    const std::vector<std::string> captions = {"cube", "icosahedron", "small"};
    RenderOptions options;
    options.size = 96;
    options.columns = 2;
    const std::string path = tmp.file("sheet.png");
    render_contact_sheet(meshes, captions, path, options);
    REQUIRE(fs::exists(path));
    const auto [w, h] = png_size(path);
    CHECK(w == 2u * 96);
    CHECK(h == 2u * static_cast<std::uint32_t>(sheet_cell_height(96)));
    CHECK(sheet_cell_height(96) > 96);

    const Image img = render_sheet(meshes, captions, options);
    REQUIRE(img.width == static_cast<int>(w));
    REQUIRE(img.height == static_cast<int>(h));
    CHECK(is_white(img.pixel(0, 0)));
    CHECK(is_white(img.pixel(95, 0)));
    CHECK(is_white(img.pixel(img.width - 1, img.height - 1)));  // the empty fourth cell
    std::set<std::uint32_t> colours;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.pixel(x, y);
            colours.insert(static_cast<std::uint32_t>(p[0]) << 16 | p[1] << 8 | p[2]);
        }
    CHECK(colours.size() > 20);  // shading, anti-aliasing, ground plate, captions
    CHECK(green_pixels(img, 0, 0, 96) > 200);
    CHECK(green_pixels(img, 96, 0, 96) > 200);
    // Captions are dark pixels under the picture.
    int dark = 0;
    for (int y = 96; y < sheet_cell_height(96); ++y)
        for (int x = 0; x < 96; ++x) dark += img.pixel(x, y)[0] < 128;
    CHECK(dark > 10);
}

TEST_CASE("a shared scale keeps sizes comparable; own scale fills each cell", "[render]") {
    const std::vector<MeshArrays> meshes = {cube(2), cube(1)};
    RenderOptions options;
    options.size = 128;
    const Image shared = render_sheet(meshes, {}, options);
    const int big = green_pixels(shared, 0, 0, 128), small = green_pixels(shared, 128, 0, 128);
    CHECK(big == Approx(4.0 * small).epsilon(0.1));  // half the edge: a quarter of the area

    options.shared_scale = false;
    const Image own = render_sheet(meshes, {}, options);
    CHECK(green_pixels(own, 0, 0, 128) == Approx(green_pixels(own, 128, 0, 128)).epsilon(0.02));
    CHECK(green_pixels(own, 0, 0, 128) == big);
}

TEST_CASE("render_mesh draws a single framed picture; bad options are refused", "[render]") {
    RenderOptions options;
    options.size = 64;
    const MeshArrays ico = icosahedron();
    const Image img = render_mesh(ico.view(), options);
    CHECK(img.width == 64);
    CHECK(img.height == 64);
    CHECK(green_pixels(img, 0, 0, 64) > 64 * 64 / 8);
    CHECK(is_white(img.pixel(0, 0)));

    MeshArrays broken = ico;
    broken.positions[0].x() = std::nan("");  // skipped, not fatal
    CHECK_NOTHROW(render_mesh(broken.view(), options));

    options.size = 16;
    CHECK_THROWS_AS(render_mesh(ico.view(), options), std::invalid_argument);
    options.size = 64;
    options.columns = 0;
    const std::vector<MeshArrays> one = {ico};
    CHECK_THROWS_AS(render_sheet(one, {}, options), std::invalid_argument);
    options.columns = 1;
    const std::vector<std::string> two = {"a", "b"};
    CHECK_THROWS_AS(render_sheet(one, two, options), std::invalid_argument);
}

TEST_CASE("writing a PNG where it cannot go throws IoError naming the path", "[render]") {
    TempDir tmp;
    const std::string path = tmp.file("no/such/dir/sheet.png");
    CHECK_THROWS_WITH(write_png(Image(4, 4), path), Catch::Contains(path));
    CHECK_THROWS_AS(write_png(Image(4, 4), path), IoError);
}

TEST_CASE("`morphogen render` reads OBJ/OFF/PLY, validates options and reports bad files", "[render][cli]") {
    TempDir tmp;
    write_mesh(cube(1).view(), tmp.file("cube.obj"));
    write_mesh(icosahedron().view(), tmp.file("ico.ply"));
    write_mesh(cube(0.5).view(), tmp.file("small.off"));
    const std::string out = tmp.file("sheet.png");
    CHECK(run_cli({"render", tmp.file("cube.obj"), tmp.file("ico.ply"), tmp.file("small.off"), "-o", out,
                   "--columns", "2", "--size", "64"}) == 0);
    const auto [w, h] = png_size(out);
    CHECK(w == 128u);
    CHECK(h == 2u * static_cast<std::uint32_t>(sheet_cell_height(64)));

    CHECK_THROWS_AS(run_cli({"render", tmp.file("cube.obj"), "-o", out, "--size", "31"}), CLI::ValidationError);
    CHECK_THROWS_AS(run_cli({"render", tmp.file("cube.obj"), "-o", out, "--size", "4097"}), CLI::ValidationError);
    CHECK_THROWS_AS(run_cli({"render", tmp.file("cube.obj"), "-o", out, "--columns", "0"}), CLI::ValidationError);
    CHECK_THROWS_AS(run_cli({"render", tmp.file("cube.obj")}), CLI::RequiredError);
    CHECK_THROWS_WITH(run_cli({"render", tmp.file("missing.obj"), "-o", out}), Catch::Contains("missing.obj"));
    CHECK_THROWS_AS(run_cli({"render", tmp.file("missing.obj"), "-o", out}), IoError);
}

TEST_CASE("labels draw every glyph, however many segments they have", "[render]") {
    // Each glyph of "8008" is inked over its whole advance (stb_easy_font used
    // to run out of vertex buffer and drop the later glyphs and half a '0').
    for (const std::string text : {"800", "20", "0", "XXXXXXXX"}) {
        INFO(text);
        Image image(200, 20);
        draw_label(image, 0, 2, text, 2, 0);
        for (std::size_t i = 0; i < text.size(); ++i) {
            const int x0 = label_width(text.substr(0, i), 2);
            const int x1 = label_width(text.substr(0, i + 1), 2);
            int left = 0, right = 0;  // ink in the left and the right half of glyph i
            for (int y = 0; y < image.height; ++y)
                for (int x = x0; x < x1; ++x)
                    if (image.pixel(x, y)[0] < 128) ++(x < (x0 + x1) / 2 ? left : right);
            CAPTURE(i, left, right);
            CHECK(left > 0);
            CHECK(right > 0);
        }
    }
}
