// The solid-texture paper's experiments as a benchmark (`sansui bench solid`; docs/solid.md).
#pragma once

#include <cstdint>
#include <string>

#include "core/context.hpp"
#include "core/params.hpp"

namespace sansui::bench {

struct SolidBenchOptions {
  int exp1_from = 4, exp1_to = 8;
  int exp2_from = 6, exp2_to = 10;
  int memory_levels = 8;
  int r2 = 6;
  double max_seconds = 20.0;  ///< skip a cell whose estimate exceeds this. [Units: s]
  bool full = false;          ///< also Type I and II where they need gigabytes
  bool skip_memory = false;
  bool skip_targets = false;
  std::uint64_t seed = 1;
  std::string child;  ///< internal: "TYPE,R,R2,WORKLOAD,RUN" of one memory measurement
};
const params::Table<SolidBenchOptions>& parameter_table(const SolidBenchOptions*);

/// Prints Experiments 1 and 2, the memory table, the reach table and the targets, each table when
/// it is complete, reporting each table's progress on `context` meanwhile. Throws InputError for
/// bad options.
void run_solid_experiments(const SolidBenchOptions& options, const Context& context = quiet_context());

}  // namespace sansui::bench
