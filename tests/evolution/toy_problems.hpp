#pragma once
// Cheap problems for GA tests: no meshes involved.
#include "evolution/problem.hpp"

#include <cmath>
#include <stdexcept>

namespace morphogen::test {

// Maximise -sum (x_i - 1)^2, with crossover blocks of `block` parameters.
// Optionally throws / returns NaN for some genomes to exercise invalid children.
class SphereProblem : public Problem {
public:
    explicit SphereProblem(std::size_t dimension = 12, std::size_t block = 3, bool faulty = false)
        : dimension_(dimension), block_(block), faulty_(faulty) {}
    std::size_t dimension() const override { return dimension_; }
    std::vector<Block> blocks() const override {
        std::vector<Block> out;
        for (std::size_t i = 0; i < dimension_; i += block_) out.emplace_back(i, std::min(block_, dimension_ - i));
        return out;
    }
    Evaluation evaluate(std::span<const double> params, int) const override {
        double sum = 0.0;
        for (double p : params) sum += (p - 1.0) * (p - 1.0);
        if (faulty_ && params[0] > 1.5) throw std::runtime_error("genome too wild");
        if (faulty_ && params[1] > 1.5) return {std::nan(""), true, "", 0.0};
        return {-sum, true, "", static_cast<double>(params.size())};
    }

private:
    std::size_t dimension_, block_;
    bool faulty_;
};

// The sphere with descriptors for MAP-Elites: the first `described`
// parameters themselves. With `faulty`, throws when params[0] > 1.5 and gives
// a NaN descriptor when params[1] > 1.5.
class DescribedSphereProblem : public Problem {
public:
    explicit DescribedSphereProblem(std::size_t dimension = 6, std::size_t described = 2, bool faulty = false)
        : dimension_(dimension), described_(described), faulty_(faulty) {}
    std::size_t dimension() const override { return dimension_; }
    std::vector<Block> blocks() const override {
        std::vector<Block> out;
        for (std::size_t i = 0; i < dimension_; i += 2) out.emplace_back(i, std::min<std::size_t>(2, dimension_ - i));
        return out;
    }
    Evaluation evaluate(std::span<const double> params, int) const override {
        double sum = 0.0;
        for (double p : params) sum += (p - 1.0) * (p - 1.0);
        if (faulty_ && params[0] > 1.5) throw std::runtime_error("genome too wild");
        Evaluation e{-sum, true, "", static_cast<double>(params.size())};
        e.descriptors.assign(params.begin(), params.begin() + static_cast<std::ptrdiff_t>(described_));
        if (faulty_ && params[1] > 1.5) e.descriptors[0] = std::nan("");
        return e;
    }

private:
    std::size_t dimension_, described_;
    bool faulty_;
};

}  // namespace morphogen::test
