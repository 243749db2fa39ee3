// A build step: writes the leaf texture's PNG bytes (encode_leaf_texture_png)
// into a C++ source that defines leaf_texture_png(), so morphogen embeds what
// its own drawing makes without drawing and encoding it in every process.
// Usage: leaf_texture_embed OUT.cpp
#include "engine/leaf_texture.hpp"

#include <cstdio>
#include <fstream>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUT.cpp\n", argv[0]);
        return 2;
    }
    const std::string png = morphogen::encode_leaf_texture_png();
    std::ofstream out(argv[1], std::ios::trunc);
    out << "// Written by engine/leaf_texture_embed.cpp when morphogen is built: do not edit.\n"
           "#include \"engine/leaf_texture.hpp\"\n\nnamespace morphogen {\nnamespace {\n"
           "constexpr unsigned char kLeafTexturePng[] = {";
    for (std::size_t i = 0; i < png.size(); ++i)
        out << (i % 20 == 0 ? "\n    " : " ") << static_cast<int>(static_cast<unsigned char>(png[i])) << ",";
    out << "\n};\n}  // namespace\n\nconst std::string& leaf_texture_png() {\n"
           "    static const std::string png(reinterpret_cast<const char*>(kLeafTexturePng), sizeof kLeafTexturePng);\n"
           "    return png;\n}\n\n}  // namespace morphogen\n";
    out.close();
    if (!out) {
        std::fprintf(stderr, "%s: cannot write\n", argv[1]);
        return 1;
    }
    return 0;
}
