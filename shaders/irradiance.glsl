// Diffuse light from a live probe (docs/rough.md, "Diffuse light from the probe"): the
// irradiance E(n) a probe's capture gives a surface of normal n, as order-2 real spherical
// harmonics. irradiance_project.vert projects the capture on the nine basis functions and scales
// each coefficient by its band's cosine-lobe factor over pi (1, 2/3, 1/4: Ramamoorthi and
// Hanrahan's A_l / pi), so that E(n) / pi, the light a white Lambertian surface sends back, is
// sum_i c_i Y_i(n). core/irradiance.h says the same for the C++ and its tests.

// Y_i(n) for i = 0..8 in the order (l, m) = (0, 0), (1, -1), (1, 0), (1, 1), (2, -2), (2, -1),
// (2, 0), (2, 1), (2, 2); n unit.
float shBasis(vec3 n, int i) {
  if (i == 0) return 0.282095;
  if (i == 1) return 0.488603 * n.y;
  if (i == 2) return 0.488603 * n.z;
  if (i == 3) return 0.488603 * n.x;
  if (i == 4) return 1.092548 * n.x * n.y;
  if (i == 5) return 1.092548 * n.y * n.z;
  if (i == 6) return 0.315392 * (3.0 * n.z * n.z - 1.0);
  if (i == 7) return 1.092548 * n.x * n.z;
  return 0.546274 * (n.x * n.x - n.y * n.y);
}

// The nine at once, in that order: Y_0..3 in a, Y_4..7 in b, Y_8 in c. Evaluating coefficients
// with these costs a few multiply-adds where a loop over shBasis runs its branches every turn.
void shBasisAll(vec3 n, out vec4 a, out vec4 b, out float c) {
  a = vec4(0.282095, 0.488603 * n.y, 0.488603 * n.z, 0.488603 * n.x);
  b = vec4(1.092548 * n.x * n.y, 1.092548 * n.y * n.z, 0.315392 * (3.0 * n.z * n.z - 1.0),
           1.092548 * n.x * n.z);
  c = 0.546274 * (n.x * n.x - n.y * n.y);
}

// The cosine lobe's factor for the band of coefficient i, over pi.
float shBandFactor(int i) {
  if (i == 0) return 1.0;
  if (i < 4) return 2.0 / 3.0;
  return 0.25;
}
