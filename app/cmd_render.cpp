// amls render: a point set, mesh or scene drawn headless (EGL or OSMesa) into a PNG.
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/picture_input.hpp"
#include "app/render_arguments.hpp"
#include "app/terminal_progress.hpp"
#include "core/surface/spacing_band.hpp"
#include "render/headless.hpp"
#include "render/offscreen_context.hpp"

namespace amls::app {

namespace {

struct RenderCommandOptions {
  std::string input;
  std::string out;
  std::string size = "800x600";
  std::string view;
  bool normals = false;
  std::string color = "uniform";
  std::string step;
  int grid = 0;
  double spacing = 0.0;
  double radius_factor = 3.0;
  int dimension = 0;
  int threads = 1;
  bool no_curve = false;
  bool no_handles = false;
  int supersample = 2;
  std::string gl_backend;
  std::string egl_device;
  bool verbose = false;
};

constexpr const char* kDescription =
    "draw a point set, mesh or scene into a PNG, headless (OpenGL 3.3 core through EGL - a GPU if there is one, else "
    "Mesa's llvmpipe - or OSMesa; no display needed; --verbose says which).\n"
    "INPUT: a point set (.ply, .off, .xyz, .pwn, .csv, .txt; 2D or 3D; normals estimated where the file has none), "
    "a triangle mesh (.obj, .stl, or .ply or .off with faces; sampled at h with face normals) or a scene (.json; its state "
    "after --step K steps, with its handles).\n"
    "3D: lit, oriented splats (back faces red) in perspective. Default view: azimuth 30, elevation 20 degrees - "
    "the eye on +z turned 30 degrees towards +x and raised 20 degrees, +y up - looking at the centre of the "
    "shape's extent and framed so that it fills the image less a small margin; --view changes the direction (and, "
    "with a distance, keeps that distance instead of fitting).\n"
    "2D: seen from above (x right, y up), orthographic, framed likewise: the points as cyan dots over the MLS curve "
    "in yellow (the zero set of F on the grid h with Delta = radius factor x h, traced by marching squares).\n"
    "Scenes' handles are white dots drawn on top.\n"
    "h: a scene's grid spacing; for files --spacing/--grid, else for a point set the median distance from a point "
    "to its 4th nearest neighbour, halved (as amls resample chooses it, but for its bound on a noisy scan), for a "
    "mesh its bounding-box diagonal / 200. Splat radius (1.2 h), normal length (2 h) and quality are in units of h.\n"
    "Examples:\n"
    "  amls render assets/scenes/clover2d.json --step last --out clover.png --size 480x360\n"
    "  amls render sphere.ply --out sphere.png --normals --view 45,30\n"
    "  amls render frame.ply --out quality.png --color quality --grid 256";

}  // namespace

void add_render_command(CLI::App& app) {
  auto options = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd = app.add_subcommand("render", kDescription);
  cmd->add_option("input", options->input,
                  "point set (.ply, .off, .xyz, .pwn, .csv, .txt), mesh (.obj, .stl, .ply, .off) or scene (.json)")
      ->required();
  cmd->add_option("--out", options->out, "PNG file to write (written whole or not at all)")->required();
  cmd->add_option("--size", options->size, "image size WIDTHxHEIGHT in pixels, each 1.." + format_number(ranges::kImageSide.max))
      ->capture_default_str();
  cmd->add_option("--view", options->view,
                  "3D only: az,el[,dist] - azimuth and elevation in degrees (elevation within +-89.9) and the eye's "
                  "distance from the shape's centre in world units (default: 30,20, framed to fit)");
  cmd->add_flag("--normals", options->normals, "draw each point's normal as a line 2 h long (blue)");
  cmd->add_option("--color", options->color,
                  "uniform (sand), normal (n * 0.5 + 0.5 as RGB) or quality (each point's nearest-neighbour spacing "
                  "in units of h on a viridis ramp from " + spacing_band_text(kSpacingBandLow) + " h, violet, to " +
                      spacing_band_text(kSpacingBandHigh) + " h, yellow)")
      ->check(CLI::IsMember({"uniform", "normal", "quality"}))
      ->capture_default_str();
  cmd->add_option("--step", options->step,
                  "scenes only: draw the state after K steps (0: the initial shape, resampled; 'last': after the whole "
                  "history), as `amls deform` writes frame K; runs the scene's deformation loop K steps");
  CLI::Option* grid =
      cmd->add_option("--grid", options->grid,
                      "point sets and meshes: N cells, h = 1/N within the unit square/cube, else the bounding box's "
                      "longest side / N")
          ->check(in_range(ranges::kGridCells));
  cmd->add_option("--spacing", options->spacing, "point sets and meshes: h itself (instead of --grid)")
      ->check(in_range(ranges::kSpacing))
      ->excludes(grid);
  cmd->add_option("--dim", options->dimension, "point sets: read as 2D or 3D (default: from the file)")
      ->check(CLI::IsMember({2, 3}));
  add_radius_factor_option(*cmd, options->radius_factor);
  add_threads_option(*cmd, options->threads);
  cmd->add_flag("--no-curve", options->no_curve, "2D: do not trace and draw the MLS curve");
  cmd->add_flag("--no-handles", options->no_handles, "scenes: do not draw the handles");
  cmd->add_option("--supersample", options->supersample,
                  "anti-aliasing: draw N times larger each way and average N x N pixels (1: off, exact colours)")
      ->check(in_range(ranges::kSupersample))
      ->capture_default_str();
  cmd->add_option("--gl-backend", options->gl_backend,
                  "headless OpenGL: auto (EGL on a device, GPUs first, then EGL surfaceless, then OSMesa), "
                  "egl-device, egl-surfaceless or osmesa (default: $AMLS_GL_BACKEND, else auto)");
  cmd->add_option("--egl-device", options->egl_device,
                  "the EGL device to draw on, by its index in eglQueryDevicesEXT's list (0, 1, ...; default: "
                  "$AMLS_EGL_DEVICE, else GPUs first, Mesa's software device last); implies egl-device");
  cmd->add_flag("--verbose", options->verbose, "also print which OpenGL drew the image (backend, device, GL_VERSION, "
                                               "GL_RENDERER) and the backends that failed before it");
  cmd->callback([options] {
    // Check everything that needs no work before the input is read (a scene may run for a while).
    const ImageSize size = parse_image_size(options->size, "--size");
    std::optional<OrbitView> view;
    if (!options->view.empty()) view = parse_view(options->view);
    RenderOptions render;
    render.color_mode = color_mode_from_string(options->color.c_str());
    render.show_normals = options->normals;
    render.show_handles = !options->no_handles;
    // The options, where given, replace the environment's choice whole (a variable set for other
    // programs never mixes with them).
    HeadlessGlChoice gl;
    if (options->gl_backend.empty() && options->egl_device.empty()) {
      gl = headless_gl_choice_from_environment();
    } else {
      gl.backend = headless_backend_from_string(options->gl_backend, "--gl-backend");
      if (!options->egl_device.empty())
        gl.egl_device = egl_device_index_from_string(options->egl_device, "--egl-device");
    }
    headless_backend_order(gl, headless_backends_built());  // a conflict or a backend not built: refused now

    PictureInputOptions input;
    if (!options->step.empty()) {
      if (options->step == "last") {
        input.step = kFinalStep;
      } else {
        std::size_t consumed = 0;
        unsigned long long k = 0;
        try {
          k = std::stoull(options->step, &consumed);
        } catch (const std::exception&) {
          consumed = 0;
        }
        if (consumed != options->step.size() || options->step.front() == '-')
          throw std::invalid_argument("--step must be a number of steps (0, 1, ...) or 'last', got '" + options->step +
                                      "'");
        input.step = static_cast<std::size_t>(k);
      }
    }
    input.spacing = options->spacing;
    input.grid = options->grid;
    input.radius_factor = options->radius_factor;
    input.dimension = options->dimension;
    input.threads = options->threads;
    input.curve = !options->no_curve;
    input.quality = render.color_mode == ColorMode::scalar;
    const Picture picture = [&] {
      TerminalProgress progress;  // a scene's run; the line is gone before the summary is printed
      PictureInputOptions with_progress = input;
      with_progress.progress = [&](std::size_t k, std::size_t n, std::size_t points) {
        progress.update(k, n, static_cast<double>(k), points);
      };
      return load_picture(options->input, with_progress);
    }();
    for (const std::string& warning : picture.warnings) std::cerr << "amls: warning: " << warning << "\n";
    if (picture.dimension == 2 && view)
      throw std::invalid_argument("--view is for 3D inputs; a 2D input is always seen from above, framed to fit");
    RenderJob job = picture_job(picture, size, view, render);
    job.supersample = options->supersample;
    job.gl = gl;
    const HeadlessGlInfo gl_used =
        render_to_png(options->out, job, [&](SplatRenderer& renderer) { picture.fill(renderer); });
    if (options->verbose) {
      for (const std::string& failure : gl_used.failures) std::cout << "OpenGL backend failed: " << failure << "\n";
      std::cout << "OpenGL: " << gl_used.summary() << "\n";
    }
    std::cout << picture.description << "\n";
    if (picture.dimension == 2 && input.curve) std::cout << "MLS curve: " << picture.curve.size() / 2 << " segments\n";
    std::cout << "wrote " << options->out << " (" << size.width << "x" << size.height << ")\n";
  });
}

}  // namespace amls::app
