// Every mesh: world-space position and normal for per-fragment lighting, and the object-space
// position for Ex12-1's cube-textured material. AMBIENT_PROBE (a probe-lit object): also its
// irradiance's parallax, which parallax_feedback.vert computed for each vertex of the mesh (0 where
// the object sets a radius instead: the attribute is then off).
// (#version and precision are prepended by ShaderProgram.)
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_viewProjection;
uniform mat4 u_model;
uniform mat3 u_normalMatrix;  // inverse-transpose of u_model's upper 3x3

out vec3 v_worldPosition;
out vec3 v_worldNormal;
out vec3 v_objectPosition;

#if defined(AMBIENT_PROBE) && AMBIENT_PROBE
layout(location = 2) in vec3 a_ambientParallax;
out vec3 v_ambientParallax;
#endif

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_worldPosition = world.xyz;
  v_worldNormal = u_normalMatrix * a_normal;
  v_objectPosition = a_position;
  gl_Position = u_viewProjection * world;
#if defined(AMBIENT_PROBE) && AMBIENT_PROBE
  v_ambientParallax = a_ambientParallax;
#endif
}
