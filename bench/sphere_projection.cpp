#include "bench/sphere_projection.hpp"

#include <cmath>
#include <stdexcept>

namespace morphogen {

namespace {
constexpr double kBound = 5.12;
constexpr double kShift = 0.4 * kBound;
}  // namespace

SphereProjection::SphereProjection(std::size_t dimension) : dimension_(dimension) {
    if (dimension < 2) throw std::invalid_argument("the sphere benchmark needs at least 2 parameters");
}

Evaluation SphereProjection::evaluate(std::span<const double> x, int /*worker*/) const {
    const std::size_t n = dimension_, half = n / 2;
    double raw = 0.0, first = 0.0, second = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        raw += (x[i] - kShift) * (x[i] - kShift);
        const double clipped = std::fabs(x[i]) <= kBound ? x[i] : kBound / x[i];
        (i < half ? first : second) += clipped;
    }
    const double worst = static_cast<double>(n) * (-kBound - kShift) * (-kBound - kShift);
    Evaluation e;
    e.valid = true;
    e.score = (raw - worst) / (0.0 - worst) * 100.0;
    e.size = static_cast<double>(n);
    e.descriptors = {first, second};
    return e;
}

std::vector<DescriptorRange> SphereProjection::archive_ranges(int bins) const {
    const double reach = kBound * static_cast<double>(dimension_) / 2.0;
    return {{"first_half", -reach, reach, bins}, {"second_half", -reach, reach, bins}};
}

}  // namespace morphogen
