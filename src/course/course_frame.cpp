// The course's Ex12-2 frame, all of it. Each frame a cube map is rendered from where the course
// places the mirror sphere (six faces, 90 degrees, aspect 1, into a framebuffer); the sphere shows
// 0.78 x what the cube map holds along the reflected ray + 0.3 x its gold base colour. The rest of
// the project (planner, traced default, searches) is elsewhere; this file needs none of it.
#include "course/course_frame.h"

#include <glm/gtc/matrix_transform.hpp>
#include <tuple>

#include "core/normal_matrix.h"
#include "gfx/gl.h"
#include "gfx/gl_handle.h"
#include "gfx/shader_program.h"

namespace reflect {
namespace {

// --- The shaders (ShaderProgram puts "#version 300 es" and precision first). Every mesh:
// world-space position and normal, for lighting per fragment.
const char* const kVertexShader = R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_viewProjection, u_model;
uniform mat3 u_normalMatrix;
out vec3 v_worldPosition, v_worldNormal;
void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_worldPosition = world.xyz;
  v_worldNormal = u_normalMatrix * a_normal;
  gl_Position = u_viewProjection * world;
})";

// The figures and the ground: Phong, white specular only where the light reaches the front.
const char* const kPhongShader = R"(
in vec3 v_worldPosition, v_worldNormal;
uniform vec3 u_colour, u_lightPosition, u_eye;
uniform vec4 u_terms;  // the light's ambient, diffuse, specular and shininess
out vec4 fragColour;
void main() {
  vec3 N = normalize(v_worldNormal);
  vec3 L = normalize(u_lightPosition - v_worldPosition);
  vec3 V = normalize(u_eye - v_worldPosition);
  float nDotL = max(dot(N, L), 0.0);
  vec3 c = u_colour * (u_terms.x + u_terms.y * nDotL);
  if (nDotL > 0.0) c += vec3(u_terms.z * pow(clamp(dot(reflect(-L, N), V), 0.0, 1.0), u_terms.w));
  fragColour = vec4(c, 1.0);
})";

// The sphere: the cube map looked up along the reflected view ray, mixed with the base colour.
const char* const kMirrorShader = R"(
in vec3 v_worldPosition, v_worldNormal;
uniform samplerCube u_cube;
uniform vec3 u_colour, u_eye;
uniform float u_reflection, u_base;  // 0.78 and 0.3: they sum past 1, so highlights clip
out vec4 fragColour;
void main() {
  vec3 N = normalize(v_worldNormal);
  vec3 I = normalize(v_worldPosition - u_eye);
  vec3 R = reflect(I, N);
  fragColour = vec4(u_base * u_colour + u_reflection * texture(u_cube, R).rgb, 1.0);
})";

// --- The face table: where each face looks, and which way is up in it (GL's convention: the
// faces are seen from inside the cube, so up is -Y on the four side faces). ---
struct Face {
  GLenum target;
  glm::vec3 look, up;
};
const Face kFaces[6] = {
    {GL_TEXTURE_CUBE_MAP_POSITIVE_X, {1, 0, 0}, {0, -1, 0}},
    {GL_TEXTURE_CUBE_MAP_NEGATIVE_X, {-1, 0, 0}, {0, -1, 0}},
    {GL_TEXTURE_CUBE_MAP_POSITIVE_Y, {0, 1, 0}, {0, 0, 1}},
    {GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, {0, -1, 0}, {0, 0, -1}},
    {GL_TEXTURE_CUBE_MAP_POSITIVE_Z, {0, 0, 1}, {0, -1, 0}},
    {GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, {0, 0, -1}, {0, -1, 0}},
};

}  // namespace
// --- The state: two programs, the cube texture, its depth buffer, the framebuffer. ---
struct CourseFrame::State {
  ShaderProgram phong, mirror;
  TextureHandle cube;
  RenderbufferHandle depth;
  FramebufferHandle framebuffer;
  int faceSize = 0;
  // Draws `object` with `program`, which is in use.
  static PassCounts drawObject(const ShaderProgram& program, const Scene& scene,
                               const SceneObject& object, double seconds,
                               const MeshBuffers& meshes) {
    const MeshBuffer* mesh = meshes.find(object.mesh, 0);
    if (!mesh) return {};
    const glm::mat4 model = scene.modelMatrix(object, seconds);  // Ry(orbit) T S
    const glm::mat3 normals = normalMatrixOf(glm::mat3(model));  // the inverse transpose x det
    glUniformMatrix4fv(program.uniform("u_model"), 1, GL_FALSE, &model[0][0]);
    glUniformMatrix3fv(program.uniform("u_normalMatrix"), 1, GL_FALSE, &normals[0][0]);
    glUniform3fv(program.uniform("u_colour"), 1, &object.colour[0]);
    mesh->draw();
    return {1, mesh->triangleCount()};
  }

