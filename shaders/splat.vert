// Splats, stage 1 (after color.glsl and lighting.glsl): one point becomes one
// screen-aligned square (GL_POINTS) just large enough to hold its disk; splat.frag cuts
// the disk out. The disk is flat, so its shading is computed here once, along the ray
// to its centre: within a splat only the view direction changes, and that only slightly.
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in float in_scalar;

uniform mat4 u_view;
uniform mat4 u_projection;  // glm::perspective or a centred glm::ortho
uniform vec4 u_viewport;    // x, y, width, height in pixels
uniform float u_radius;     // disk radius, world units
uniform float u_near;       // near-plane distance (perspective)
uniform bool u_perspective;
uniform float u_max_point_size;
uniform bool u_cull_back_faces;
uniform vec3 u_back_color;

flat out vec3 v_center;  // view space
flat out vec3 v_normal;  // view space, unit
flat out vec3 v_color;  // shaded

void main() {
  vec3 c = (u_view * vec4(in_position, 1.0)).xyz;
  vec3 n = normalize(mat3(u_view) * in_normal);
  v_center = c;
  v_normal = n;
  gl_Position = u_projection * vec4(c, 1.0);
  // A normal pointing away from the eye is a back face.
  vec3 to_eye = u_perspective ? normalize(-c) : vec3(0.0, 0.0, 1.0);
  bool back = dot(n, to_eye) < 0.0;
  if (back && u_cull_back_faces) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: dropped
    gl_PointSize = 1.0;
    return;
  }
  v_color = back ? shade(u_back_color, -n, to_eye) : shade(point_color(in_normal, in_scalar), n, to_eye);

  // The disk's view-space bounding box: along axis i it reaches r * sqrt(1 - n_i^2) from c.
  vec3 reach = u_radius * sqrt(max(vec3(1.0) - n * n, vec3(0.0)));
  vec2 half_extent;  // of the disk's image about the centre's image, in NDC / focal length
  if (u_perspective) {
    float nearest = -(c.z + reach.z), farthest = -(c.z - reach.z);
    if (nearest <= u_near) {
      // The disk may reach the near plane: drop it.
      gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
      gl_PointSize = 1.0;
      return;
    }
    // x / -z is monotonic in x and in z, so the box's image is bounded by its corners' images.
    vec2 lo = c.xy - reach.xy, hi = c.xy + reach.xy;
    vec2 image_lo = min(lo / nearest, lo / farthest);
    vec2 image_hi = max(hi / nearest, hi / farthest);
    vec2 centre = c.xy / -c.z;
    half_extent = max(image_hi - centre, centre - image_lo);
  } else {
    half_extent = reach.xy;
  }
  vec2 half_px = half_extent * vec2(u_projection[0][0], u_projection[1][1]) * 0.5 * u_viewport.zw;
  // +1: half a pixel of margin on each side against rounding.
  gl_PointSize = min(2.0 * max(half_px.x, half_px.y) + 1.0, u_max_point_size);
}
