#pragma once
// `amls deform`'s report: JSON and a short text summary.
#include <iosfwd>
#include <nlohmann/json.hpp>

#include "core/run/scene_run.hpp"

namespace amls::app {

nlohmann::json to_json(const SceneRunReport& report);
void print_summary(std::ostream& out, const SceneRunReport& report);

}  // namespace amls::app
