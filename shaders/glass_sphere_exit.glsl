// Glass seen through both surfaces, a sphere's far side in closed form: the refracted ray
// crosses the sphere and leaves it at the far side, refracted again (n to air). Inside a sphere a
// ray meets the far side at the angle it entered, so it always leaves; the loop covers the total
// internal reflection other shapes would have. `origin` and `d` become the leaving ray. The
// lookups use it (environment_lookup.glsl), and so does glass traced through the Phong objects
// alone in a capture (exact_shade.glsl); the uniforms are environment.frag's.
void leaveGlassSphere(inout vec3 origin, inout vec3 d) {
  vec3 centre = u_glassSphere.xyz;
  for (int bounce = 0; bounce < 4; ++bounce) {
    vec3 offset = origin - centre;
    float b = dot(offset, d);
    float c = dot(offset, offset) - u_glassSphere.w * u_glassSphere.w;
    float t = -b + sqrt(max(b * b - c, 0.0));  // the far root: the ray starts on the surface
    origin += t * d;
    vec3 inward = -normalize(origin - centre);
    vec3 out_ = refract(d, inward, 1.0 / u_eta);
    if (dot(out_, out_) > 0.0) {
      d = out_;
      return;
    }
    d = reflect(d, inward);
  }
}
