#include "app/flow_report.hpp"

#include <algorithm>
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
  if (r.config.variant == FlowVariant::raytrace)
    j["ray_settings"] = {{"samples_per_cell", r.config.ray.samples_per_cell},
                         {"cluster_threshold", r.config.ray.cluster_threshold}};
  j["radius_factor"] = r.config.radius_factor;
  j["min_weight"] = r.config.min_weight;
  // In effect: 3D, grid resampler (see AmlsParameters::bias_correction).
  j["bias_correction"] = r.config.bias_correction && r.dimension == 3 && r.config.variant != FlowVariant::raytrace;
  j["dt"] = r.config.dt;
  j["substeps"] = r.config.substeps;
  j["steps"] = r.steps;
  j["steps_planned"] = r.steps_planned;
  j["resample"] = r.config.resample.to_string();
  if (r.config.resample.kind == ResamplePolicy::Kind::local) j["strain_limit"] = r.config.strain_limit;
  j["resamples"] = r.resamples;
  j["quality_seconds"] = r.quality_seconds;
  j["threads"] = r.config.threads;
  j["status"] = r.broken ? "broken" : "ok";
  j["status_reason"] = r.status_reason;
  j["points_initial"] = r.points_initial;
  j["points_max"] = r.points_max;
  j["points_final"] = r.points_final;
  j["spacing_h"] = {{"min", r.spacing_h.min}, {"median", r.spacing_h.median}, {"max", r.spacing_h.max}};
  nlohmann::json timings = nlohmann::json::object();
  for (const PhaseTime& p : r.timings) timings[p.phase] = p.seconds;
  timings["total"] = total_seconds(r.timings);
  j["timings_s"] = timings;
  j["peak_memory_mib"] = r.peak_memory_mib;
  j["work"] = {{"vertex_evaluations", r.vertex_evaluations}, {"sample_evaluations", r.sample_evaluations},
               {"crossings", r.crossings},
               {"root_evaluations", r.root_evaluations},
               {"removed_clusters", r.removed_clusters},
               {"failed_normal_fits", r.failed_normal_fits}};
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
  char line[200];
  const auto& c = r.config;
  std::snprintf(line, sizeof line,
                "%s test, %d^%d grid, %s, Delta = %gh, dt = %g, %zu/%zu steps, %zu resamples (%s), %d thread%s\n",
                r.test.c_str(), c.grid, r.dimension, to_string(c.variant), c.radius_factor, c.dt, r.steps,
                r.steps_planned, r.resamples, c.resample.to_string().c_str(), c.threads, c.threads == 1 ? "" : "s");
  out << line;
  const double total = total_seconds(r.timings);
  auto row = [&](const std::string& name, double seconds) {
    std::snprintf(line, sizeof line, "  %-16s %10.3f s %7.2f %%\n", name.c_str(), seconds,
                  total > 0 ? 100 * seconds / total : 0.0);
    out << line;
  };
  for (const PhaseTime& p : r.timings) row(p.phase, p.seconds);
  row("total", total);
  if (c.resample.kind == ResamplePolicy::Kind::automatic) {
    std::snprintf(line, sizeof line, "sampling-quality checks (auto, outside the phases): %.3f s, %.2f %% of total\n",
                  r.quality_seconds, total > 0 ? 100 * r.quality_seconds / total : 0.0);
    out << line;
  }
  std::snprintf(line, sizeof line, "points: initial %zu, max %zu, final %zu; spacing/h min %.3f median %.3f max %.3f\n",
                r.points_initial, r.points_max, r.points_final, r.spacing_h.min, r.spacing_h.median, r.spacing_h.max);
  out << line;
  if (r.config.variant == FlowVariant::raytrace) {
    std::snprintf(line, sizeof line,
                  "work: %zu ray-sample evaluations, %zu crossings, %zu root-finder evaluations, %zu candidates removed "
                  "as clusters, %zu failed normal fits\n",
                  r.sample_evaluations, r.crossings, r.root_evaluations, r.removed_clusters, r.failed_normal_fits);
  } else {
    std::snprintf(line, sizeof line,
                  "work: %zu vertex evaluations, %zu crossings, %zu root-finder evaluations, %zu failed normal fits\n",
                  r.vertex_evaluations, r.crossings, r.root_evaluations, r.failed_normal_fits);
  }
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

