// GL lifetime without lists: a handle knows the context generation it was made in, so a lost
// context is forgotten through the handles themselves, and a live one is still freed.
#include <gtest/gtest.h>

#include "core/scene.h"
#include "gfx/gl_handle.h"
#include "gl_fixture.h"

namespace reflect {
namespace {

// The tests' context (gl_fixture: one for the run) is never really lost, so a name a handle deleted
// is gone and a name it forgot is still there: glIsTexture tells the two apart.
bool textureExists(GLuint name) {
  return glIsTexture(name) == GL_TRUE;
}

GLuint makeBoundTexture() {
  const GLuint name = genTexture();
  glBindTexture(GL_TEXTURE_2D, name);  // a name is a texture only once bound
  glBindTexture(GL_TEXTURE_2D, 0);
  return name;
}

TEST(GlLifetime, AHandleOfALiveContextDeletesItsName) {
  const long before = gLiveGlObjects;
  TextureHandle texture(makeBoundTexture());
  const GLuint name = texture.id();
  ASSERT_TRUE(textureExists(name));
  EXPECT_EQ(gLiveGlObjects, before + 1);
  texture.reset();
  EXPECT_FALSE(textureExists(name));
  EXPECT_EQ(gLiveGlObjects, before);
}

TEST(GlLifetime, AHandleOfALostContextForgetsItsNameWithoutCallingGl) {
  const long before = gLiveGlObjects;
  TextureHandle texture(makeBoundTexture());
  const GLuint name = texture.id();
  markGlContextLost();
  EXPECT_EQ(texture.id(), 0u);  // its name means nothing in the context that follows
  EXPECT_FALSE(texture);
  texture.reset();
  EXPECT_TRUE(textureExists(name));  // not deleted: GL was not called
  EXPECT_EQ(gLiveGlObjects, before);
  glDeleteTextures(1, &name);  // the test's own clean-up (this context is in fact alive)

  // A handle made after the loss belongs to the new generation and is deleted as usual.
  TextureHandle next(makeBoundTexture());
  const GLuint nextName = next.id();
  next.reset();
  EXPECT_FALSE(textureExists(nextName));
}

TEST(GlLifetime, AMovedHandleKeepsItsGeneration) {
  TextureHandle texture(makeBoundTexture());
  const GLuint name = texture.id();
  markGlContextLost();
  TextureHandle moved(std::move(texture));
  EXPECT_EQ(moved.id(), 0u);
  moved.reset();
  EXPECT_TRUE(textureExists(name));
  glDeleteTextures(1, &name);
}

// A whole demo after a lost context: every handle it held is forgotten (the count of live
// objects is back where it was) and no GL call failed; made again, it renders.
TEST(GlLifetime, ADemoForgetsEveryNameOfALostContextAndIsMadeAgain) {
  const long before = gLiveGlObjects;
  std::unique_ptr<Demo> demo = testing::makeDemo(makeDynamicReflectionScene());
  ASSERT_GT(gLiveGlObjects, before);
  demo->loseGraphics();
  EXPECT_EQ(gLiveGlObjects, before);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  ASSERT_EQ(demo->initGraphics(), "");
  EXPECT_GT(gLiveGlObjects, before);
  demo.reset();
  EXPECT_EQ(gLiveGlObjects, before);
}

}  // namespace
}  // namespace reflect
