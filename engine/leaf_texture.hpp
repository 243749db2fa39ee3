#pragma once
// The leaf texture of foliage cards (leaf_cards.hpp): a leaf drawn by
// morphogen itself, RGBA with alpha 0 around its outline, embedded in the
// GLB as PNG. Its base is at the bottom row (v = 1), its tip at the top.
#include <cstdint>
#include <string>
#include <vector>

namespace morphogen {

inline constexpr int kLeafTextureSize = 128;  // a power of two: mipmaps in every engine

// size x size RGBA pixels, row by row from the top, sRGB colour: a pointed
// blade with a midrib and side veins on a short stalk. The same bytes every call.
std::vector<std::uint8_t> leaf_texture_rgba(int size = kLeafTextureSize);

// leaf_texture_rgba() as PNG bytes (stb_image_write), encoded every call.
std::string encode_leaf_texture_png();

// The PNG bytes every GLB with leaves embeds: encode_leaf_texture_png()'s,
// made when morphogen is built (leaf_texture_embed.cpp writes them into a
// source file), so an export pays nothing to draw or encode them.
const std::string& leaf_texture_png();

}  // namespace morphogen