namespace {

// Rows of the comparison: the phases that do the same job side by side (the
// pseudo-normals; F and the new points; the clusters; the deformation; the
// neighbour index), then any phase not listed here.
constexpr const char* kPhaseRows[] = {"normals", "function", "resample",    "intersections",
                                      "remove_clusters", "deform", "hash", "rebuild_tree"};

std::vector<std::string> phase_rows(const std::vector<FlowTestReport>& runs) {
  std::vector<std::string> rows;
  auto present = [&](const std::string& phase) {
    for (const FlowTestReport& r : runs)
      for (const PhaseTime& p : r.timings)
        if (p.phase == phase) return true;
    return false;
  };
  for (const char* phase : kPhaseRows)
    if (present(phase)) rows.emplace_back(phase);
  for (const FlowTestReport& r : runs)
    for (const PhaseTime& p : r.timings)
      if (std::find(rows.begin(), rows.end(), p.phase) == rows.end()) rows.push_back(p.phase);
  return rows;
}

std::string cell_text(const char* pattern, auto... values) {
  char cell[96];
  std::snprintf(cell, sizeof cell, pattern, values...);
  return cell;
}

}  // namespace

void print_comparison(std::ostream& out, const std::vector<FlowTestReport>& runs) {
  if (runs.empty()) return;
  const FlowTestReport& first = runs.front();
  const auto& c = first.config;
  out << cell_text("%s test, %d^%d grid, Delta = %gh, dt = %g, %zu steps, %d thread%s\n", first.test.c_str(), c.grid,
                first.dimension, c.radius_factor, c.dt, first.steps_planned, c.threads, c.threads == 1 ? "" : "s");
  const FlowTestReport* raytrace = nullptr;
  for (const FlowTestReport& r : runs)
    if (r.config.variant == FlowVariant::raytrace) raytrace = &r;

  auto row = [&](const std::string& name, auto&& cell) {
    out << cell_text("%-22s", name.c_str());
    for (const FlowTestReport& r : runs) out << cell_text("%22s", cell(r).c_str());
    out << "\n";
  };
  row("", [](const FlowTestReport& r) { return std::string(to_string(r.config.variant)); });
  row("phase", [](const FlowTestReport&) { return std::string("s        %"); });
  for (const std::string& phase : phase_rows(runs)) {
    row(phase, [&](const FlowTestReport& r) {
      for (const PhaseTime& p : r.timings)
        if (p.phase == phase) return cell_text("%.3f %7.2f", p.seconds, 100.0 * p.seconds / total_seconds(r.timings));
      return std::string("-");
    });
  }
  row("total", [](const FlowTestReport& r) { return cell_text("%.3f  100.00", total_seconds(r.timings)); });
  if (raytrace) {
    const double reference = total_seconds(raytrace->timings);
    row("total / raytrace total", [&](const FlowTestReport& r) { return cell_text("%.3f", total_seconds(r.timings) / reference); });
    row("speed-up over raytrace", [&](const FlowTestReport& r) { return cell_text("%.2fx", reference / total_seconds(r.timings)); });
  }
  if (first.dimension == 2) {
    row("L1 error", [](const FlowTestReport& r) { return cell_text("%.3g", r.l1_error); });
  } else {
    row("volume loss", [](const FlowTestReport& r) { return cell_text("%.3f %%", 100.0 * r.volume_loss); });
    row("symmetric difference", [](const FlowTestReport& r) { return cell_text("%.3f %% V0", 100.0 * r.relative_symmetric_difference); });
  }
  row("points initial/max/final", [](const FlowTestReport& r) {
    return cell_text("%zu/%zu/%zu", r.points_initial, r.points_max, r.points_final);
  });
  row("spacing/h min/med/max", [](const FlowTestReport& r) {
    return cell_text("%.2f/%.2f/%.2f", r.spacing_h.min, r.spacing_h.median, r.spacing_h.max);
  });
  row("status", [](const FlowTestReport& r) { return std::string(r.broken ? "broken" : "ok"); });
  for (const FlowTestReport& r : runs)
    if (r.broken) out << to_string(r.config.variant) << ": " << r.status_reason << "\n";
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
