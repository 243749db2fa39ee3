#pragma once
// Separable CMA-ES (docs/algorithm.md §9.9): CMA-ES with a diagonal
// covariance matrix (Ros & Hansen 2008), the search distribution of the
// cma_me and cma_mae emitters. Diagonal because a genome has about 2,000
// parameters: sampling and updating cost O(n) per child, where full CMA-ES
// costs O(n^2) per sample and an O(n^3) eigendecomposition (§9.9 gives the
// measurement). The update is the textbook one (Hansen, "The CMA Evolution
// Strategy: A Tutorial", 2016, with the separable learning rates c1 and cmu
// scaled by (n + 2) / 3), plus one rule for children sampled from an earlier
// distribution (the birth pipeline's lag, §8.4): a step whose Mahalanobis
// length exceeds sqrt(n) + 2n / (n + 2) is shortened to it (Hansen 2011,
// "Injecting external solutions into CMA-ES").
#include "evolution/rng.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace morphogen {

struct SepCmaState {
    std::vector<double> mean;        // m
    std::vector<double> variances;   // the diagonal of C, each > 0
    std::vector<double> path_c;      // p_c, the evolution path of C
    std::vector<double> path_sigma;  // p_sigma, the conjugate evolution path
    double sigma = 1.0;              // the step size, > 0
    std::uint64_t updates = 0;       // updates since the (re)start
};

// The distribution N(mean, sigma^2 I) with both paths zero.
SepCmaState sep_cma_start(std::vector<double> mean, double sigma);

// One child: x_i = m_i + sigma * sqrt(c_ii) * z_i with one N(0,1) per
// parameter drawn from `stream` in index order.
std::vector<double> sep_cma_sample(const SepCmaState& state, RandomStream& stream);

// One update from the selected children's parameters, best first (mu >= 1 of
// them; the recombination weights are w_k ~ ln(mu + 1/2) - ln k). Throws
// std::invalid_argument for no parents or a wrong length.
void sep_cma_update(SepCmaState& state, std::span<const std::vector<double>* const> parents_best_first);

// CMA-ES's own stop tests (the "basic" restart rule): the distribution has
// shrunk below 1e-11 (sigma * max sqrt(c_ii)), or C's condition number
// (max c_ii / min c_ii) exceeds 1e14, or a step size or variance is no longer
// finite and positive.
bool sep_cma_converged(const SepCmaState& state);

}  // namespace morphogen