  // Every Phong object: the whole scene but the sphere, which cannot see itself.
  PassCounts drawPhong(const Scene& scene, double seconds, const MeshBuffers& meshes,
                       const glm::mat4& viewProjection, const glm::vec3& eye) const {
    glUseProgram(phong.id());
    glUniformMatrix4fv(phong.uniform("u_viewProjection"), 1, GL_FALSE, &viewProjection[0][0]);
    // The course lights the faces as seen from the main camera's eye too.
    glUniform3fv(phong.uniform("u_eye"), 1, &eye[0]);
    const PhongLight& l = scene.light;
    glUniform3fv(phong.uniform("u_lightPosition"), 1, &l.position[0]);
    glUniform4f(phong.uniform("u_terms"), l.ambient, l.diffuse, l.specular, l.shininess);
    PassCounts counts;
    for (const SceneObject& o : scene.objects) {
      if (o.material == Material::Phong) counts += drawObject(phong, scene, o, seconds, meshes);
    }
    return counts;
  }
};

Result<CourseFrame> CourseFrame::create(int faceSize) {
  auto s = std::make_shared<State>();
  for (auto [program, name, source] : {std::tuple{&s->phong, "course (phong)", kPhongShader},
                                       std::tuple{&s->mirror, "course (mirror)", kMirrorShader}}) {
    Result<ShaderProgram> built =
        ShaderProgram::buildFromSource("course (vertex)", kVertexShader, name, source);
    if (!built) return Result<CourseFrame>::failure(built.error());
    *program = built.take();
  }
  // The cube texture: six RGBA8 faces, filtered linearly (across the seams: GL ES 3 always
  // filters cube maps seamlessly, so no wrap mode applies), no mipmaps.
  s->faceSize = faceSize;
  s->cube = TextureHandle(genTexture());
  glBindTexture(GL_TEXTURE_CUBE_MAP, s->cube.id());
  glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_RGBA8, faceSize, faceSize);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // The framebuffer the faces are drawn through, with a 16-bit depth buffer.
  s->depth = RenderbufferHandle(genRenderbuffer());
  glBindRenderbuffer(GL_RENDERBUFFER, s->depth.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT16, faceSize, faceSize);
  s->framebuffer = FramebufferHandle(genFramebuffer());
  glBindFramebuffer(GL_FRAMEBUFFER, s->framebuffer.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, s->depth.id());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!checkGlError("course frame: create")) {
    return Result<CourseFrame>::failure("course frame: GL error while creating its objects");
  }
  CourseFrame frame;
  frame.state_ = std::move(s);
  return frame;
}

// 1. The six faces, from the origin, where the course places the sphere: 90 degrees, aspect 1.
PassCounts CourseFrame::captureFaces(const Scene& scene, double seconds, const MeshBuffers& meshes,
                                     const glm::vec3& eye) {
  const State& s = *state_;
  PassCounts counts;
  glEnable(GL_DEPTH_TEST);
  glClearColor(scene.clearColour.r, scene.clearColour.g, scene.clearColour.b, 1.0f);
  const glm::mat4 projection =
      glm::perspective(glm::radians(90.0f), 1.0f, scene.capture.near, scene.capture.far);
  glBindFramebuffer(GL_FRAMEBUFFER, s.framebuffer.id());
  glViewport(0, 0, s.faceSize, s.faceSize);
  for (const Face& face : kFaces) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, face.target, s.cube.id(), 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f), face.look, face.up);
    counts += s.drawPhong(scene, seconds, meshes, projection * view, eye);
  }
  return counts;
}

// 2. The main pass: the Phong objects, then the sphere with the cube map.
PassCounts CourseFrame::drawMain(const Scene& scene, double seconds, const MeshBuffers& meshes,
                                 const glm::mat4& view, const glm::mat4& projection,
                                 const glm::vec3& eye, unsigned framebuffer, int width,
                                 int height) {
  const State& s = *state_;
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const glm::mat4 viewProjection = projection * view;
  PassCounts counts = s.drawPhong(scene, seconds, meshes, viewProjection, eye);
  const ShaderProgram& mirror = s.mirror;  // 0.78 x the cube along reflect(I, N) + 0.3 x gold
  glUseProgram(mirror.id());
  glUniformMatrix4fv(mirror.uniform("u_viewProjection"), 1, GL_FALSE, &viewProjection[0][0]);
  glUniform3fv(mirror.uniform("u_eye"), 1, &eye[0]);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, s.cube.id());
  glUniform1i(mirror.uniform("u_cube"), 0);
  const SceneObject& sphere = scene.objects[static_cast<size_t>(scene.reflectorIndex())];
  glUniform1f(mirror.uniform("u_reflection"), sphere.reflection);
  glUniform1f(mirror.uniform("u_base"), sphere.base);
  counts += State::drawObject(mirror, scene, sphere, seconds, meshes);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindVertexArray(0);
  checkGlError("course frame");
  return counts;
}

}  // namespace reflect
