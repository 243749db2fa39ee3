#pragma once
// Eigen views over the row-major std::vector<double> matrices and vectors
// that CMA states store (full_cma.hpp), for the files that do their algebra
// with Eigen. Include only from .cpp files that link Eigen.
#include <Eigen/Dense>

namespace morphogen::eigen_views {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using MatrixView = Eigen::Map<RowMatrix>;
using ConstMatrixView = Eigen::Map<const RowMatrix>;
using VectorView = Eigen::Map<Eigen::VectorXd>;
using ConstVectorView = Eigen::Map<const Eigen::VectorXd>;

}  // namespace morphogen::eigen_views
