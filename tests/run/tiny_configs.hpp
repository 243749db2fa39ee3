#pragma once
// Configs small enough for a run to take milliseconds, for the run/ tests and
// the end-to-end tests that run the executable.
#include <string>

namespace morphogen::test {

std::string tiny_config(int generations, int population = 8, int batch = 3);
// The same run with the pipeline schedule (evolution.lag) instead of batches.
std::string tiny_pipeline_config(int generations, int population = 8, int lag = 5);

}  // namespace morphogen::test
