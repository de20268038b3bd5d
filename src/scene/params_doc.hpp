// docs/params.md, generated from the parameter tables: every section, key, type, unit, range,
// default and help, which source and outputs read each section, and the option names each
// command gives it. `sansui params` prints it; a test fails when the checked-in file is stale.
#pragma once

#include <string>

namespace sansui::scene {

std::string params_markdown();

}  // namespace sansui::scene
