// Library (put before a stage that calls point_color): the colour of a point.
uniform int u_color_mode;  // ColorMode: 0 uniform, 1 normal, 2 scalar
uniform vec3 u_surface_color;
uniform vec2 u_scalar_range;  // (low, high)
uniform vec3 u_missing_scalar_color;

// A perceptually ordered ramp: viridis, piecewise linear through five of its stops.
vec3 color_ramp(float t) {
  const vec3 stops[5] = vec3[5](vec3(0.267, 0.005, 0.329), vec3(0.229, 0.322, 0.546), vec3(0.128, 0.567, 0.551),
                               vec3(0.369, 0.789, 0.383), vec3(0.993, 0.906, 0.144));
  float x = clamp(t, 0.0, 1.0) * 4.0;
  int i = min(int(x), 3);
  return mix(stops[i], stops[i + 1], x - float(i));
}

vec3 point_color(vec3 normal, float scalar) {
  if (u_color_mode == 1) return 0.5 * normal + 0.5;
  if (u_color_mode == 2) {
    if (isnan(scalar)) return u_missing_scalar_color;
    float span = u_scalar_range.y - u_scalar_range.x;
    return color_ramp(span > 0.0 ? (scalar - u_scalar_range.x) / span : 0.5);
  }
  return u_surface_color;
}
