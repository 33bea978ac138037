#include "app/flow_report.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <stdexcept>

namespace amls::app {

nlohmann::json to_json(const FlowTestReport& r) {
  nlohmann::json j;
  j["test"] = r.test;
  j["dimension"] = r.dimension;
  j["grid"] = r.config.grid;
  j["variant"] = to_string(r.config.variant);
  j["radius_factor"] = r.config.radius_factor;
  j["min_weight"] = r.config.min_weight;
  j["dt"] = r.config.dt;
  j["substeps"] = r.config.substeps;
  j["steps"] = r.steps;
  j["steps_planned"] = r.steps_planned;
  j["resample"] = r.config.resample.to_string();
  j["resamples"] = r.resamples;
  j["threads"] = r.config.threads;
  j["status"] = r.broken ? "broken" : "ok";
  j["status_reason"] = r.status_reason;
  j["points_initial"] = r.points_initial;
  j["points_max"] = r.points_max;
  j["points_final"] = r.points_final;
  j["spacing_h"] = {{"min", r.spacing_h.min}, {"median", r.spacing_h.median}, {"max", r.spacing_h.max}};
  j["timings_s"] = {{"normals", r.timings.normals}, {"function", r.timings.function},
                    {"resample", r.timings.resample}, {"deform", r.timings.deform},
                    {"hash", r.timings.hash}, {"total", r.timings.total()}};
  j["peak_memory_mib"] = r.peak_memory_mib;
  j["work"] = {{"vertex_evaluations", r.vertex_evaluations}, {"crossings", r.crossings},
               {"root_evaluations", r.root_evaluations}, {"failed_normal_fits", r.failed_normal_fits}};
  if (r.dimension == 2) {
    j["l1_error"] = r.l1_error;
  } else {
    j["volume_loss"] = r.volume_loss;
    j["symmetric_difference"] = r.symmetric_difference;
    j["relative_symmetric_difference"] = r.relative_symmetric_difference;
  }
  return j;
}

void print_table(std::ostream& out, const FlowTestReport& r) {
  char line[160];
  const auto& c = r.config;
  std::snprintf(line, sizeof line,
                "%s test, %d^%d grid, %s, Delta = %gh, dt = %g, %zu/%zu steps, %zu resamples (%s), %d thread%s\n",
                r.test.c_str(), c.grid, r.dimension, to_string(c.variant), c.radius_factor, c.dt, r.steps,
                r.steps_planned, r.resamples, c.resample.to_string().c_str(), c.threads, c.threads == 1 ? "" : "s");
  out << line;
  const double total = r.timings.total();
  auto row = [&](const char* name, double seconds) {
    std::snprintf(line, sizeof line, "  %-10s %10.3f s %7.2f %%\n", name, seconds, total > 0 ? 100 * seconds / total : 0.0);
    out << line;
  };
  row("normals", r.timings.normals);
  row("function", r.timings.function);
  row("resample", r.timings.resample);
  row("deform", r.timings.deform);
  row("hash", r.timings.hash);
  row("total", total);
  std::snprintf(line, sizeof line, "points: initial %zu, max %zu, final %zu; spacing/h min %.3f median %.3f max %.3f\n",
                r.points_initial, r.points_max, r.points_final, r.spacing_h.min, r.spacing_h.median, r.spacing_h.max);
  out << line;
  std::snprintf(line, sizeof line, "work: %zu vertex evaluations, %zu crossings, %zu root-finder evaluations, %zu failed normal fits\n",
                r.vertex_evaluations, r.crossings, r.root_evaluations, r.failed_normal_fits);
  out << line;
  if (r.dimension == 2) {
    std::snprintf(line, sizeof line, "L1 error: %.6g\n", r.l1_error);
  } else {
    std::snprintf(line, sizeof line, "volume loss: %.4f %%, symmetric difference: %.4f %% of V0\n",
                  100 * r.volume_loss, 100 * r.relative_symmetric_difference);
  }
  out << line;
  std::snprintf(line, sizeof line, "peak memory: %.1f MiB\n", r.peak_memory_mib);
  out << line;
  out << "status: " << (r.broken ? "broken (" + r.status_reason + ")" : std::string("ok")) << "\n";
}

void write_json_file(const std::string& path, const nlohmann::json& json) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream file(temporary);
    if (!file) throw std::runtime_error("cannot write '" + temporary + "'");
    file << json.dump(2) << "\n";
    if (!file.flush()) throw std::runtime_error("failed writing '" + temporary + "'");
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw std::runtime_error("cannot write '" + path + "'");
  }
}

}  // namespace amls::app
