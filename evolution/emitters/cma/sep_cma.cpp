#include "evolution/emitters/cma/sep_cma.hpp"

#include "evolution/emitters/cma/cma_rates.hpp"

#include <algorithm>
#include <cmath>

namespace morphogen {

SepCmaState sep_cma_start(std::vector<double> mean, double sigma) {
    SepCmaState s;
    const std::size_t n = mean.size();
    s.mean = std::move(mean);
    s.variances.assign(n, 1.0);
    s.path_c.assign(n, 0.0);
    s.path_sigma.assign(n, 0.0);
    s.sigma = sigma;
    return s;
}

std::vector<double> sep_cma_sample(const SepCmaState& state, RandomStream& stream) {
    std::vector<double> x(state.mean.size());
    for (std::size_t i = 0; i < x.size(); ++i)
        x[i] = state.mean[i] + state.sigma * std::sqrt(state.variances[i]) * stream.normal();
    return x;
}

void sep_cma_update(SepCmaState& s, std::span<const std::vector<double>* const> parents) {
    const std::size_t n = s.mean.size(), mu = parents.size();
    const CmaRates rates = cma_rates(parents, n, /*separable=*/true);
    const std::vector<double>& w = rates.weights;
    const double N = static_cast<double>(n), mueff = rates.mueff, cs = rates.cs, ds = rates.ds, cc = rates.cc;
    const double c1 = rates.c1, cmu = rates.cmu, chi = rates.chi;

    // Steps y_k = (x_k - m) / sigma, clipped in Mahalanobis length.
    const double max_length = rates.max_length;
    std::vector<std::vector<double>> y(mu, std::vector<double>(n));
    std::vector<double> yw(n, 0.0);
    for (std::size_t k = 0; k < mu; ++k) {
        double length2 = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            y[k][i] = ((*parents[k])[i] - s.mean[i]) / s.sigma;
            length2 += y[k][i] * y[k][i] / s.variances[i];
        }
        const double length = std::sqrt(length2);
        if (length > max_length)
            for (double& v : y[k]) v *= max_length / length;
        for (std::size_t i = 0; i < n; ++i) yw[i] += w[k] * y[k][i];
    }

    // Mean, then the paths (C^(-1/2) y_w is y_w / sqrt(c_ii) for a diagonal C).
    for (std::size_t i = 0; i < n; ++i) s.mean[i] += s.sigma * yw[i];
    const double ps_rate = std::sqrt(cs * (2.0 - cs) * mueff);
    double ps2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        s.path_sigma[i] = (1.0 - cs) * s.path_sigma[i] + ps_rate * yw[i] / std::sqrt(s.variances[i]);
        ps2 += s.path_sigma[i] * s.path_sigma[i];
    }
    const double ps_norm = std::sqrt(ps2);
    ++s.updates;
    const double correction = std::sqrt(1.0 - std::pow(1.0 - cs, 2.0 * static_cast<double>(s.updates)));
    const bool hsig = ps_norm / correction < (1.4 + 2.0 / (N + 1.0)) * chi;
    const double pc_rate = hsig ? std::sqrt(cc * (2.0 - cc) * mueff) : 0.0;
    for (std::size_t i = 0; i < n; ++i) s.path_c[i] = (1.0 - cc) * s.path_c[i] + pc_rate * yw[i];

    // Covariance (rank-one and rank-mu), then the step size (its exponent
    // capped at 1 as in pycma, so one update at most multiplies sigma by e).
    const double keep = 1.0 - c1 - cmu + (hsig ? 0.0 : c1 * cc * (2.0 - cc));
    for (std::size_t i = 0; i < n; ++i) {
        double rank_mu = 0.0;
        for (std::size_t k = 0; k < mu; ++k) rank_mu += w[k] * y[k][i] * y[k][i];
        s.variances[i] = keep * s.variances[i] + c1 * s.path_c[i] * s.path_c[i] + cmu * rank_mu;
    }
    s.sigma *= std::exp(std::min(1.0, (cs / ds) * (ps_norm / chi - 1.0)));
}

bool sep_cma_converged(const SepCmaState& s) {
    if (!(s.sigma > 0.0) || !std::isfinite(s.sigma)) return true;
    double low = s.variances.empty() ? 1.0 : s.variances.front(), high = low;
    for (double v : s.variances) {
        if (!(v > 0.0) || !std::isfinite(v)) return true;
        low = std::min(low, v);
        high = std::max(high, v);
    }
    return s.sigma * std::sqrt(high) < 1e-11 || high > 1e14 * low;
}

}  // namespace morphogen
