// The leaf texture (see leaf_texture.hpp).
#include "engine/leaf_texture.hpp"

#include "core/base/errors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

// A C single-file library; static, so it cannot clash with report/render.cpp's copy.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace morphogen {

namespace {

// The leaf's half width at height y (0 base, 1 tip) with x across in
// [-1, 1]: a short stalk, then a blade pointed at both ends; 0 beyond it.
double half_width(double y) {
    if (y >= 0.0 && y < 0.14) return 0.045;  // the stalk
    const double s = (y - 0.1) / 0.88;
    if (s <= 0.0 || s >= 1.0) return 0.0;
    return 0.94 * std::pow(std::sin(std::numbers::pi * std::pow(s, 0.75)), 0.8);
}

// The blade's sRGB colour at (x, y): darker at the base, a pale midrib and side veins.
void leaf_colour(double x, double y, std::uint8_t* rgb) {
    const double ax = std::abs(x);
    double r = 58 + 30 * y, g = 112 + 40 * y, b = 34 + 10 * y;
    const double vein = std::abs(std::remainder(y * 7.0 - ax * 1.6, 1.0));
    if (ax < 0.035) r += 60, g += 55, b += 35;              // midrib
    else if (vein < 0.045) r += 22, g += 24, b += 12;       // side veins
    r -= 18 * ax, g -= 22 * ax, b -= 8 * ax;                // darker towards the edge
    rgb[0] = static_cast<std::uint8_t>(std::clamp(std::lround(r), 0L, 255L));
    rgb[1] = static_cast<std::uint8_t>(std::clamp(std::lround(g), 0L, 255L));
    rgb[2] = static_cast<std::uint8_t>(std::clamp(std::lround(b), 0L, 255L));
}

void append_bytes(void* context, void* data, int size) {
    auto* out = static_cast<std::string*>(context);
    out->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

std::vector<std::uint8_t> leaf_texture_rgba(int size) {
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 4);
    constexpr int kSub = 4;  // 4 x 4 samples a pixel: alpha is the leaf's coverage
    std::vector<double> widths(static_cast<std::size_t>(size) * kSub);  // per row of samples, from the top
    for (std::size_t r = 0; r < widths.size(); ++r)
        widths[r] = half_width(1.0 - (static_cast<double>(r) + 0.5) / (static_cast<double>(size) * kSub));
    for (int row = 0; row < size; ++row)
        for (int col = 0; col < size; ++col) {
            std::uint8_t* px = &pixels[(static_cast<std::size_t>(row) * static_cast<std::size_t>(size) +
                                        static_cast<std::size_t>(col)) * 4];
            int covered = 0;
            for (int i = 0; i < kSub; ++i)
                for (int j = 0; j < kSub; ++j)
                    covered += std::abs((col + (j + 0.5) / kSub) / size * 2.0 - 1.0) <
                               widths[static_cast<std::size_t>(row * kSub + i)];
            leaf_colour((col + 0.5) / size * 2.0 - 1.0, 1.0 - (row + 0.5) / size, px);  // outside too: no dark fringe in mipmaps
            px[3] = static_cast<std::uint8_t>((covered * 255 + kSub * kSub / 2) / (kSub * kSub));
        }
    return pixels;
}

std::string encode_leaf_texture_png() {
    const std::vector<std::uint8_t> pixels = leaf_texture_rgba(kLeafTextureSize);
    std::string bytes;
    if (!stbi_write_png_to_func(append_bytes, &bytes, kLeafTextureSize, kLeafTextureSize, 4, pixels.data(),
                                kLeafTextureSize * 4))
        throw IoError("leaf texture: cannot encode PNG");
    return bytes;
}

}  // namespace morphogen
