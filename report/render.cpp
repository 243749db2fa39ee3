// Software rasteriser and contact sheets (see render.hpp).
#include "report/render.hpp"

#include "core/base/errors.hpp"
#include "core/base/parallel_for.hpp"
#include "core/io/mesh_file_types.hpp"
#include "report/corner_normals.hpp"

#include <Eigen/Geometry>

// Both stb headers are C single-file libraries; the PNG writer is compiled
// here (static, so it cannot clash with the copy inside libtinygltf).
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#include <stb/stb_easy_font.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace morphogen {
namespace {

using Rgb = Eigen::Array3f;

// Palette: a light plant green on a warm grey ground plate, white background.
const Rgb kPlant{0.50f, 0.76f, 0.38f};
const Rgb kPlate{0.90f, 0.90f, 0.87f};
const Rgb kBackground{1.0f, 1.0f, 1.0f};
constexpr float kAmbient = 0.42f;
constexpr float kDiffuse = 0.58f;
constexpr float kShadow = 0.80f;        // plate brightness factor under the footprint
constexpr double kMargin = 0.05;        // of the cell size, on every side
constexpr double kPlateRadius = 0.45;   // of the cell size, in pixels across
constexpr std::uint8_t kCaptionGrey = 70;
constexpr std::uint8_t kGridGrey = 225;

void check_options(const RenderOptions& o) {
    if (o.size < 32 || o.size > 4096)
        throw std::invalid_argument("render size must be in [32, 4096], got " + std::to_string(o.size));
    if (o.columns < 1) throw std::invalid_argument("render columns must be >= 1, got " + std::to_string(o.columns));
    if (o.supersample < 1 || o.supersample > 4)
        throw std::invalid_argument("render supersample must be in [1, 4], got " + std::to_string(o.supersample));
    if (!(o.crease_deg >= 0 && o.crease_deg <= 180))
        throw std::invalid_argument("render crease angle must be in [0, 180] degrees, got " + std::to_string(o.crease_deg));
}

struct Camera {
    Vec3 right, up, forward;  // orthonormal; forward points into the picture
    Vec3 light;               // unit vector towards the light
    double sin_elevation;
};

Camera make_camera(const RenderOptions& o) {
    const double el = o.elevation_deg * std::numbers::pi / 180;
    const double az = o.azimuth_deg * std::numbers::pi / 180;
    // Towards the camera: the front direction -y turned by az around +z, raised by el.
    const Vec3 to_camera(std::cos(el) * std::sin(az), -std::cos(el) * std::cos(az), std::sin(el));
    Camera c;
    c.forward = -to_camera;
    c.right = c.forward.cross(Vec3::UnitZ()).normalized();
    c.up = c.right.cross(c.forward);
    // Key light from above, a little left of and behind the camera.
    c.light = (0.8 * Vec3::UnitZ() + 0.7 * to_camera - 0.4 * c.right).normalized();
    c.sin_elevation = std::sin(el);
    return c;
}

bool finite(const Vec3& p) { return p.allFinite(); }

// Where a mesh sits: the centre of its xy bounding box, and how far it reaches
// on screen from that centre at z = 0 (in world units).
struct Placement {
    Vec3 centre = Vec3::Zero();
    double half_width = 0, top = 0, bottom = 0;
    bool empty = true;
};

Placement place(MeshView mesh, const Camera& cam) {
    Placement pl;
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Vec3& p : mesh.positions)
        if (finite(p)) {
            lo = lo.cwiseMin(p.head<2>());
            hi = hi.cwiseMax(p.head<2>());
            pl.empty = false;
        }
    if (pl.empty) return pl;
    pl.centre = Vec3(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), 0);
    for (const Vec3& p : mesh.positions)
        if (finite(p)) {
            const Vec3 q = p - pl.centre;
            pl.half_width = std::max(pl.half_width, std::abs(q.dot(cam.right)));
            pl.top = std::max(pl.top, q.dot(cam.up));
            pl.bottom = std::max(pl.bottom, -q.dot(cam.up));
        }
    return pl;
}

// Pixels per world unit and the image row of the ground point under the centre.
struct Frame {
    double scale = 1;
    double ground_row = 0;
};

