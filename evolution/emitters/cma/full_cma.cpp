#include "evolution/emitters/cma/full_cma.hpp"

#include "evolution/emitters/cma/cma_rates.hpp"
#include "evolution/emitters/cma/eigen_views.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace morphogen {

namespace {
using namespace eigen_views;

Eigen::Index size_of(const std::vector<double>& v) { return static_cast<Eigen::Index>(v.size()); }

// After an update: B and d from the new C. If rounding made C indefinite,
// zero scales make the emitter's stop test fire (full_cma_converged) and it
// restarts.
void decompose_after_update(FullCmaState& s) {
    const std::size_t n = s.mean.size();
    if (!full_cma_decompose(s)) {
        s.scales.assign(n, 0.0);
        s.basis.assign(n * n, 0.0);
    }
}
}  // namespace

FullCmaState full_cma_start(std::vector<double> mean, double sigma) {
    FullCmaState s;
    const std::size_t n = mean.size();
    s.mean = std::move(mean);
    s.covariance.assign(n * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) s.covariance[i * n + i] = 1.0;
    s.path_c.assign(n, 0.0);
    s.path_sigma.assign(n, 0.0);
    s.sigma = sigma;
    s.basis = s.covariance;
    s.scales.assign(n, 1.0);
    return s;
}

std::vector<double> full_cma_sample(const FullCmaState& s, RandomStream& stream) {
    const Eigen::Index n = size_of(s.mean);
    Eigen::VectorXd z(n);
    for (Eigen::Index i = 0; i < n; ++i) z[i] = stream.normal();
    const Eigen::VectorXd y = ConstMatrixView(s.basis.data(), n, n) * ConstVectorView(s.scales.data(), n).cwiseProduct(z);
    std::vector<double> x(s.mean);
    VectorView(x.data(), n) += s.sigma * y;
    return x;
}

bool full_cma_decompose(FullCmaState& s) {
    const std::size_t n = s.mean.size();
    s.basis.clear();
    s.scales.clear();
    if (s.covariance.size() != n * n) return false;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i; j < n; ++j)
            if (!std::isfinite(s.covariance[i * n + j]) || s.covariance[i * n + j] != s.covariance[j * n + i]) return false;
    const Eigen::Index N = static_cast<Eigen::Index>(n);
    const Eigen::SelfAdjointEigenSolver<RowMatrix> eigen(ConstMatrixView(s.covariance.data(), N, N));
    if (eigen.info() != Eigen::Success || !(eigen.eigenvalues().minCoeff() > 0.0)) return false;
    s.basis.resize(n * n);
    s.scales.resize(n);
    MatrixView(s.basis.data(), N, N) = eigen.eigenvectors();
    VectorView(s.scales.data(), N) = eigen.eigenvalues().cwiseSqrt();
    return true;
}

void full_cma_update(FullCmaState& s, std::span<const std::vector<double>* const> parents) {
    const std::size_t n = s.mean.size(), mu = parents.size();
    const CmaRates r = cma_rates(parents, n, /*separable=*/false);
    const Eigen::Index N = static_cast<Eigen::Index>(n);
    const ConstMatrixView basis(s.basis.data(), N, N);
    const ConstVectorView scales(s.scales.data(), N);
    // C^(-1/2) v = B diag(1/scales) B^T v.
    auto whiten = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
        return basis * (basis.transpose() * v).cwiseQuotient(scales);
    };

    // Steps y_k = (x_k - m) / sigma, clipped in Mahalanobis length.
    VectorView mean(s.mean.data(), N);
    Eigen::MatrixXd y(N, static_cast<Eigen::Index>(mu));
    Eigen::VectorXd yw = Eigen::VectorXd::Zero(N);
    for (std::size_t k = 0; k < mu; ++k) {
        const Eigen::Index col = static_cast<Eigen::Index>(k);
        y.col(col) = (ConstVectorView(parents[k]->data(), N) - mean) / s.sigma;
        const double length = whiten(y.col(col)).norm();
        if (length > r.max_length) y.col(col) *= r.max_length / length;
        yw += r.weights[k] * y.col(col);
    }

    // Mean, then the paths.
    mean += s.sigma * yw;
    VectorView path_sigma(s.path_sigma.data(), N), path_c(s.path_c.data(), N);
    path_sigma = (1.0 - r.cs) * path_sigma + std::sqrt(r.cs * (2.0 - r.cs) * r.mueff) * whiten(yw);
    const double ps_norm = path_sigma.norm();
    ++s.updates;
    const double correction = std::sqrt(1.0 - std::pow(1.0 - r.cs, 2.0 * static_cast<double>(s.updates)));
    const bool hsig = ps_norm / correction < (1.4 + 2.0 / (static_cast<double>(n) + 1.0)) * r.chi;
    path_c = (1.0 - r.cc) * path_c + (hsig ? std::sqrt(r.cc * (2.0 - r.cc) * r.mueff) : 0.0) * yw;

    // Covariance (rank-one and rank-mu), kept exactly symmetric, then the
    // step size (exponent capped at 1, as sep_cma_update).
    const double keep = 1.0 - r.c1 - r.cmu + (hsig ? 0.0 : r.c1 * r.cc * (2.0 - r.cc));
    const Eigen::VectorXd w = Eigen::Map<const Eigen::VectorXd>(r.weights.data(), static_cast<Eigen::Index>(mu));
    MatrixView c(s.covariance.data(), N, N);
    const RowMatrix next = keep * c + r.c1 * path_c * path_c.transpose() + r.cmu * (y * w.asDiagonal() * y.transpose());
    c = 0.5 * (next + next.transpose());  // a + b == b + a: symmetric to the bit
    s.sigma *= std::exp(std::min(1.0, (r.cs / r.ds) * (ps_norm / r.chi - 1.0)));
    decompose_after_update(s);
}

bool full_cma_converged(const FullCmaState& s) {
    if (!(s.sigma > 0.0) || !std::isfinite(s.sigma)) return true;
    if (s.scales.empty()) return false;
    const auto [low, high] = std::minmax_element(s.scales.begin(), s.scales.end());
    if (!(*low > 0.0) || !std::isfinite(*high)) return true;
    return s.sigma * *high < 1e-11 || (*high * *high) > 1e14 * (*low * *low);
}

}  // namespace morphogen
