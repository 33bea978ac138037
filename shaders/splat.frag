// Splats, stage 2: the ray through this pixel meets the disk's plane; outside the disk
// the fragment is discarded, inside it gets the depth of the hit point (perspective-correct)
// and the splat's colour, shaded in splat.vert.
flat in vec3 v_center;
flat in vec3 v_normal;
flat in vec3 v_color;  // shaded

uniform mat4 u_projection;
uniform bool u_perspective;
// Window position -> view-space ray: xy = gl_FragCoord.xy * scale + offset is the ray's
// direction at z = -1 (perspective, from the eye) or its origin at z = 0 (orthographic).
uniform vec4 u_pixel_to_ray;  // scale.xy, offset.zw
uniform float u_radius;

out vec4 frag_color;

void main() {
  vec2 xy = gl_FragCoord.xy * u_pixel_to_ray.xy + u_pixel_to_ray.zw;
  vec3 origin = u_perspective ? vec3(0.0) : vec3(xy, 0.0);
  vec3 direction = u_perspective ? vec3(xy, -1.0) : vec3(0.0, 0.0, -1.0);

  float facing = dot(v_normal, direction);
  if (facing == 0.0) discard;  // seen exactly edge-on
  // hit = origin + t direction; both rays have direction.z = -1, so the hit's view z is -t.
  float t = dot(v_normal, v_center - origin) / facing;
  vec3 hit = origin + t * direction;
  vec3 offset = hit - v_center;
  // (Perspective: a hit behind the eye is no hit. Orthographic: the origin plane z = 0 is
  // arbitrary, so any t counts; the clip volume keeps what is visible.)
  if ((u_perspective && t <= 0.0) || dot(offset, offset) > u_radius * u_radius) discard;

  float z = -t;
  float clip_w = u_perspective ? t : 1.0;
  float ndc_z = (u_projection[2][2] * z + u_projection[3][2]) / clip_w;
  gl_FragDepth = 0.5 * gl_DepthRange.diff * ndc_z + 0.5 * (gl_DepthRange.near + gl_DepthRange.far);
  frag_color = vec4(v_color, 1.0);
}
