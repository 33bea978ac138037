#include "render/frame.hpp"

#include "render/shader_program.hpp"

namespace amls {

void set_color_uniforms(const ShaderProgram& program, const Frame& frame) {
  program.set("u_color_mode", static_cast<int>(frame.color_mode));
  program.set("u_surface_color", frame.options.surface_color);
  program.set("u_scalar_range", frame.scalar_range);
  program.set("u_missing_scalar_color", frame.options.missing_scalar_color);
}

}  // namespace amls
