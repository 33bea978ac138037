#pragma once
// What SplatRenderer::draw shows and how: plain settings, no GL.
#include <array>
#include <glm/glm.hpp>
#include <optional>

namespace amls {

// A rectangle of the framebuffer in pixels, origin at the bottom left (as glViewport).
struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;

  float aspect() const { return height > 0 ? static_cast<float>(width) / static_cast<float>(height) : 1.0f; }
};

enum class ColorMode {
  uniform,  // RenderOptions::surface_color
  normal,   // the world-space normal, n * 0.5 + 0.5
  scalar,   // the per-point scalar (e.g. sampling quality) through a colour ramp; uniform if none was set
};

// "uniform", "normal", "scalar" (also "quality" for scalar); throws std::invalid_argument otherwise.
ColorMode color_mode_from_string(const char* name);
const char* to_string(ColorMode mode);

enum class HandleState : int { idle = 0, hovered = 1, selected = 2, selected_hovered = 3 };

// A deformation handle as drawn: a dot of constant pixel size over everything.
struct Handle {
  glm::vec3 position{0.0f};  // world coordinates (z = 0 in 2D)
  HandleState state = HandleState::idle;
};

struct RenderOptions {
  // Points: oriented splats in 3D, round dots in 2D.
  bool show_points = true;
  ColorMode color_mode = ColorMode::uniform;
  // Splat radius in units of the point spacing. 1.2 closes a surface sampled at
  // about h (AMLS resampling leaves nearest-neighbour gaps up to ~1.5 h).
  float splat_scale = 1.2f;
  // Skip splats facing away from the eye: half the work for a closed surface seen from
  // outside, but back faces (and so flipped normals) no longer show.
  bool cull_back_faces = false;
  float point_size_px = 6.0f;  // 2D dots
  // Scalar colour range; none: the minimum and maximum of the scalars set.
  std::optional<glm::vec2> scalar_range;

  bool show_normals = false;
  float normal_length = 2.0f;  // in units of the point spacing (h)

  bool show_handles = true;
  float handle_size_px = 14.0f;

  bool show_curve = true;
  float line_width_px = 1.0f;  // clamped to what the GL implementation supports

  // 2D only (planar camera): grid lines every grid_spacing (0: the point spacing) from grid_origin.
  bool show_grid = false;
  float grid_spacing = 0.0f;
  glm::vec2 grid_origin{0.0f};

  bool clear = true;  // clear the viewport to `background` first
  glm::vec3 background{0.13f, 0.14f, 0.16f};
  glm::vec3 surface_color{0.85f, 0.75f, 0.55f};      // front faces in ColorMode::uniform
  glm::vec3 back_color{0.70f, 0.25f, 0.25f};         // back faces (normal facing away from the viewer)
  glm::vec3 missing_scalar_color{0.5f, 0.5f, 0.5f};  // NaN scalars
  glm::vec3 normal_color{0.30f, 0.65f, 1.00f};
  glm::vec3 curve_color{1.00f, 0.85f, 0.20f};
  glm::vec3 grid_color{0.22f, 0.23f, 0.26f};
  // Indexed by HandleState.
  std::array<glm::vec3, 4> handle_colors{glm::vec3{0.95f, 0.95f, 0.95f}, glm::vec3{1.00f, 0.60f, 0.10f},
                                         glm::vec3{0.20f, 0.90f, 0.35f}, glm::vec3{0.60f, 1.00f, 0.60f}};
};

// Throws std::invalid_argument naming the first size or length that is negative or not finite.
void validate(const RenderOptions& options);

}  // namespace amls
