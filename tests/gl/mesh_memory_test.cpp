// What the demo keeps of its meshes, by the byte: level 0's arrays exactly sized (no text, no
// slack from growing), coarser levels as index lists over level 0's vertices (no vertex copies),
// levels only while a LOD setting is on; and chunks and levels built after the first frame.
#include <gtest/gtest.h>

#include "app/headless_frames.h"
#include "core/scene_file.h"
#include "gfx/mesh_buffer.h"
#include "gl_fixture.h"
#include "platform/native/model_paths.h"

namespace reflect {
namespace {

// The bytes meshCpuBytes() must report when every array is exactly sized.
size_t exactCpuBytes(const Demo& demo) {
  size_t bytes = 0;
  for (const std::string& name : demo.scene().meshNames()) {
    const std::vector<Demo::LevelInfo> levels = demo.levelInfo(name);
    const MeshData* base = demo.meshLevel(name, 0);
    EXPECT_NE(base, nullptr) << name;
    if (!base) continue;
    EXPECT_EQ(base->vertices.capacity(), base->vertices.size()) << name;
    EXPECT_EQ(base->indices.capacity(), base->indices.size()) << name;
    bytes += base->vertices.size() * sizeof(Vertex) + base->indices.size() * sizeof(uint32_t) +
             base->chunks.capacity() * sizeof(MeshChunk);
    for (size_t k = 1; k < levels.size(); ++k) {
      bytes += levels[k].triangles * 3 * sizeof(uint32_t) + levels[k].chunks * sizeof(MeshChunk);
    }
  }
  return bytes;
}

size_t exactGpuBytes(const Demo& demo) {
  size_t bytes = 0;
  for (const std::string& name : demo.scene().meshNames()) {
    for (const Demo::LevelInfo& level : demo.levelInfo(name)) {
      bytes += level.vertices * sizeof(Vertex) + level.triangles * 3 * sizeof(uint32_t);
    }
  }
  return bytes;
}

TEST(MeshMemory, TheCpuKeepsTheMeshesArraysAndNothingElse) {
  Demo demo(makeDynamicReflectionScene());
  ASSERT_EQ(loadSceneModels(demo, ""), "");
  // As parsed: no chunks, no levels yet; the arrays exactly sized (the parser's blocks are gone,
  // and the file's text was never kept).
  for (const std::string& name : demo.scene().meshNames()) {
    EXPECT_EQ(demo.levelInfo(name).size(), 1u) << name;
    EXPECT_EQ(demo.meshLevel(name, 0)->chunks.size(), 0u) << name;
  }
  EXPECT_FALSE(demo.lodReady());
  EXPECT_EQ(demo.meshCpuBytes(), exactCpuBytes(demo));
  EXPECT_EQ(demo.meshGpuBytes(), exactGpuBytes(demo));

  demo.waitForLevels();  // captureLod is on by default: chunks and coarser levels
  EXPECT_TRUE(demo.lodReady());
  const std::vector<Demo::LevelInfo> mario = demo.levelInfo("mario.obj");
  ASSERT_EQ(mario.size(), 3u);
  EXPECT_GT(mario[0].chunks, 1u);
  for (size_t k = 1; k < mario.size(); ++k) {
    EXPECT_LT(mario[k].triangles, mario[k - 1].triangles) << k;
    EXPECT_LT(mario[k].vertices, mario[0].vertices) << k;  // the GPU's copy is compact
    EXPECT_GE(mario[k].chunks, 1u) << k;
  }
  EXPECT_EQ(demo.meshCpuBytes(), exactCpuBytes(demo));
  EXPECT_EQ(demo.meshGpuBytes(), exactGpuBytes(demo));
  // The coarser levels cost the CPU their indices only: less than a copy of their vertices would.
  const MeshData& base = *demo.meshLevel("mario.obj", 0);
  size_t coarserCpu = 0, coarserAsMeshes = 0;
  for (size_t k = 1; k < mario.size(); ++k) {
    coarserCpu += mario[k].triangles * 3 * sizeof(uint32_t);
    coarserAsMeshes +=
        mario[k].triangles * 3 * sizeof(uint32_t) + mario[k].vertices * sizeof(Vertex);
  }
  EXPECT_LT(coarserCpu, coarserAsMeshes);
  EXPECT_EQ(base.vertices.capacity(), base.vertices.size());
}

TEST(MeshMemory, NoCoarserLevelWhileEveryLodSettingIsOff) {
  Demo demo(makeDynamicReflectionScene());
  PlannerSettings off;
  off.captureLod = 0.0f;
  off.viewLod = 0.0f;
  demo.setPlannerSettings(off);
  ASSERT_EQ(loadSceneModels(demo, ""), "");
  demo.waitForLevels();
  EXPECT_TRUE(demo.lodReady());
  for (const std::string& name : demo.scene().meshNames()) {
    EXPECT_EQ(demo.levelInfo(name).size(), 1u) << name;  // chunks, but no level nobody draws
    EXPECT_GE(demo.levelInfo(name)[0].chunks, 1u) << name;
  }
  // Turned on, the levels are built.
  demo.setPlannerSettings(PlannerSettings{});
  EXPECT_FALSE(demo.lodReady());
  demo.waitForLevels();
  EXPECT_EQ(demo.levelInfo("mario.obj").size(), 3u);
}

// Natively the first frame is drawn from the meshes as parsed; chunks and levels are built on a
// thread started after it and join a later frame (waitForLevels() waits for them).
TEST(MeshMemory, TheFirstFrameComesBeforeTheLevels) {
  auto demo = std::make_unique<Demo>(makeDynamicReflectionScene());
  ASSERT_EQ(loadSceneModels(*demo, ""), "");
  ASSERT_EQ(demo->initGraphics(), "");
  const size_t full = demo->levelInfo("mario.obj")[0].triangles;
  Result<RgbaImage> first = renderFrameAt(*demo, 0.0, 64, 64);
  ASSERT_TRUE(first) << first.error();
  EXPECT_FALSE(demo->lastStats().lodReady);
  EXPECT_EQ(demo->levelInfo("mario.obj").size(), 1u);  // nothing was built before it
  EXPECT_EQ(demo->levelInfo("mario.obj")[0].chunks, 0u);
  EXPECT_EQ(demo->levelInfo("mario.obj")[0].triangles, full);
  demo->waitForLevels();
  Result<RgbaImage> later = renderFrameAt(*demo, 0.0, 64, 64);
  ASSERT_TRUE(later) << later.error();
  EXPECT_TRUE(demo->lastStats().lodReady);
  EXPECT_EQ(demo->levelInfo("mario.obj").size(), 3u);
}

// Every renderer of a demo (the frame's, and the error view's exact one) draws from one GPU copy
// of each mesh level: turning the error view on uploads nothing, and the buffers alive hold
// exactly the bytes meshGpuBytes() reports.
TEST(MeshMemory, TheErrorViewDrawsFromTheSameGpuMeshes) {
  const long buffersBefore = gLiveMeshBuffers;
  const size_t bytesBefore = gLiveMeshBufferBytes;
  std::unique_ptr<Demo> demo = testing::makeDemo(makeDynamicReflectionScene());
  demo->waitForLevels();
  ASSERT_TRUE(renderFrameAt(*demo, 1.0, 64, 64));
  size_t levels = 0;
  for (const std::string& name : demo->scene().meshNames()) levels += demo->levelInfo(name).size();
  ASSERT_NE(demo->gpuMeshes(), nullptr);
  EXPECT_EQ(demo->gpuMeshes()->levelCount(), levels);
  EXPECT_GT(levels, demo->scene().meshNames().size());  // coarser levels are on the GPU too
  const long buffers = gLiveMeshBuffers - buffersBefore;
  EXPECT_EQ(buffers, static_cast<long>(levels));
  EXPECT_EQ(gLiveMeshBufferBytes - bytesBefore, demo->meshGpuBytes());

  ASSERT_EQ(demo->setShowError(true), "");
  ASSERT_TRUE(renderFrameAt(*demo, 1.0, 64, 64));
  EXPECT_TRUE(demo->lastStats().errorView);
  EXPECT_EQ(gLiveMeshBuffers - buffersBefore, buffers);
  EXPECT_EQ(gLiveMeshBufferBytes - bytesBefore, demo->meshGpuBytes());
  // New settings remake both renderers; the meshes stay as they are.
  AccuracySettings hierarchical = demo->accuracySettings();
  hierarchical.search = Search::Hierarchical;
  ASSERT_EQ(demo->setAccuracySettings(hierarchical), "");
  ASSERT_TRUE(renderFrameAt(*demo, 1.5, 64, 64));
  EXPECT_TRUE(demo->lastStats().errorView);
  EXPECT_EQ(gLiveMeshBuffers - buffersBefore, buffers);

  // A lost context forgets them; the restore uploads each level once again.
  demo->loseGraphics();
  EXPECT_EQ(gLiveMeshBuffers, buffersBefore);
  ASSERT_EQ(demo->initGraphics(), "");
  ASSERT_TRUE(renderFrameAt(*demo, 1.5, 64, 64));
  EXPECT_TRUE(demo->lastStats().errorView);
  EXPECT_EQ(gLiveMeshBuffers - buffersBefore, buffers);
  demo->releaseGraphics();
  EXPECT_EQ(gLiveMeshBuffers, buffersBefore);
  EXPECT_EQ(gLiveMeshBufferBytes, bytesBefore);
}

}  // namespace
}  // namespace reflect