// The largest scale at which every placement fits the cell with its margins,
// leaving room under the ground row for the plate; then centred vertically.
Frame fit(std::span<const Placement> placements, int size, const Camera& cam) {
    double half_width = 0, top = 0, bottom = 0;
    for (const Placement& p : placements) {
        half_width = std::max(half_width, p.half_width);
        top = std::max(top, p.top);
        bottom = std::max(bottom, p.bottom);
    }
    const double margin = kMargin * size;
    const double usable = size - 2 * margin;
    const double plate_below = kPlateRadius * size * cam.sin_elevation;
    constexpr double tiny = 1e-300;
    Frame f;
    f.scale = std::min({(0.5 * size - margin) / std::max(half_width, tiny),
                        usable / std::max(top + bottom, tiny),
                        (usable - plate_below) / std::max(top, tiny)});
    if (!std::isfinite(f.scale) || f.scale <= 0 || f.scale > 1e12) f.scale = 1;  // empty or a point
    const double used = f.scale * top + std::max(f.scale * bottom, plate_below);
    f.ground_row = margin + f.scale * top + std::max(0.0, usable - used) / 2;
    return f;
}

// Which points of the plate (a square of half-width `radius` around the
// mesh centre, `n` x `n` cells) lie under the mesh, seen from straight above.
class Footprint {
public:
    Footprint(MeshView mesh, const Vec3& centre, double radius, int n)
        : centre_(centre), radius_(radius), n_(n), covered_(static_cast<std::size_t>(n) * n, 0) {
        for (const Face& f : mesh.faces) add(mesh.positions[f[0]], mesh.positions[f[1]], mesh.positions[f[2]]);
    }
    bool covers(double x, double y) const {
        const int i = cell(x - centre_.x()), j = cell(y - centre_.y());
        return i >= 0 && j >= 0 && i < n_ && j < n_ && covered_[static_cast<std::size_t>(j) * n_ + i];
    }

private:
    int cell(double d) const { return static_cast<int>(std::floor((d + radius_) / (2 * radius_) * n_)); }
    double centre_of(int i) const { return (i + 0.5) / n_ * 2 * radius_ - radius_; }

    void add(const Vec3& a3, const Vec3& b3, const Vec3& c3) {
        if (!finite(a3) || !finite(b3) || !finite(c3)) return;
        const Eigen::Vector2d a = (a3 - centre_).head<2>(), b = (b3 - centre_).head<2>(), c = (c3 - centre_).head<2>();
        const double area = cross(b - a, c - a);
        if (std::abs(area) < 1e-300) return;
        const int i0 = std::max(0, cell(std::min({a.x(), b.x(), c.x()}))),
                  i1 = std::min(n_ - 1, cell(std::max({a.x(), b.x(), c.x()})));
        const int j0 = std::max(0, cell(std::min({a.y(), b.y(), c.y()}))),
                  j1 = std::min(n_ - 1, cell(std::max({a.y(), b.y(), c.y()})));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const Eigen::Vector2d p(centre_of(i), centre_of(j));
                const double w0 = cross(c - b, p - b) / area, w1 = cross(a - c, p - c) / area,
                             w2 = cross(b - a, p - a) / area;
                if (w0 >= 0 && w1 >= 0 && w2 >= 0) covered_[static_cast<std::size_t>(j) * n_ + i] = 1;
            }
    }
    static double cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

    Vec3 centre_;
    double radius_;
    int n_;
    std::vector<std::uint8_t> covered_;
};

// Supersampled colour + depth buffer of one picture.
struct SampleBuffer {
    int n;  // samples per side
    std::vector<Rgb> colour;
    std::vector<float> depth;
    explicit SampleBuffer(int side)
        : n(side), colour(static_cast<std::size_t>(side) * side, kBackground),
          depth(static_cast<std::size_t>(side) * side, std::numeric_limits<float>::infinity()) {}
};

// What a triangle's corners carry: their colour, unlit, and their shading
// normal's dot with the light (linear across the face, as the normal is).
struct Corners {
    std::array<Rgb, 3> colour;
    std::array<Vec3, 3> normal;
    std::array<double, 3> towards_light;
};

// Two-sided Lambert plus ambient for a normal n (not unit): |n.l| / |n|, so
// faces seen from inside are lit like outside.
float light_of(const Vec3& n, double n_dot_l) {
    const double len = n.norm();
    return kAmbient + kDiffuse * static_cast<float>(len > 0 ? std::min(1.0, std::abs(n_dot_l) / len) : 0);
}

