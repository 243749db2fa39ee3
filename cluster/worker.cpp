#include "cluster/worker.hpp"

#include "cluster/protocol.hpp"
#include "evolution/batch.hpp"
#include "run/experiment_config.hpp"
#include "run/growth_problem.hpp"
#include "run/worker_threads.hpp"

#include <nlohmann/json.hpp>
#include <omp.h>

#include <csignal>
#include <exception>
#include <memory>

namespace morphogen::cluster {

namespace {
struct Serving {
    std::unique_ptr<GrowthProblem> problem;
    int threads = 1;
};

// The problem of a new session, or the reason it cannot be built.
std::string start_session(Serving& serving, const std::string& config_text) {
    try {
        const ExperimentConfig config =
            read_experiment_config(nlohmann::json::parse(config_text), "config from rank 0");
        serving.problem = std::make_unique<GrowthProblem>(config);
        serving.threads = resolve_threads(config.run.threads);
        start_worker_threads(serving.threads);
        serving.problem->prepare(serving.threads);
        return {};
    } catch (const std::exception& e) {
        serving.problem.reset();
        return e.what();
    }
}

std::vector<ResultItem> score(const Serving& serving, const std::vector<WorkItem>& items) {
    std::vector<ResultItem> results(items.size());
#pragma omp parallel for schedule(dynamic) num_threads(serving.threads)
    for (std::size_t i = 0; i < items.size(); ++i)
        results[i] = ResultItem{items[i].index,
                                evaluate_safely(*serving.problem, items[i].params, omp_get_thread_num())};
    return results;
}
}  // namespace

int serve(World& world) {
    std::signal(SIGINT, SIG_IGN);
    std::signal(SIGTERM, SIG_IGN);
    Serving serving;
    for (;;) {
        const Message m = world.receive(0, World::any_tag);
        switch (m.tag) {
        case tag_quit:
            return decode_int(m.bytes);
        case tag_config: {
            const std::string failure = start_session(serving, m.bytes);
            if (failure.empty())
                world.send(0, tag_ready, encode_ready({serving.threads, cpu_kind()}));
            else
                world.send(0, tag_failed, failure);
            break;
        }
        case tag_work:
            if (!serving.problem) throw ProtocolError("work before a config");
            world.send(0, tag_result, encode_results(score(serving, decode_work(m.bytes))));
            break;
        default:
            throw ProtocolError("unknown message tag " + std::to_string(m.tag));
        }
    }
}

}  // namespace morphogen::cluster
