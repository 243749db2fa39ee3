#pragma once
// The strategy parameters CMA-ES derives from n and mu (Hansen, "The CMA
// Evolution Strategy: A Tutorial", 2016, Table 1), shared by the separable
// (sep_cma.hpp) and the full (full_cma.hpp) model.
#include <cstddef>
#include <span>
#include <vector>

namespace morphogen {

struct CmaRates {
    std::vector<double> weights;  // w_k ~ ln(mu + 1/2) - ln k, summing to 1
    double mueff = 1.0;           // 1 / sum w_k^2
    double cs = 0, ds = 0;        // step-size path rate and damping
    double cc = 0;                // covariance path rate
    double c1 = 0, cmu = 0;       // rank-one and rank-mu learning rates
    double chi = 0;               // E||N(0, I_n)||
    double max_length = 0;        // a step's Mahalanobis length is clipped to this (Hansen 2011)
};

// For an update from `parents` (mu = their number) in n dimensions;
// `separable`: c1 and cmu scaled by (n + 2) / 3 (Ros & Hansen 2008). Throws
// std::invalid_argument for no parents or one of another length than n.
CmaRates cma_rates(std::span<const std::vector<double>* const> parents, std::size_t n, bool separable);
// The same for mu parents, unchecked but for mu > 0.
CmaRates cma_rates_for(std::size_t mu, std::size_t n, bool separable);

}  // namespace morphogen
