#pragma once
// Scores genomes as a stream (docs/algorithm.md §8.4): the pipeline submits a
// genome as soon as it is conceived and takes results back in whatever order
// they finish. Implemented by a pool of threads in this process
// (thread_evaluator.hpp) and by worker processes over MPI (cluster/). Which
// thread or process scores a genome never changes its evaluation.
#include "evolution/individual.hpp"

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace morphogen {

struct ScoredBirth {
    std::uint64_t birth = 0;
    Evaluation evaluation;
};

class GenomeEvaluator {
public:
    virtual ~GenomeEvaluator() = default;
    // Queues a genome (copied) under its birth index; never blocks for long.
    // Its evaluation keeps what exporting it needs if it scores at least
    // `keep_from` (Problem::evaluate_keeping; +infinity: never).
    virtual void submit(std::uint64_t birth, std::span<const double> params, double keep_from) = 0;
    // One finished evaluation, exactly what evaluate_safely gives for that
    // genome, or nothing if none finished within `timeout`. May throw only
    // for failures of its own (a lost worker), never for a genome.
    virtual std::optional<ScoredBirth> next(std::chrono::milliseconds timeout) = 0;
    // Forgets every genome submitted and not yet returned: none of them is
    // returned afterwards. Returns when no work of theirs is left running.
    virtual void cancel() = 0;
    // Genomes that can usefully be in flight at once (threads, over all processes).
    virtual int capacity() const = 0;
    // Where the genomes go, for the run's log ("2 threads", "3 worker processes, 6 threads").
    virtual std::string description() const = 0;
    // What it cost the calling process, for the run's log at the end ("" if nothing to say).
    virtual std::string summary() const { return {}; }
};

}  // namespace morphogen
