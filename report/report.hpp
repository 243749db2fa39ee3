#pragma once
// `morphogen report`: a static HTML report of a run directory that opens from
// disk (file://) with no network: the run at a glance, plots per generation,
// a three.js viewer of the best mesh of every exported generation and of the
// growth of the best genome, the ancestry of the best, the MAP-Elites archive
// and a contact sheet (docs/report.md).
//
// The run directory is only read (never locked, never written), so a run in
// progress can be reported. Meshes are embedded as base64 in .js files loaded
// by <script> (browsers refuse fetch/XHR of file:// URLs).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace morphogen {

struct ReportOptions {
    std::uint64_t max_elites = 64;  // MAP-Elites: the fittest elites grown for the viewer (0 = none)
    int sheet_count = 12;           // contact sheet: at most this many exported generations
    int thumb_size = 128;           // ancestry thumbnails, pixels
    int animation_frames = 50;      // frames of the best genome's growth, at most steps + 1 (0 = no animation)
    bool colour = true;             // the viewer's plants (COLOR_0), thumbnails and sheet in colours from growth history
};

struct ReportSummary {
    std::filesystem::path index;     // OUT_DIR/index.html
    std::size_t meshes = 0;          // exported generations in the viewer
    std::size_t elites = 0;          // elites grown for the viewer
    std::size_t ancestors = 0;       // length of the best's line, itself included
    bool animation = false;          // the growth animation is in the report
    std::vector<std::string> notes;  // what is missing and why (also shown in the page)
};

// Throws IoError for a missing or not-a-run directory, a missing or malformed
// history.csv / lineage.csv / config.json, or an OUT_DIR that cannot be
// written; CheckpointError for a missing or refused checkpoint.json. A
// bad exported mesh does not stop the report: it becomes a note.
ReportSummary write_report(const std::filesystem::path& run_dir, const std::filesystem::path& out_dir,
                           const ReportOptions& options);

// RFC 4648 base64 (with padding), for embedding binary files in scripts.
std::string base64(std::string_view bytes);

}  // namespace morphogen
