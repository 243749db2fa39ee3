#include "cluster/worker.hpp"

#include "cluster/protocol.hpp"
#include "evolution/execution/thread_evaluator.hpp"
#include "run/config/experiment_config.hpp"
#include "run/growth_problem.hpp"
#include "core/base/parallel_for.hpp"

#include <nlohmann/json.hpp>

#include <csignal>
#include <exception>
#include <memory>

namespace morphogen::cluster {

namespace {
struct Serving {
    std::unique_ptr<GrowthProblem> problem;
    std::unique_ptr<ThreadEvaluator> evaluator;
    int threads = 1;
};

// The problem of a new session, or the reason it cannot be built.
std::string start_session(Serving& serving, const std::string& config_text) {
    try {
        serving.evaluator.reset();
        const ExperimentConfig config =
            read_experiment_config(nlohmann::json::parse(config_text), "config from rank 0");
        serving.problem = std::make_unique<GrowthProblem>(config);
        serving.threads = resolve_threads(config.run.threads);
        serving.evaluator = std::make_unique<ThreadEvaluator>(*serving.problem, serving.threads);
        return {};
    } catch (const std::exception& e) {
        serving.evaluator.reset();
        serving.problem.reset();
        return e.what();
    }
}

// Sends back every result that is ready, one message each; returns how many.
std::size_t return_results(World& world, ThreadEvaluator& evaluator) {
    std::vector<ScoredBirth> ready = evaluator.take_ready();
    for (ScoredBirth& scored : ready)
        world.post(0, tag_result, encode_results({ResultItem{scored.birth, std::move(scored.evaluation)}}));
    return ready.size();
}
}  // namespace

int serve(World& world) {
    std::signal(SIGINT, SIG_IGN);
    std::signal(SIGTERM, SIG_IGN);
    Serving serving;
    // Up to 1 ms between polls: the threads have queued genomes meanwhile.
    World::Backoff backoff(1000);
    for (;;) {
        world.progress();
        std::optional<Message> m = world.try_receive(0, World::any_tag);
        if (!m) {
            // Results first: a finished genome goes back at once, and its
            // thread already has the next one from the queue rank 0 keeps full.
            if (serving.evaluator && serving.evaluator->outstanding() > 0) {
                if (return_results(world, *serving.evaluator) > 0) {
                    backoff.reset();
                    continue;
                }
            }
            backoff.pause();
            continue;
        }
        backoff.reset();
        switch (m->tag) {
        case tag_quit:
            world.flush();
            return decode_int(m->bytes);
        case tag_config: {
            const std::string failure = start_session(serving, m->bytes);
            if (failure.empty())
                world.post(0, tag_ready, encode_ready({serving.threads, cpu_kind()}));
            else
                world.post(0, tag_failed, failure);
            break;
        }
        case tag_work:
            if (!serving.evaluator) throw ProtocolError("work before a config");
            for (WorkItem& item : decode_work(m->bytes)) serving.evaluator->submit(item.index, item.params, item.keep_from);
            break;
        default:
            throw ProtocolError("unknown message tag " + std::to_string(m->tag));
        }
    }
}

}  // namespace morphogen::cluster
