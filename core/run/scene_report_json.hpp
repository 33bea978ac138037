#pragma once
// `amls deform`'s JSON report of a scene run (docs/cli.md), made here so that
// the command line and the Python module's run_scene() give the same keys.
#include <nlohmann/json.hpp>

#include "core/run/scene_run.hpp"

namespace amls {

nlohmann::json scene_report_json(const SceneRunReport& report);

}  // namespace amls