// Fills the triangle's samples that are nearer than what is there, each lit
// by the corners' normals interpolated to it (smooth shading) and coloured
// by their colours interpolated.
void raster_triangle(SampleBuffer& buf, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                     const Eigen::Vector3d& c, const Corners& corner) {
    const auto edge = [](const Eigen::Vector3d& u, const Eigen::Vector3d& v, double x, double y) {
        return (v.x() - u.x()) * (y - u.y()) - (v.y() - u.y()) * (x - u.x());
    };
    const double area = edge(a, b, c.x(), c.y());
    if (!(std::abs(area) > 1e-12)) return;  // degenerate on screen (or NaN)
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
    const int x1 = std::min(buf.n - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
    const int y1 = std::min(buf.n - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            // Barycentrics divided by the signed area: positive inside for either winding.
            const double w0 = edge(b, c, px, py) / area, w1 = edge(c, a, px, py) / area,
                         w2 = edge(a, b, px, py) / area;
            if (w0 < 0 || w1 < 0 || w2 < 0) continue;
            const auto d = static_cast<float>(w0 * a.z() + w1 * b.z() + w2 * c.z());
            const std::size_t k = static_cast<std::size_t>(y) * buf.n + x;
            if (d < buf.depth[k]) {
                buf.depth[k] = d;
                const float light = light_of(w0 * corner.normal[0] + w1 * corner.normal[1] + w2 * corner.normal[2],
                                             w0 * corner.towards_light[0] + w1 * corner.towards_light[1] +
                                                 w2 * corner.towards_light[2]);
                buf.colour[k] = light * (static_cast<float>(w0) * corner.colour[0] + static_cast<float>(w1) * corner.colour[1] +
                                         static_cast<float>(w2) * corner.colour[2]);
            }
        }
}

Image downsample(const SampleBuffer& buf, const RenderOptions& o);

// The vertex colours as the picture's (sRGB) colours; empty for none.
std::vector<Rgb> picture_colours(MeshView mesh, std::span<const float> colours) {
    if (colours.empty()) return {};
    if (colours.size() != 4 * mesh.positions.size())
        throw std::invalid_argument("render: " + std::to_string(colours.size()) + " colour values for " +
                                    std::to_string(mesh.positions.size()) + " vertices (4 per vertex)");
    std::vector<Rgb> out(mesh.positions.size());
    for (std::size_t v = 0; v < out.size(); ++v)
        for (int c = 0; c < 3; ++c)
            out[v][c] = static_cast<float>(srgb_encode(std::clamp(static_cast<double>(colours[4 * v + c]), 0.0, 1.0)));
    return out;
}

// Draws one mesh at frame `frame`, its xy centre `centre` at the cell's middle.
Image render_framed(MeshView mesh, const Vec3& centre, const Frame& frame, const Camera& cam,
                    const RenderOptions& o, std::span<const float> vertex_colours) {
    const std::vector<Rgb> colours = picture_colours(mesh, vertex_colours);
    const int s = o.supersample;
    SampleBuffer buf(o.size * s);
    // Screen position in samples (x right, y down) and depth along the view.
    const auto project = [&](const Vec3& p) {
        const Vec3 q = p - centre;
        return Eigen::Vector3d(s * (0.5 * o.size + frame.scale * q.dot(cam.right)),
                               s * (frame.ground_row - frame.scale * q.dot(cam.up)), q.dot(cam.forward));
    };
    const std::vector<std::array<Vec3, 3>> normals = corner_normals(mesh, o.crease_deg);
    for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
        const Face& f = mesh.faces[i];
        const Vec3 &a = mesh.positions[f[0]], &b = mesh.positions[f[1]], &c = mesh.positions[f[2]];
        if (!finite(a) || !finite(b) || !finite(c)) continue;
        Corners corner{{kPlant, kPlant, kPlant}, normals[i], {}};
        for (int k = 0; k < 3; ++k) {
            if (!colours.empty()) corner.colour[k] = colours[f[k]];
            corner.towards_light[k] = normals[i][k].dot(cam.light);
        }
        raster_triangle(buf, project(a), project(b), project(c), corner);
    }

    // Ground plate under what the mesh left uncovered: it is always behind a
    // mesh standing on z >= 0 (the view ray descends), so no depth test. An
    // empty mesh gets an empty cell.
    if (mesh.faces.empty()) return downsample(buf, o);
    const double plate_radius = kPlateRadius * o.size / frame.scale;  // world units
    const Footprint footprint(mesh, centre, plate_radius, std::max(64, o.size));
    const double t_per_up = cam.up.z() / cam.sin_elevation;  // along forward, to reach z = 0
    for (int y = 0; y < buf.n; ++y)
        for (int x = 0; x < buf.n; ++x) {
            const std::size_t k = static_cast<std::size_t>(y) * buf.n + x;
            if (buf.depth[k] != std::numeric_limits<float>::infinity()) continue;
            const double sx = ((x + 0.5) / s - 0.5 * o.size) / frame.scale;
            const double sy = (frame.ground_row - (y + 0.5) / s) / frame.scale;
            const Vec3 g = sx * cam.right + sy * cam.up + sy * t_per_up * cam.forward;  // g.z == 0
            const double r2 = g.head<2>().squaredNorm() / (plate_radius * plate_radius);
            if (r2 >= 1) continue;
            // Fades to the background at the rim so the plate reads as a floor, not a disc.
            const float fade = static_cast<float>(1 - r2 * r2);
            const bool shade = footprint.covers(g.x() + centre.x(), g.y() + centre.y());
            const Rgb plate = shade ? Rgb(kPlate * kShadow) : kPlate;
            buf.colour[k] = kBackground + fade * (plate - kBackground);
        }
    return downsample(buf, o);
}

