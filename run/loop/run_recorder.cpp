#include "run/loop/run_recorder.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "run/exports/plant_exports.hpp"
#include "run/loop/run_records.hpp"

#include <filesystem>
#include <utility>

namespace morphogen {

RunRecorder::RunRecorder(RunSession& session, GrowthProblem& problem, const RunSearch& search,
                         const BirthPipeline& pipeline, Progress& progress)
    : session_(session),
      problem_(problem),
      search_(search),
      pipeline_(pipeline),
      progress_(progress),
      population_(static_cast<std::uint64_t>(session.config.evolution.population)),
      target_births_((session.config.run.generations + 1) * population_),
      descriptor_columns_(session.lineage_descriptor_columns.value_or(session.config.qd.descriptors.size())),
      elapsed_before_(session.state.elapsed_s),
      generation_first_birth_(search.births()) {}

double RunRecorder::elapsed_s() const {
    return elapsed_before_ + std::chrono::duration<double>(Clock::now() - session_start_).count();
}

// spdlog reports a failed log write to the handler, not to us: check it.
void RunRecorder::check_log() const {
    if (!session_.log.failure->empty()) throw IoError(*session_.log.failure);
}

void RunRecorder::write_rows() {
    session_.lineage.write(rows_);
    rows_.clear();
    check_log();
}

void RunRecorder::inserted(const Individual& child, const std::string& error, const Inserted& what,
                           const std::string& kept) {
    if (!kept.empty()) {
        if (const Individual* exported = search_.exported(); exported != nullptr && exported->id == child.id) {
            kept_id_ = child.id;
            kept_files_ = kept;
        }
    }
    rows_ += format_lineage_row(child, descriptor_columns_);
    if (!error.empty()) {
        progress_.clear();
        session_.log.both->warn("birth {} is invalid: {}", child.id, error);
    }
    const std::uint64_t births = search_.births();
    const std::optional<Individual>& best = search_.best();
    progress_.update(births, births / population_, best ? std::optional<double>(best->fitness) : std::nullopt);
    if (what.ends_generation) end_generation(what);
}

void RunRecorder::end_generation(const Inserted& what) {
    io_.wait_for(checkpoint_ticket_);
    write_rows();
    const std::uint64_t births = search_.births();
    const std::uint64_t generation = births / population_ - 1;
    const HistoryRow row = history_row(generation, what);
    session_.history.write(format_history_row(row));
    session_.state.history.push_back(row);
    progress_.clear();
    progress_.generation(row);

    const bool last = births == target_births_;
    const auto every = [&](std::uint64_t n) { return n > 0 && (generation % n == 0 || last); };
    if (every(session_.config.run.export_every)) export_best(generation);
    if (last || every(session_.config.run.checkpoint_every)) checkpoint();
    generation_start_ = Clock::now();
    generation_first_birth_ = births;
}

HistoryRow RunRecorder::history_row(std::uint64_t generation, const Inserted& what) const {
    HistoryRow row;
    row.generation = generation;
    row.births = search_.births();
    search_.fill(row, what);
    row.invalid = what.generation_invalid;
    const double seconds = std::chrono::duration<double>(Clock::now() - generation_start_).count();
    row.births_per_s = seconds > 0 ? static_cast<double>(row.births - generation_first_birth_) / seconds : 0.0;
    row.elapsed_s = elapsed_s();
    return row;
}

// On the I/O thread: from the files its evaluation kept, else grown again there.
void RunRecorder::export_best(std::uint64_t generation) {
    const Individual* best = search_.exported();
    if (best == nullptr) return;
    const std::filesystem::path stem = session_.paths.best_stem(generation);
    GrowthProblem& problem = problem_;
    if (const auto& options = session_.config.run.export_glb) {
        // Grown again on the I/O thread: an engine GLB needs each vertex's birth step.
        io_.post([&problem, params = best->params, stem, options = *options,
                  record = birth_record(session_.config, *best, session_.config.qd.measure_names(),
                                       search_.exported_cell())] {
            export_engine_plant(problem.grower(), params, record, options, stem);
        });
        return;
    }
    if (kept_id_ == best->id)
        io_.post([&problem, files = kept_files_, params = best->params, stem] {
            problem.export_kept(files, params, stem);
        });
    else
        io_.post([&problem, params = best->params, stem] { problem.export_genome(params, stem); });
}

// The state is taken here; the I/O thread syncs the rows written so far and
// writes archive.csv, then the checkpoint (each atomically, in order).
void RunRecorder::checkpoint() {
    write_rows();
    RunState& state = session_.state;
    state.config = session_.config.resolved;
    state.seed = session_.config.run.seed;
    state.search = search_.save();
    state.pending = pipeline_.kept();
    state.lineage_bytes = session_.lineage.size();
    state.lineage_hash = session_.lineage.hash_hex();
    state.elapsed_s = elapsed_s();
    RunSession& session = session_;
    checkpoint_ticket_ =
        io_.post([&session, bytes = checkpoint_bytes(state), archive = state.search->archive_text()] {
            session.history.sync();
            session.lineage.sync();
            // archive.csv first: a checkpoint never refers to an older archive.csv.
            if (!archive.empty()) write_file_atomically(session.paths.archive, archive);
            write_file_atomically(session.paths.checkpoint, bytes);
        });
}

}  // namespace morphogen
