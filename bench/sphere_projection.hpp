#pragma once
// The sphere linear-projection benchmark of quality diversity (Fontaine et al.
// 2020 §4, used in the CMA-MAE paper's tables; docs/algorithm.md §9.10): a
// Problem with no meshes, so the emitters can be checked against the field's
// own numbers.
//   objective = 100 (s - worst) / (0 - worst), s = sum_i (x_i - 2.048)^2,
//               worst = n (-5.12 - 2.048)^2   (100 at the optimum x_i = 2.048)
//   clip(x) = x if |x| <= 5.12, else 5.12 / x
//   descriptors = (sum of clip(x_i) over the first n/2 parameters,
//                  sum over the rest)
// The papers' archive is 100 x 100 over [-5.12 n/2, 5.12 n/2]^2.
#include "evolution/archives/archive.hpp"
#include "evolution/problem.hpp"

#include <vector>

namespace morphogen {

class SphereProjection : public Problem {
public:
    explicit SphereProjection(std::size_t dimension);  // dimension >= 2
    std::size_t dimension() const override { return dimension_; }
    Evaluation evaluate(std::span<const double> params, int worker) const override;
    // The papers' grid: `bins` x `bins` over the descriptors' reachable range.
    std::vector<DescriptorRange> archive_ranges(int bins = 100) const;

private:
    std::size_t dimension_;
};

}  // namespace morphogen
