// Handles: round dots of a constant pixel size, coloured by state, drawn by dot.frag.
layout(location = 0) in vec3 in_position;
layout(location = 1) in float in_state;  // HandleState: 0 idle, 1 hovered, 2 selected, 3 selected and hovered

uniform mat4 u_view_projection;
uniform float u_point_size;  // pixels
uniform vec4 u_state_colors[4];

flat out vec4 v_color;

void main() {
  gl_Position = u_view_projection * vec4(in_position, 1.0);
  gl_PointSize = u_point_size;
  v_color = u_state_colors[clamp(int(in_state + 0.5), 0, 3)];
}
