#pragma once
// `amls deform`'s short text summary (its JSON: core/run/scene_report_json.hpp).
#include <iosfwd>

#include "core/run/scene_run.hpp"

namespace amls::app {

void print_summary(std::ostream& out, const SceneRunReport& report);

}  // namespace amls::app
