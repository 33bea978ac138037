// 2D background grid: one-pixel lines at origin + k * spacing, computed per pixel
// (orthographic view only), so the grid costs no geometry whatever the zoom.
in vec2 v_ndc;

uniform mat4 u_inverse_view_projection;
uniform vec2 u_origin;
uniform float u_spacing;
uniform vec4 u_color;

out vec4 frag_color;

void main() {
  vec2 world = (u_inverse_view_projection * vec4(v_ndc, 0.0, 1.0)).xy;
  vec2 cells = (world - u_origin) / u_spacing;
  vec2 px_per_cell = 1.0 / fwidth(cells);
  if (min(px_per_cell.x, px_per_cell.y) < 4.0) discard;  // denser lines would fill the view
  vec2 to_line_px = abs(fract(cells + 0.5) - 0.5) * px_per_cell;
  if (min(to_line_px.x, to_line_px.y) > 0.5) discard;
  frag_color = u_color;
}
