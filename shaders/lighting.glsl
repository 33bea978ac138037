// Library (put before a stage that calls shade): Blinn-Phong with a headlight.
const float kAmbient = 0.15;
const float kDiffuse = 0.85;
const float kSpecular = 0.25;
const float kShininess = 48.0;

// `normal` faces the viewer, `to_eye` is the unit vector from the surface to the eye.
// The light sits at the eye, so L = V and the half vector H = normalize(L + V) = V.
vec3 shade(vec3 base, vec3 normal, vec3 to_eye) {
  vec3 light = to_eye;
  vec3 half_vector = normalize(light + to_eye);
  float diffuse = max(dot(normal, light), 0.0);
  float specular = pow(max(dot(normal, half_vector), 0.0), kShininess);
  return min(base * (kAmbient + kDiffuse * diffuse) + vec3(kSpecular * specular), vec3(1.0));
}
