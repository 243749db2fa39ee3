#pragma once
// A small software rasteriser (no GPU, no OpenGL) for looking at grown meshes:
// one fixed three-quarter view from above, smooth Lambert + ambient shading
// (normals interpolated across each face, creases kept: corner_normals.hpp)
// with two-sided lighting (|n.l|, so inside-out faces still read), a z-buffer,
// SxS supersampling, and a ground plate at z = 0 carrying the mesh's vertical
// footprint as a shadow (the area the canopy fitness measures).
//
// Camera: orthographic. It sits at elevation `elevation_deg` above the
// horizon, and its azimuth is measured around +z from the -y axis (0 = front
// view looking along +y). Meshes are Z-up. Every mesh is centred on its cell
// by the centre of its xy bounding box; z is kept, so the ground (z = 0) of
// every cell lies on the same image row.
#include "core/mesh/mesh.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

struct RenderOptions {
    int size = 256;             // width and height of one picture, pixels (32..4096)
    int columns = 5;            // cells per row of a contact sheet (>= 1)
    bool shared_scale = true;   // one scale for all meshes (fits the largest), so sizes compare
    int supersample = 2;        // SxS samples per pixel (1..4), box-filtered
    double elevation_deg = 25;  // camera above the horizon
    double azimuth_deg = -35;   // camera around +z, from the front (-y) view
    double crease_deg = 60;     // faces bending more than this from a neighbour keep a sharp edge (0: flat shading)
};

// An 8-bit RGB image, rows top to bottom, 3 bytes per pixel.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;

    Image() = default;
    Image(int w, int h, std::uint8_t fill = 255)
        : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, fill) {}
    std::uint8_t* pixel(int x, int y) { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
    const std::uint8_t* pixel(int x, int y) const {
        return &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
    }
};

// Vertex colours, where given: 4 linear floats per vertex (RGBA, as
// engine/plant_colour.hpp makes them; A is ignored), sRGB-encoded and
// interpolated across each face, then shaded. Empty: the plain plant green.

// One mesh alone, framed to fill an options.size square picture. Non-finite
// vertices and the faces using them are skipped. Throws std::invalid_argument
// for options out of range or colours that are not empty or 4 per vertex.
Image render_mesh(MeshView mesh, const RenderOptions& options, std::span<const float> colours = {});

// A grid of min(options.columns, meshes.size()) columns (at least one):
// columns * size pixels wide, sheet_cell_height(size) per row high. Each cell
// is the mesh's picture with a caption under it (captions[i], or "#i" where
// captions is empty). With shared_scale all meshes are drawn at the scale that
// fits the largest one, and their ground (z = 0) is on the same row.
// colours: empty, or one entry per mesh (each empty or 4 per vertex).
// Throws std::invalid_argument if captions is neither empty nor one per mesh.
Image render_sheet(std::span<const MeshArrays> meshes, std::span<const std::string> captions,
                   const RenderOptions& options, std::span<const std::vector<float>> colours = {});

// Height of one sheet cell: the size x size picture plus its caption line.
int sheet_cell_height(int size);

// Text in the sheets' 7-pixel vector font scaled by `scale`, its top-left
// corner at (x, y), clipped to the image; and its width in pixels.
void draw_label(Image& image, int x, int y, const std::string& text, int scale, std::uint8_t grey);
int label_width(const std::string& text, int scale);

// Writes `image` as a PNG; throws IoError("<path>: ...") on failure.
void write_png(const Image& image, const std::string& path);

// render_sheet + write_png.
void render_contact_sheet(std::span<const MeshArrays> meshes, std::span<const std::string> captions,
                          const std::string& png_path, const RenderOptions& options,
                          std::span<const std::vector<float>> colours = {});

}  // namespace morphogen