// Box filter: one pixel per SxS samples.
Image downsample(const SampleBuffer& buf, const RenderOptions& o) {
    const int s = o.supersample;
    Image img(o.size, o.size);
    const float norm = 255.0f / static_cast<float>(s * s);
    for (int y = 0; y < o.size; ++y)
        for (int x = 0; x < o.size; ++x) {
            Rgb sum = Rgb::Zero();
            for (int dy = 0; dy < s; ++dy)
                for (int dx = 0; dx < s; ++dx) sum += buf.colour[static_cast<std::size_t>(y * s + dy) * buf.n + x * s + dx];
            for (int c = 0; c < 3; ++c)
                img.pixel(x, y)[c] = static_cast<std::uint8_t>(std::clamp(sum[c] * norm + 0.5f, 0.0f, 255.0f));
        }
    return img;
}

// Text with stb_easy_font (a 7-pixel-high vector font made of quads), scaled
// by an integer factor; `x`, `y` is the top-left corner.
int text_width(const std::string& text, int scale) {
    return stb_easy_font_width(const_cast<char*>(text.c_str())) * scale;
}

void draw_text(Image& img, int x, int y, const std::string& text, int scale, std::uint8_t grey) {
    // One 64-byte quad per segment and at most 11 segments per glyph ('X');
    // stb_easy_font silently drops what does not fit, which cut off the
    // later glyphs of labels such as "800" and the right half of a '0'.
    std::vector<char> quads(text.size() * 11 * 64 + 64);
    unsigned char colour[4] = {grey, grey, grey, 255};
    const int n = stb_easy_font_print(0, 0, const_cast<char*>(text.c_str()), colour, quads.data(),
                                      static_cast<int>(quads.size()));
    // 4 vertices per quad, 16 bytes per vertex: float x, y, z, then 4 colour bytes.
    for (int q = 0; q < n; ++q) {
        float v0[2], v2[2];
        std::memcpy(v0, quads.data() + q * 64, sizeof v0);
        std::memcpy(v2, quads.data() + q * 64 + 32, sizeof v2);
        for (int py = y + static_cast<int>(v0[1]) * scale; py < y + static_cast<int>(v2[1]) * scale; ++py)
            for (int px = x + static_cast<int>(v0[0]) * scale; px < x + static_cast<int>(v2[0]) * scale; ++px)
                if (px >= 0 && py >= 0 && px < img.width && py < img.height) {
                    std::uint8_t* p = img.pixel(px, py);
                    p[0] = p[1] = p[2] = grey;
                }
    }
}

// Shortens `text` with ".." until it fits `width` pixels.
std::string fit_text(std::string text, int width, int scale) {
    if (text_width(text, scale) <= width) return text;
    while (!text.empty() && text_width(text + "..", scale) > width) text.pop_back();
    return text + "..";
}

// "#i"; built with append, since GCC 12 warns falsely (-Wrestrict) on "#" + std::string.
std::string index_caption(int i) {
    std::string text = "#";
    text += std::to_string(i);
    return text;
}

