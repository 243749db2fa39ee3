// Writes the labelled limb controls (tests/fitness/limb_controls.hpp) as OBJ
// files NAME-VERTICES.obj at every resolution the test uses, and their labels
// as labels.json, for `morphogen score --json` (experiments/2026-11-28-limb-measure-controls.md).
//   g++ -std=c++20 -O2 -I. -isystem /usr/include/eigen3 experiments/scripts/limb-controls/controls.cpp \
//       tests/fitness/limb_controls.cpp -o /tmp/controls -lgmp -lmpfr
//   /tmp/controls OUT_DIR [--grid]
// --grid: uniform marching-tetrahedra meshes instead, the grid chosen for
// about each count (no decimation), to see where a uniform grid loses limbs.
#include "tests/fitness/limb_controls.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

using namespace morphogen;
using namespace morphogen::testing;

int main(int argc, char** argv) {
    if (argc != 2 && !(argc == 3 && std::string(argv[2]) == "--grid")) {
        std::fputs("usage: controls OUT_DIR [--grid]\n", stderr);
        return 2;
    }
    const std::string out = argv[1];
    const bool grid = argc == 3;
    std::ofstream labels(out + "/labels.json");
    labels << "[\n";
    for (const LimbControl& c : limb_controls()) {
        std::vector<MeshArrays> meshes;
        if (grid) {
            const LimbControlSolid solid = limb_control_solid(c.name);
            const double coarse = 0.25;
            const double count = static_cast<double>(implicit_mesh(solid.field, solid.lo, solid.hi, coarse).positions.size());
            for (const int n : limb_control_resolutions())
                meshes.push_back(implicit_mesh(solid.field, solid.lo, solid.hi, coarse * std::sqrt(count / n)));
        } else {
            meshes = limb_control_meshes(c.name);
        }
        for (std::size_t i = 0; i < meshes.size(); ++i) {
            const MeshArrays& mesh = meshes[i];
            const int n = limb_control_resolutions()[i];
            std::ofstream obj(out + "/" + c.name + "-" + std::to_string(n) + ".obj");
            obj.precision(17);
            for (const Vec3& p : mesh.positions) obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
            for (const Face& f : mesh.faces) obj << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
            std::printf("%s-%d: %zu vertices\n", c.name.c_str(), n, mesh.positions.size());
        }
        labels << "  {\"name\": \"" << c.name << "\", \"tips\": " << c.tips << ", \"limbs\": " << c.limbs
               << ", \"fork_fraction\": " << c.fork_fraction << ", \"fork_tolerance\": " << c.fork_tolerance
               << (&c == &limb_controls().back() ? "}\n" : "},\n");
    }
    labels << "]\n";
    return 0;
}
