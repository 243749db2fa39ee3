#pragma once
// CMA-ES with a full covariance matrix (docs/algorithm.md §9.9), the search
// distribution of a cma_me or cma_mae emitter with `covariance: "full"`.
// The textbook update (Hansen, "The CMA Evolution Strategy: A Tutorial",
// 2016, Table 1) with the same weights, rates, step-length clip and sigma cap
// as sep_cma.hpp, whose separable model is the default: here every update
// costs O(mu n^2) plus an O(n^3) eigendecomposition and every child O(n^2),
// affordable for the sphere benchmark's n = 100, not for a genome's ~2,000
// parameters (§9.9 gives the measurement).
#include "evolution/rng.hpp"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace morphogen {

struct FullCmaState {
    std::vector<double> mean;        // m
    std::vector<double> covariance;  // C, n x n row-major, symmetric positive definite
    std::vector<double> path_c;      // p_c
    std::vector<double> path_sigma;  // p_sigma
    double sigma = 1.0;              // > 0
    std::uint64_t updates = 0;       // updates since the (re)start
    // Derived from `covariance` by full_cma_decompose (never stored):
    // C = B diag(scales)^2 B^T, B's columns the eigenvectors.
    std::vector<double> basis;   // B, n x n row-major
    std::vector<double> scales;  // the square roots of C's eigenvalues
};

// N(mean, sigma^2 I), both paths zero.
FullCmaState full_cma_start(std::vector<double> mean, double sigma);

// One child: z = one N(0,1) per parameter from `stream` in index order, then
// x = m + sigma * B (scales .* z).
std::vector<double> full_cma_sample(const FullCmaState& state, RandomStream& stream);

// One update from the selected children, best first (as sep_cma_update),
// then the eigendecomposition of the new C. Throws std::invalid_argument for
// no parents or a wrong length.
void full_cma_update(FullCmaState& state, std::span<const std::vector<double>* const> parents_best_first);

// A replacement for full_cma_update, for code that links the library to
// compare other update rules (bench/pyribs_cma.hpp reproduces pyribs 0.4's):
// called with the state, the selected children best first, and lambda, the
// emitter's children per iteration. It must leave basis and scales usable
// for sampling (full_cma_decompose).
using FullCmaUpdate =
    std::function<void(FullCmaState&, std::span<const std::vector<double>* const> parents_best_first, std::size_t lambda)>;

// Recomputes basis and scales from covariance. False, leaving them empty,
// when C is not n x n, not exactly symmetric, not finite, or not positive
// definite (an eigenvalue <= 0): how a damaged checkpoint is caught.
bool full_cma_decompose(FullCmaState& state);

// The "basic" stop tests of sep_cma_converged on C's eigenvalues: sigma *
// max scale < 1e-11, condition number (max/min eigenvalue) > 1e14, or sigma
// not finite and positive.
bool full_cma_converged(const FullCmaState& state);

}  // namespace morphogen
