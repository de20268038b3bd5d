// One budget (issue 30): every stage whose memory or time follows from its parameters estimates
// both before it allocates, and checks the estimate here, in one place, against the memory limit
// (--max-memory, core/memory.hpp) and the work limit (ten minutes on the reference machine; a
// stage over it runs only with force / --force). A refusal is one line: what was asked, the
// estimate, the limit and the way out (a smaller parameter, --max-memory, --force).
#pragma once

#include <string>

namespace sansui::budget {

/// Work estimated to take longer than this is refused unless forced. [Units: s]
inline constexpr double work_limit_s = 600.0;

/// What a stage will need, estimated from its parameters alone.
struct Cost {
  /// Peak memory the stage adds. [Units: bytes] [Range: >= 0]
  double bytes = 0.0;
  /// Time on the reference machine (2 cores, Release build). [Units: s] [Range: >= 0]
  double seconds = 0.0;
  /// What is asked, with the parameters that size it: "tree 'oak' (branching 12, depth 8: 4.3e+08
  /// branches, 1.7e+10 triangles)". The message starts with it.
  std::string what;
  /// The way out through the stage's own parameters, e.g. "lower branching, depth or
  /// leaves_per_twig"; empty: none named.
  std::string smaller;
  /// How the user forces long work, e.g. "force (--force)"; empty: the stage cannot be forced,
  /// and work over the limit is refused like memory over it.
  std::string force = "force (--force)";
};

/// Throws InputError if `cost` needs more memory than memory_limit_bytes(), or (unless `forced`)
/// more time than work_limit_s:
///   "WHAT needs 2.94 GB, more than the memory limit of 0.2 GB (raise it with --max-memory GB[, or SMALLER])"
///   "WHAT would take about 21 minutes, more than the work limit of 10 minutes: SMALLER, or pass FORCE to run it"
void check(const Cost& cost, bool forced = false);

/// "0.0042 GB", "4.4 TB": the form every memory message uses.
std::string format_bytes(double bytes);
/// "40 s", "21 minutes", "3.2 hours".
std::string format_seconds(double seconds);

}  // namespace sansui::budget
