// A round dot with an outline, cut from a GL_POINTS square.
flat in vec4 v_color;

uniform float u_point_size;  // pixels
uniform float u_outline_px;  // outline width, pixels (0: none)
uniform vec4 u_outline_color;

out vec4 frag_color;

void main() {
  float radius = 0.5 * u_point_size;
  float from_centre = length(gl_PointCoord - 0.5) * u_point_size;
  if (from_centre > radius) discard;
  frag_color = from_centre > radius - u_outline_px ? u_outline_color : v_color;
}
