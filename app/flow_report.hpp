#pragma once
// The flow tests' report: a Table-1-like text table and the JSON report, and
// the side-by-side table of `amls compare`.
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/run/flow_test.hpp"

namespace amls::app {

nlohmann::json to_json(const FlowTestReport& report);
void print_table(std::ostream& out, const FlowTestReport& report);
// Runs of one test with different variants, one column each: seconds and share
// per phase (every variant's own phases), total, total as a fraction of the
// ray-tracing run's (if there is one), error, point counts and status.
void print_comparison(std::ostream& out, const std::vector<FlowTestReport>& runs);
// Writes `json` to `path` through a temporary file renamed into place.
void write_json_file(const std::string& path, const nlohmann::json& json);

}  // namespace amls::app
