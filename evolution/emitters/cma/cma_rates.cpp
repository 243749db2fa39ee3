#include "evolution/emitters/cma/cma_rates.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace morphogen {

CmaRates cma_rates(std::span<const std::vector<double>* const> parents, std::size_t n, bool separable) {
    for (const std::vector<double>* p : parents)
        if (p->size() != n) throw std::invalid_argument("a CMA parent has the wrong number of parameters");
    return cma_rates_for(parents.size(), n, separable);
}

CmaRates cma_rates_for(std::size_t mu, std::size_t n, bool separable) {
    if (mu == 0) throw std::invalid_argument("a CMA update needs at least one parent");
    const double N = static_cast<double>(n);
    CmaRates r;
    r.weights.resize(mu);
    double wsum = 0.0;
    for (std::size_t k = 0; k < mu; ++k) {
        r.weights[k] = std::log(static_cast<double>(mu) + 0.5) - std::log(static_cast<double>(k + 1));
        wsum += r.weights[k];
    }
    double w2 = 0.0;
    for (double& v : r.weights) {
        v /= wsum;
        w2 += v * v;
    }
    const double mueff = 1.0 / w2;
    r.mueff = mueff;
    r.cs = (mueff + 2.0) / (N + mueff + 5.0);
    r.ds = 1.0 + 2.0 * std::max(0.0, std::sqrt((mueff - 1.0) / (N + 1.0)) - 1.0) + r.cs;
    r.cc = (4.0 + mueff / N) / (N + 4.0 + 2.0 * mueff / N);
    const double c1_full = 2.0 / ((N + 1.3) * (N + 1.3) + mueff);
    const double cmu_full = std::min(1.0 - c1_full, 2.0 * (mueff - 2.0 + 1.0 / mueff) / ((N + 2.0) * (N + 2.0) + mueff));
    r.c1 = separable ? std::min(1.0, c1_full * (N + 2.0) / 3.0) : c1_full;
    r.cmu = separable ? std::min(1.0 - r.c1, cmu_full * (N + 2.0) / 3.0) : cmu_full;
    r.chi = std::sqrt(N) * (1.0 - 1.0 / (4.0 * N) + 1.0 / (21.0 * N * N));
    r.max_length = std::sqrt(N) + 2.0 * N / (N + 2.0);
    return r;
}

}  // namespace morphogen