int caption_scale(int size) { return 1 + size / 400; }
int caption_height(int size) { return 7 * caption_scale(size) + 8; }

void blit(Image& dst, const Image& src, int x0, int y0) {
    for (int y = 0; y < src.height; ++y)
        std::copy_n(src.pixel(0, y), 3 * src.width, dst.pixel(x0, y0 + y));
}

}  // namespace

void draw_label(Image& image, int x, int y, const std::string& text, int scale, std::uint8_t grey) {
    draw_text(image, x, y, text, scale, grey);
}
int label_width(const std::string& text, int scale) { return text_width(text, scale); }

int sheet_cell_height(int size) { return size + caption_height(size); }

Image render_mesh(MeshView mesh, const RenderOptions& options, std::span<const float> colours) {
    check_options(options);
    const Camera cam = make_camera(options);
    const Placement pl = place(mesh, cam);
    return render_framed(mesh, pl.centre, fit(std::span(&pl, 1), options.size, cam), cam, options, colours);
}

Image render_sheet(std::span<const MeshArrays> meshes, std::span<const std::string> captions,
                   const RenderOptions& options, std::span<const std::vector<float>> colours) {
    check_options(options);
    if (!captions.empty() && captions.size() != meshes.size())
        throw std::invalid_argument("render_sheet: " + std::to_string(captions.size()) + " captions for " +
                                    std::to_string(meshes.size()) + " meshes");
    if (!colours.empty() && colours.size() != meshes.size())
        throw std::invalid_argument("render_sheet: " + std::to_string(colours.size()) + " colour lists for " +
                                    std::to_string(meshes.size()) + " meshes");
    const Camera cam = make_camera(options);
    const int n = static_cast<int>(meshes.size());
    std::vector<Placement> placements(meshes.size());
    for (int i = 0; i < n; ++i) placements[i] = place(meshes[i].view(), cam);
    const Frame shared = fit(placements, options.size, cam);

    const int size = options.size;
    const int columns = std::max(1, std::min(options.columns, n));
    const int rows = (n + columns - 1) / columns;
    const int cell_h = sheet_cell_height(size);
    Image sheet(columns * size, std::max(1, rows) * cell_h);

    // Cells are disjoint: no race.
    parallel_for(meshes.size(), resolve_threads(0), [&](std::size_t index, int) {
        const int i = static_cast<int>(index);
        const Frame frame = options.shared_scale ? shared : fit(std::span(&placements[i], 1), size, cam);
        const Image cell = render_framed(meshes[i].view(), placements[i].centre, frame, cam, options,
                                         colours.empty() ? std::span<const float>{} : std::span<const float>(colours[index]));
        const int x0 = (i % columns) * size, y0 = (i / columns) * cell_h;
        blit(sheet, cell, x0, y0);
        const int scale = caption_scale(size);
        const std::string text = fit_text(captions.empty() ? index_caption(i) : captions[i], size - 8, scale);
        draw_text(sheet, x0 + (size - text_width(text, scale)) / 2, y0 + size + 3, text, scale, kCaptionGrey);
    });

    // Thin grid lines between cells.
    for (int c = 1; c < columns; ++c)
        for (int y = 0; y < sheet.height; ++y) std::fill_n(sheet.pixel(c * size, y), 3, kGridGrey);
    for (int r = 1; r < rows; ++r) std::fill_n(sheet.pixel(0, r * cell_h), 3 * sheet.width, kGridGrey);
    return sheet;
}

void write_png(const Image& image, const std::string& path) {
    if (image.width <= 0 || image.height <= 0) throw IoError(path + ": cannot write an empty image");
    if (!stbi_write_png(path.c_str(), image.width, image.height, 3, image.rgb.data(), image.width * 3)) {
        std::error_code ignored;
        if (std::filesystem::is_regular_file(path, ignored)) std::filesystem::remove(path, ignored);
        throw IoError(path + ": cannot write PNG (missing directory, no permission or disk full?)");
    }
}

void render_contact_sheet(std::span<const MeshArrays> meshes, std::span<const std::string> captions,
                          const std::string& png_path, const RenderOptions& options,
                          std::span<const std::vector<float>> colours) {
    write_png(render_sheet(meshes, captions, options, colours), png_path);
}

}  // namespace morphogen
