// Writes hand-built plant shapes as OBJ files, to score them with
// `morphogen score` under a fitness config and set them beside evolved bests:
// does the fitness prefer a tree (trunk, limbs, a crown on each) to a shrub
// of the same height? Built from tests/support/implicit_mesh.hpp.
//   g++ -std=c++20 -O2 -I. -isystem /usr/include/eigen3 experiments/scripts/tree-fitness-probe/shapes.cpp -o /tmp/shapes
//   /tmp/shapes OUT_DIR
#include "tests/support/implicit_mesh.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>

using namespace morphogen;
using namespace morphogen::testing;

namespace {

void write_obj(const MeshArrays& mesh, const std::string& path) {
    std::ofstream out(path);
    for (const Vec3& p : mesh.positions) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for (const Face& f : mesh.faces) out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
}

constexpr double kGrid = 0.2;
constexpr double kPi = std::numbers::pi;

// A crown at `c`: a sphere of radius r with `spikes` short shoots on its upper half.
double crown(const Vec3& p, const Vec3& c, double r, int spikes) {
    double f = sphere_field(p, c, r);
    for (int i = 0; i < spikes; ++i) {
        const double polar = 0.35 + 0.8 * (i % 2), azimuth = 2 * kPi * i / spikes;
        const Vec3 dir(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
        f = smooth_union(f, capsule_field(p, c + 0.7 * r * dir, c + (r + 1.0) * dir, 0.25), 0.1);
    }
    return f;
}

// A trunk to `fork` z, `limbs` limbs out to radius `spread` at z `top`, a crown on each.
MeshArrays tree(int limbs, double fork, double top, double spread, double crown_r, int spikes) {
    return implicit_mesh(
        [=](const Vec3& p) {
            double f = cylinder_field(p, {0, 0, 0}, 0.7, fork + 0.3);
            for (int i = 0; i < limbs; ++i) {
                const double a = 2 * kPi * i / limbs;
                const Vec3 end(spread * std::cos(a), spread * std::sin(a), top);
                f = smooth_union(f, capsule_field(p, {0, 0, fork}, end, 0.45), 0.2);
                f = smooth_union(f, crown(p, end, crown_r, spikes), 0.3);
            }
            return f;
        },
        {-spread - crown_r - 1.5, -spread - crown_r - 1.5, -0.5}, {spread + crown_r + 1.5, spread + crown_r + 1.5, top + crown_r + 1.5},
        kGrid);
}

// A shrub: a column of radius r to `height` with spikes all over its side.
MeshArrays spiky_column(double r, double height, int rings, int per_ring) {
    return implicit_mesh(
        [=](const Vec3& p) {
            double f = smooth_union(cylinder_field(p, {0, 0, 0}, r, height - r), sphere_field(p, {0, 0, height - r}, r), 0.2);
            for (int k = 0; k < rings; ++k)
                for (int i = 0; i < per_ring; ++i) {
                    const double z = height * (0.3 + 0.6 * k / std::max(1, rings - 1));
                    const double a = 2 * kPi * (i + 0.5 * k) / per_ring;
                    const Vec3 d(std::cos(a), std::sin(a), 0.8);
                    const Vec3 base(0.8 * r * std::cos(a), 0.8 * r * std::sin(a), z);
                    f = smooth_union(f, capsule_field(p, base, base + 1.6 * d.normalized(), 0.3), 0.1);
                }
            return f;
        },
        {-r - 2, -r - 2, -0.5}, {r + 2, r + 2, height + 1.5}, kGrid);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string usage =
        "usage: shapes OUT_DIR                                   the fixed set\n"
        "       shapes tree LIMBS FORK TOP SPREAD CROWN_R SPIKES OUT.obj\n"
        "       shapes column RADIUS HEIGHT RINGS PER_RING OUT.obj\n";
    const std::string kind = argc > 1 ? argv[1] : ".";
    if (kind == "tree" && argc == 9) {
        write_obj(tree(std::stoi(argv[2]), std::stod(argv[3]), std::stod(argv[4]), std::stod(argv[5]), std::stod(argv[6]),
                       std::stoi(argv[7])),
                  argv[8]);
        return 0;
    }
    if (kind == "column" && argc == 7) {
        write_obj(spiky_column(std::stod(argv[2]), std::stod(argv[3]), std::stoi(argv[4]), std::stoi(argv[5])), argv[6]);
        return 0;
    }
    if (argc != 2 || kind == "tree" || kind == "column") {
        std::fputs(usage.c_str(), stderr);
        return 2;
    }
    const std::string out = kind;
    write_obj(tree(3, 6.0, 10.5, 3.5, 2.0, 0), out + "/tree3-smooth.obj");
    write_obj(tree(3, 6.0, 10.5, 3.5, 2.0, 6), out + "/tree3-spiky.obj");
    write_obj(tree(5, 5.0, 10.5, 4.0, 1.8, 6), out + "/tree5-spiky.obj");
    write_obj(tree(5, 5.0, 10.5, 4.5, 2.4, 10), out + "/tree5-big.obj");
    write_obj(spiky_column(2.5, 14.0, 3, 5), out + "/column-spiky.obj");
    write_obj(spiky_column(3.5, 12.0, 3, 6), out + "/shrub-spiky.obj");
    return 0;
}
