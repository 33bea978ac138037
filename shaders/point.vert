// 2D points (after color.glsl): round dots of a constant pixel size, drawn by dot.frag.
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in float in_scalar;

uniform mat4 u_view_projection;
uniform float u_point_size;  // pixels

flat out vec4 v_color;

void main() {
  gl_Position = u_view_projection * vec4(in_position, 1.0);
  gl_PointSize = u_point_size;
  v_color = vec4(point_color(in_normal, in_scalar), 1.0);
}
