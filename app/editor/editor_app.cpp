#include "app/editor/editor_app.hpp"

#include "render/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <ctime>
#include <sstream>
#include <string_view>
#include <thread>

#include "core/io/point_set_io.hpp"
#include "render/image.hpp"

namespace amls::editor {

namespace {

// SIGINT and SIGTERM close the window as Ctrl+Q does (the loop wakes at least every 0.25 s).
volatile std::sig_atomic_t stop_requested = 0;
void request_stop(int) { stop_requested = 1; }

int default_threads() {
  const unsigned cores = std::thread::hardware_concurrency();
  return cores > 1 ? static_cast<int>(cores) - 1 : 1;
}

std::string timestamped_png() {
  const std::time_t now = std::time(nullptr);
  char text[64];
  std::strftime(text, sizeof text, "amls-editor-%Y%m%d-%H%M%S.png", std::localtime(&now));
  return text;
}

const char* level_name(Message::Level level) {
  return level == Message::Level::error ? "error" : level == Message::Level::warning ? "warning" : "info";
}

}  // namespace

EditorApp::EditorApp(const EditorOptions& options)
    : options_(options),
      log_(options.debug_log),
      window_(options.width, options.height, "amls-editor", options.ui_scale),
      view_([this](Command c) { post(std::move(c)); }),
      regions_([this](Command c) { post(std::move(c)); }),
      browser_(std::filesystem::current_path()) {
  renderer_ = std::make_unique<SplatRenderer>();
  ui_.export_path = options.export_path;
  ui_.mesh_path = std::filesystem::path(options.export_path).replace_extension(".obj").string();
  ui_.scene_path = options.scene_path;
  ui_.estimate_normals = options.estimate_normals;
  ui_.screenshot_path = options.screenshot_path;
  ui_.render.point_size_px *= window_.ui_scale();
  ui_.render.handle_size_px *= window_.ui_scale();
  ui_.render.line_width_px = std::max(1.0f, std::round(window_.ui_scale()));
  ui_.render.scalar_range = glm::vec2(0.0f, 2.0f);
  view_.set_pick_radius(8.0f * window_.ui_scale() * window_.pixels_per_unit().x);
  regions_.set_pick_radius(12.0f * window_.ui_scale() * window_.pixels_per_unit().x);
  WorkerOptions worker;
  worker.threads = options.threads > 0 ? options.threads : default_threads();
  worker.on_publish = [] { EditorWindow::wake(); };
  worker_ = std::make_unique<EditorWorker>(worker);
  if (options.input.empty())
    post(command::LoadShape{options.start_3d ? 3 : 2, 1.0, options.start_3d ? 10000u : 250u,
                            options.start_3d ? 0.04 : 0.024});
  else
    post(command::LoadFile{options.input, ui_.estimate_normals});
  const Viewport vp = window_.viewport();
  log_.line([&] {
    return "ready gl=\"" + window_.gl_description() + "\" scale=" + std::to_string(window_.ui_scale()) +
           " framebuffer=" + std::to_string(vp.width) + "x" + std::to_string(vp.height) +
           " threads=" + std::to_string(worker.threads);
  });
}

EditorApp::~EditorApp() {
  // The worker may finish a phase before it stops: the window goes at once.
  window_.hide();
  for (auto& pending : background_) pending.wait();
  worker_.reset();
}

void EditorApp::post(Command command) { last_posted_ = std::max(last_posted_, worker_->post(std::move(command))); }

int EditorApp::run() {
  std::signal(SIGINT, request_stop);
  std::signal(SIGTERM, request_stop);
  while (!window_.should_close() && !stop_requested) frame();
  log_.line([&] { return "exit frames=" + std::to_string(frames_); });
  return 0;
}

double EditorApp::wait_timeout() const {
  // Busy or interacting: about 60 frames a second to show progress; idle: wake on events (and now and then).
  if (worker_->status().busy || view_.dragging() || regions_.busy() || screenshot_requested_ || !background_.empty())
    return 1.0 / 60.0;
  return 0.25;
}

void EditorApp::frame() {
  window_.begin_frame(wait_timeout());
  take_messages();
  take_snapshot();
  process_input();

  const Snapshot& snapshot = *shown_;
  const WorkerStatus status = worker_->status();
  const PanelActions actions{[this](Command c) { post(std::move(c)); }, [this] { export_points(); },
                             [this] { export_mesh(); },
                             [this] { save_scene(); }, [this] { screenshot_requested_ = true; },
                             [this] { fit_view(); }};
  draw_side_panel(ui_, snapshot, status, view_, actions);
  draw_table1(snapshot);
  draw_status_bar(ui_, snapshot, status, view_);
  draw_help(ui_);
  if (snapshot.dimension > 0) {
    regions_.set_spacing(snapshot.settings.spacing);
    log_region_window(draw_region_window(regions_, snapshot.settings.spacing));
    draw_region_overlay(regions_, view_.camera(), window_.viewport(), window_.pixels_per_unit());
  }
  if (std::optional<std::string> chosen = browser_.draw(ui_.show_browser, ui_.estimate_normals))
    post(command::LoadFile{*chosen, ui_.estimate_normals});

  const Viewport viewport = window_.viewport();
  renderer_->set_handles(view_.drawn_handles());
  glViewport(0, 0, viewport.width, viewport.height);
  if (viewport.width > 0 && viewport.height > 0) {
    try {
      renderer_->draw(view_.camera(), viewport, render_options());
    } catch (const std::exception& e) {
      ui_.tell({Message::Level::error, std::string("Drawing failed: ") + e.what()});
    }
  }
  window_.render_ui();
  if (screenshot_requested_) write_screenshot();
  window_.present();

  ++frames_;
  log_.line([&] {
    return "frame " + std::to_string(frames_) + " busy=" + (status.busy ? "1" : "0") +
           " gen=" + std::to_string(snapshot.generation) + " handles=" + std::to_string(view_.handles().size()) +
           " dragging=" + (view_.dragging() ? "1" : "0");
  });
  log_view();
  log_regions();
  for (auto it = background_.begin(); it != background_.end();) {
    if (it->wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
      ++it;
      continue;
    }
    const Message m = it->get();
    log_.line([&] { return std::string("message level=") + level_name(m.level) + " " + m.text; });
    ui_.tell(m);
    it = background_.erase(it);
  }
}

void EditorApp::take_messages() {
  for (Message& m : worker_->take_messages()) {
    log_.line([&] { return std::string("message level=") + level_name(m.level) + " " + m.text; });
    ui_.tell(std::move(m));
  }
}

void EditorApp::take_snapshot() {
  std::shared_ptr<const Snapshot> next = worker_->snapshot();
  if (shown_ && next->generation == shown_->generation) return;
  const bool new_load = !shown_ || next->load_id != shown_->load_id;
  const bool new_points = new_load || next->points_version != shown_->points_version;
  if (next->dimension > 0) {
    if (new_points) {
      try {
        renderer_->set_points(*next->points);
      } catch (const std::exception& e) {
        ui_.tell({Message::Level::error, std::string("Cannot show the points: ") + e.what()});
      }
      // In 3D a click anywhere on a splat picks its point (splats are RenderOptions::splat_scale h wide).
      regions_.set_points(next->points);
      view_.set_points(next->points, next->dimension == 3
                                         ? ui_.render.splat_scale * static_cast<float>(next->settings.spacing)
                                         : 0.0f);
    }
    if (new_points || next->spacing_version != shown_->spacing_version) {
      if (next->spacing_h)
        renderer_->set_scalars(next->spacing_h->drawn);
      else
        renderer_->clear_scalars();
    }
    if (next->dimension == 2) {
      std::vector<glm::vec2> ends;
      ends.reserve(2 * next->curve.size());
      for (const CurveSegment& s : next->curve) {
        ends.emplace_back(static_cast<float>(s.a.x()), static_cast<float>(s.a.y()));
        ends.emplace_back(static_cast<float>(s.b.x()), static_cast<float>(s.b.y()));
      }
      renderer_->set_curve(std::span<const glm::vec2>(ends));
    } else {
      renderer_->set_curve(std::span<const glm::vec3>());
    }
  }
  // The worker's handles, once it has applied everything the UI sent.
  if (next->processed >= last_posted_) {
    view_.sync_handles(next->handles);
    regions_.sync(next->regions);
  }
  if (new_load && next->dimension > 0) {
    regions_.start();
    renderer_->set_handles({});
    view_.start(next->dimension, renderer_->bounds(), window_.viewport());
    window_.set_title("amls-editor - " + next->name);
  }
  if (!ui_.seen_any || !(next->settings == ui_.seen)) {
    ui_.edit = next->settings;
    ui_.seen = next->settings;
    ui_.seen_any = true;
  }
  log_.line([&] {
    return "snapshot gen=" + std::to_string(next->generation) + " processed=" + std::to_string(next->processed) +
           " load=" + std::to_string(next->load_id) + " dimension=" + std::to_string(next->dimension) +
           " points=" + std::to_string(next->points->input_count) + " steps=" + std::to_string(next->steps) +
           " variant=" + to_string(next->settings.variant) + " resamples=" + std::to_string(next->resamples);
  });
  shown_ = std::move(next);
}

void EditorApp::process_input() {
  const ImGuiIO& io = ImGui::GetIO();
  const Viewport viewport = window_.viewport();
  const glm::vec2 scale = window_.pixels_per_unit();
  view_.set_middle_orbits(regions_.brush_mode || regions_.lasso_mode);
  for (const std::string& path : window_.take_dropped_paths()) {
    log_.line([&] { return "drop " + path; });
    post(command::LoadFile{path, ui_.estimate_normals});
  }
  for (const InputEvent& event : window_.take_events()) {
    if (event.type == InputEvent::Type::key) {
      if (!io.WantTextInput && event.action != GLFW_RELEASE) on_key(event);
      continue;
    }
    // ImGui takes presses and wheel turns over its windows; moves and releases always reach the view,
    // so that a drag ends wherever the button is let go.
    const bool starts = (event.type == InputEvent::Type::button && event.action == GLFW_PRESS) ||
                        event.type == InputEvent::Type::scroll;
    const char* taker = "view";
    if (starts && io.WantCaptureMouse)
      taker = "ui";
    else if (!view_.dragging() && !view_.moving_camera() &&
             regions_.on_event(event, viewport, scale, view_.camera(), view_.handles()))
      taker = "regions";
    if (event.type == InputEvent::Type::button)
      log_.line([&] {
        return "button " + std::to_string(event.code) + " action=" + std::to_string(event.action) +
               " mods=" + std::to_string(event.mods) + " at " + std::to_string(event.position.x) + "," +
               std::to_string(event.position.y) + " to " + taker;
      });
    if (taker == std::string_view("view")) view_.on_event(event, viewport, scale);
  }
  view_.update(viewport, io.KeyShift, io.WantCaptureMouse);
  regions_.update();
}

void EditorApp::on_key(const InputEvent& event) {
  const bool ctrl = (event.mods & GLFW_MOD_CONTROL) != 0, shift = (event.mods & GLFW_MOD_SHIFT) != 0;
  const bool repeat = event.action == GLFW_REPEAT;
  log_.line([&] {
    return "key " + std::to_string(event.code) + " mods=" + std::to_string(event.mods) + (repeat ? " repeat" : "");
  });
  if (repeat && event.code != GLFW_KEY_Z && event.code != GLFW_KEY_Y) return;  // only undo/redo repeat
  switch (event.code) {
    case GLFW_KEY_S:
      if (ctrl) shift ? save_scene() : export_points();
      break;
    case GLFW_KEY_Z:
      if (ctrl) post(shift ? Command{command::Redo{}} : Command{command::Undo{}});
      if (!ctrl) view_.toggle_lock(AxisLock::z);
      break;
    case GLFW_KEY_Y:
      if (ctrl) post(command::Redo{});
      if (!ctrl) view_.toggle_lock(AxisLock::y);
      break;
    case GLFW_KEY_X:
      if (!ctrl) view_.toggle_lock(AxisLock::x);
      break;
    case GLFW_KEY_O:
      if (ctrl) ui_.show_browser = true;
      break;
    case GLFW_KEY_Q:
      if (ctrl) window_.request_close();
      break;
    case GLFW_KEY_R:
      if (ctrl) post(command::Reset{});
      break;
    case GLFW_KEY_F12:
      screenshot_requested_ = true;
      break;
    case GLFW_KEY_F:
      if (!ctrl) fit_view();
      break;
    case GLFW_KEY_H:
      if (!ctrl) ui_.show_help = !ui_.show_help;
      break;
    case GLFW_KEY_I:
      if (!ctrl && shown_ && shown_->dimension > 0) {
        ui_.edit.variant = ui_.edit.variant == Variant::exact ? Variant::interpolated : Variant::exact;
        post(command::SetVariant{ui_.edit.variant});
      }
      break;
    case GLFW_KEY_N:
      if (!ctrl) ui_.render.show_normals = !ui_.render.show_normals;
      break;
    case GLFW_KEY_C:
      if (!ctrl) {
        ui_.show_curve = !ui_.show_curve;
        post(command::SetCurveTracing{ui_.show_curve});
      }
      break;
    case GLFW_KEY_G:
      if (!ctrl) ui_.render.show_grid = !ui_.render.show_grid;
      break;
    case GLFW_KEY_ESCAPE:
      if (ui_.show_browser)
        ui_.show_browser = false;
      else if (ui_.show_help)
        ui_.show_help = false;
      else if (!regions_.cancel())
        view_.cancel();
      break;
    case GLFW_KEY_B:
      if (!ctrl) regions_.brush_mode = !regions_.brush_mode;
      break;
    case GLFW_KEY_LEFT_BRACKET:
    case GLFW_KEY_RIGHT_BRACKET:
      if (!ctrl) regions_.scale_brush(event.code == GLFW_KEY_RIGHT_BRACKET ? 1.25f : 0.8f);
      break;
    case GLFW_KEY_P:
      if (!ctrl && regions_.active() && *regions_.active() < regions_.regions().size())
        regions_.set_pinned(!regions_.regions()[*regions_.active()].pinned);
      break;
    case GLFW_KEY_DELETE:
    case GLFW_KEY_BACKSPACE:
      view_.remove_selected();
      break;
    default:
      break;
  }
}

RenderOptions EditorApp::render_options() const {
  RenderOptions options = ui_.render;
  const int dimension = shown_ ? shown_->dimension : 2;
  options.splat_scale = ui_.dots_in_3d ? 0.35f : 1.2f;
  options.show_curve = dimension == 2 && ui_.show_curve;
  options.show_grid = dimension == 2 && ui_.render.show_grid;
  if (shown_) {
    options.grid_spacing = static_cast<float>(shown_->settings.spacing);
    options.grid_origin = glm::vec2(shown_->grid_origin.x(), shown_->grid_origin.y());
  }
  return options;
}

void EditorApp::write_screenshot() {
  screenshot_requested_ = false;
  const std::string path = ui_.screenshot_path.empty() ? timestamped_png() : ui_.screenshot_path;
  try {
    Image image = read_framebuffer(window_.viewport());
    log_.line(
        [&] { return "screenshot " + path + " " + std::to_string(image.width) + "x" + std::to_string(image.height); });
    background_.push_back(std::async(std::launch::async, [image = std::move(image), path] {
      try {
        write_png(path, image);
        return Message{Message::Level::info, "Screenshot saved to " + path};
      } catch (const std::exception& e) {
        return Message{Message::Level::error, std::string("Screenshot failed: ") + e.what()};
      }
    }));
  } catch (const std::exception& e) {
    ui_.tell({Message::Level::error, std::string("Screenshot failed: ") + e.what()});
  }
}

void EditorApp::export_points() {
  log_.line([&] { return "export " + ui_.export_path; });
  post(command::Export{ui_.export_path});
  if (worker_->status().busy) ui_.tell({Message::Level::info, "Exporting once the running step is done..."});
}

void EditorApp::export_mesh() {
  log_.line("export-mesh " + ui_.mesh_path);
  post(command::ExportMesh{ui_.mesh_path});
  if (worker_->status().busy) ui_.tell({Message::Level::info, "Exporting once the running step is done..."});
}

void EditorApp::save_scene() {
  log_.line([&] { return "save-scene " + ui_.scene_path; });
  post(command::SaveScene{ui_.scene_path});
}

void EditorApp::fit_view() {
  const BoundingSphere bounds = renderer_->bounds();
  if (!bounds.empty()) view_.fit(bounds, window_.viewport());
}

void EditorApp::log_regions() {
  if (!log_.enabled()) return;
  std::ostringstream line;
  line.precision(9);
  const glm::vec2 ppu = window_.pixels_per_unit();
  line << "regions count=" << regions_.regions().size()
       << " active=" << (regions_.active() ? static_cast<long long>(*regions_.active()) : -1LL)
       << " drag=" << regions_.drag_gesture()
       << " ring=" << (regions_.ring_shown() ? regions_.ring_radius_px() / ppu.x : 0.0f);
  for (const RegionView& r : regions_.regions()) {
    const glm::vec3 w = view_.camera().to_window(
        glm::vec3(static_cast<float>(r.centre.x()), static_cast<float>(r.centre.y()), static_cast<float>(r.centre.z())),
        window_.viewport());
    line << " | members=" << r.members.size() << " pinned=" << r.pinned << " marker=" << w.x / ppu.x << ","
         << w.y / ppu.y << " translation=" << r.motion.translation.x() << "," << r.motion.translation.y() << ","
         << r.motion.translation.z() << " rotation=" << r.motion.rotation.x() << "," << r.motion.rotation.y() << ","
         << r.motion.rotation.z() << " scale=" << r.motion.scale << " pivot=" << r.rest_centre.x() << ","
         << r.rest_centre.y() << "," << r.rest_centre.z();
  }
  if (line.str() == last_regions_) return;
  last_regions_ = line.str();
  log_.line(last_regions_);
}

void EditorApp::log_region_window(const ControlCentres& centres) {
  if (!log_.enabled()) return;
  std::ostringstream line;
  line << "region-window";
  for (const auto& [name, centre] : centres) line << " " << name << "=" << centre.x << "," << centre.y;
  if (line.str() == last_region_window_) return;
  last_region_window_ = line.str();
  log_.line(last_region_window_);
}

void EditorApp::log_view() {
  if (!log_.enabled()) return;
  const Camera& c = view_.camera();
  const Viewport v = window_.viewport();
  const glm::vec2 ppu = window_.pixels_per_unit();
  std::ostringstream line;
  line.precision(9);
  line << "view mode=" << (c.mode == Camera::Mode::planar ? "planar" : "orbit") << " target=" << c.target.x << ","
       << c.target.y << "," << c.target.z << " half_height=" << c.half_height << " distance=" << c.distance
       << " azimuth=" << c.azimuth_deg << " elevation=" << c.elevation_deg << " viewport=" << v.width << "x" << v.height
       << " pixels_per_unit=" << ppu.x;
  if (line.str() == last_view_) return;
  last_view_ = line.str();
  log_.line(last_view_);
}

}  // namespace amls::editor
