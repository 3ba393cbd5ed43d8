// A glass object's interior map (gfx/glass_interior_map): the outward normal of the surface nearest
// the map's centre, in the mesh's own coordinates (mesh.vert's "world" is the mesh moved to put
// the centre at the origin, with an identity normal matrix). The depth buffer keeps the depth.
in vec3 v_worldNormal;

layout(location = 0) out vec4 fragColour;

void main() {
  vec3 n = v_worldNormal;
  // A degenerate normal would decode to no direction at all; any unit vector is better.
  n = dot(n, n) > 0.0 ? normalize(n) : vec3(0.0, 0.0, 1.0);
  fragColour = vec4(n * 0.5 + 0.5, 1.0);
}
