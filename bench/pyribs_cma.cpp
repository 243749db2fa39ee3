#include "bench/pyribs_cma.hpp"

#include "evolution/emitters/cma/cma_rates.hpp"
#include "evolution/emitters/cma/eigen_views.hpp"


#include <algorithm>
#include <cmath>
#include <memory>
#include <unordered_map>

namespace morphogen {

using namespace eigen_views;

void pyribs_cma_update(FullCmaState& s, std::uint64_t& decomposed_at, std::span<const std::vector<double>* const> parents,
                       std::size_t lambda) {
    const std::size_t n = s.mean.size(), mu = parents.size();
    const CmaRates r = cma_rates(parents, n, /*separable=*/false);
    const Eigen::Index N = static_cast<Eigen::Index>(n);
    const double Nd = static_cast<double>(n);
    const ConstMatrixView basis(s.basis.data(), N, N);
    const ConstVectorView scales(s.scales.data(), N);

    // Unscaled steps x_k - m, no clip; the new mean.
    VectorView mean(s.mean.data(), N);
    Eigen::MatrixXd y(N, static_cast<Eigen::Index>(mu));
    Eigen::VectorXd shift = Eigen::VectorXd::Zero(N);
    for (std::size_t k = 0; k < mu; ++k) {
        const Eigen::Index col = static_cast<Eigen::Index>(k);
        y.col(col) = ConstVectorView(parents[k]->data(), N) - mean;
        shift += r.weights[k] * y.col(col);
    }
    mean += shift;

    // p_s with the (possibly stale) C^(-1/2); h_sigma and p_c as pyribs.
    VectorView path_sigma(s.path_sigma.data(), N), path_c(s.path_c.data(), N);
    const Eigen::VectorXd whitened = basis * (basis.transpose() * shift).cwiseQuotient(scales);
    path_sigma = (1.0 - r.cs) * path_sigma + (std::sqrt(r.cs * (2.0 - r.cs) * r.mueff) / s.sigma) * whitened;
    ++s.updates;
    const double ps2 = path_sigma.squaredNorm();
    const double left = ps2 / Nd / (1.0 - std::pow(1.0 - r.cs, 2.0 * static_cast<double>(s.updates)));
    const bool hsig = left < 2.0 + 4.0 / (Nd + 1.0);
    path_c = (1.0 - r.cc) * path_c + (hsig ? std::sqrt(r.cc * (2.0 - r.cc) * r.mueff) : 0.0) * shift;

    const double c1a = r.c1 * (1.0 - (hsig ? 0.0 : r.cc * (2.0 - r.cc)));
    const Eigen::VectorXd w = Eigen::Map<const Eigen::VectorXd>(r.weights.data(), static_cast<Eigen::Index>(mu));
    MatrixView c(s.covariance.data(), N, N);
    // pyribs multiplies its rank-one term by c1 twice (c1 * outer(pc, pc),
    // then * c1 again in _calc_cov_update): c1^2, about 4e-8 at n = 100.
    const RowMatrix next = (1.0 - c1a - r.cmu) * c + r.c1 * r.c1 * path_c * path_c.transpose() +
                           (r.cmu / (s.sigma * s.sigma)) * (y * w.asDiagonal() * y.transpose());
    c = 0.5 * (next + next.transpose());
    s.sigma *= std::exp(std::min(1.0, (r.cs / r.ds) * (ps2 / Nd - 1.0) / 2.0));

    // pyribs' lazy gap, with its rates for lambda / 2 parents.
    const CmaRates g = cma_rates_for(std::max<std::size_t>(1, lambda / 2), n, /*separable=*/false);
    const double gap = 0.5 * Nd * static_cast<double>(lambda) / (g.c1 + g.cmu) / (Nd * Nd);
    if (static_cast<double>(lambda) * static_cast<double>(s.updates - decomposed_at) > gap) {
        decomposed_at = s.updates;
        // If rounding made C indefinite, zero scales make the emitter restart (full_cma_converged).
        if (!full_cma_decompose(s)) {
            s.scales.assign(n, 0.0);
            s.basis.assign(n * n, 0.0);
        }
    }
}

FullCmaUpdate pyribs_full_update() {
    auto decomposed = std::make_shared<std::unordered_map<const FullCmaState*, std::uint64_t>>();
    return [decomposed](FullCmaState& state, std::span<const std::vector<double>* const> parents, std::size_t lambda) {
        std::uint64_t& at = (*decomposed)[&state];
        if (state.updates < at) at = 0;  // restarted since
        pyribs_cma_update(state, at, parents, lambda);
    };
}

}  // namespace morphogen
