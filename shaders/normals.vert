// Normals as segments, drawn instanced (one instance per point, two vertices each)
// from the point buffer itself: vertex 0 at the point, vertex 1 at the normal's tip.
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;

uniform mat4 u_view_projection;
uniform float u_length;  // world units

void main() {
  vec3 p = in_position + float(gl_VertexID) * u_length * in_normal;
  gl_Position = u_view_projection * vec4(p, 1.0);
}
