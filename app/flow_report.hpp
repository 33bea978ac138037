#pragma once
// The flow tests' report: a Table-1-like text table and the JSON report.
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>

#include "core/flow_test.hpp"

namespace amls::app {

nlohmann::json to_json(const FlowTestReport& report);
void print_table(std::ostream& out, const FlowTestReport& report);
// Writes `json` to `path` through a temporary file renamed into place.
void write_json_file(const std::string& path, const nlohmann::json& json);

}  // namespace amls::app
