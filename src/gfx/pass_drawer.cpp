#include "gfx/pass_drawer.h"

#include <algorithm>
#include <type_traits>

#include "core/frustum.h"
#include "core/normal_matrix.h"

namespace reflect {

namespace {

// Back faces off for a closed solid the eye sees from outside only (DrawPass::cullReach), wound
// as its model leaves it (a mirroring scale turns it inside out).
void setFaceCulling(const DrawPass& pass, const MeshBuffer& buffer, const Bounds& world,
                    const glm::mat4& model) {
  const bool cull = pass.cullReach > 0.0f && buffer.closedOutward() &&
                    distanceToBox(pass.environmentEye, world) > pass.cullReach;
  if (!cull) {
    glDisable(GL_CULL_FACE);
    return;
  }
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(glm::determinant(glm::mat3(model)) < 0.0f ? GL_CW : GL_CCW);
}

}  // namespace

void PassDrawer::setForPass(const PhongUniforms& u, const ProgramKey&, const DrawPass& pass) const {
  u.mesh.viewPosition.set(pass.lightingEye);
  u.setLight(pass.scene.light);
}

void PassDrawer::setForPass(const EnvironmentUniforms& u, const ProgramKey& key,
                            const DrawPass& pass) const {
  u.mesh.viewPosition.set(pass.environmentEye);
  u.outputDirection.set(pass.outputDirections);
  environments_.bindTracer(u, key);
}

void PassDrawer::setForPass(const CubeTexturedUniforms& u, const ProgramKey&,
                            const DrawPass& pass) const {
  u.mesh.viewPosition.set(pass.environmentEye);
}

template <typename Uniforms>
PassCounts PassDrawer::drawObject(const Uniforms& u, const ProgramKey& key, const DrawPass& pass,
                                  const DrawItem& item) const {
  const SceneObject& object = pass.scene.objects[static_cast<size_t>(item.object)];
  const MeshBuffer* buffer = mesh(object.mesh, item.lod);
  if (!buffer) return {};
  const glm::mat4& model = pass.plan.modelOf(item.object);
  u.mesh.model.set(model);
  u.mesh.normalMatrix.set(normalMatrixOf(glm::mat3(model)));
  // The object's size, for the third capture pass (capture_output.glsl).
  const Bounds world = transformBounds(buffer->bounds(), model);
  u.mesh.capture.extent.set(glm::length(world.max - world.min) / pass.scene.capture.near);
  setFaceCulling(pass, *buffer, world, model);
  u.mesh.colour.set(object.colour);
  environments_.setForObject(u, key, pass.scene, pass.plan, item.object);
  GLuint perVertex = 0;
  if constexpr (std::is_same_v<Uniforms, PhongUniforms>) {
    if (key.probeLight)
      perVertex = environments_.parallaxFor(pass.scene, pass.plan, item.object, *buffer);
  }
  buffer->draw(item.ranges, perVertex);
  const size_t triangles = item.ranges.empty() ? buffer->triangleCount() : item.triangles;
  return {static_cast<int>(std::max<size_t>(item.ranges.size(), 1)), triangles};
}

PassCounts PassDrawer::draw(const DrawPass& pass, const std::vector<DrawItem>& draws) const {
  // One program switch per variant present, in the keys' order (Phong first).
  std::vector<std::pair<ProgramKey, const DrawItem*>> keyed;
  keyed.reserve(draws.size());
  for (const DrawItem& d : draws) {
    keyed.emplace_back(environments_.keyFor(pass.scene, pass.plan, d, pass.capture), &d);
  }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  PassCounts counts;
  for (size_t i = 0; i < keyed.size();) {
    size_t end = i;
    while (end < keyed.size() && keyed[end].first == keyed[i].first) ++end;
    ProgramKey key = keyed[i].first;
    const SceneProgram* p = programs_.get(key);
    if (!p && key.glassExit) {  // no interior-map program: glass leaves at one surface
      key.glassExit = false;
      p = programs_.get(key);
    }
    if (p) {
      glUseProgram(p->id());
      const MeshPassUniforms& mesh = p->mesh();
      mesh.capture.set(pass.capture);
      mesh.viewProjection.set(pass.viewProjection);
      // The program's own type from here on: each setter reaches its own table alone.
      std::visit(
          [&](const auto& program) {
            setForPass(program.u(), key, pass);
            for (size_t k = i; k < end; ++k) {
              counts += drawObject(program.u(), key, pass, *keyed[k].second);
            }
          },
          p->program);
    }
    i = end;
  }
  return counts;
}

}  // namespace reflect
