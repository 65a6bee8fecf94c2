// Display lists with client data (GL 1.5 5.4): the data is unpacked when the list is compiled,
// with the unpack modes current then; later changes to client memory or to the modes do not
// reach the list. Proxy texture commands execute at once.
#include <vector>

#include "gl_shim/pixels/list_images.hpp"
#include "gl_test_context.hpp"

namespace {

class ListImageTest : public GlTest {
 protected:
  std::vector<GLubyte> texels(GLint level, int count) {
    std::vector<GLubyte> out(size_t(count) * 4, 0xEE);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, level, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    return out;
  }
};

TEST_F(ListImageTest, TexImageSeesTheDataAndModesOfCompileTime) {
  // A 2x1 RGB image at skip (1, 1) of a 3-wide client image aligned to 4 (rows of 12 bytes).
  std::vector<GLubyte> client(2 * 12, 0);
  client[12 + 3] = 10;
  client[12 + 6] = 20;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 3);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, client.data());
  glEndList();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  GLint width = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 0);  // GL_COMPILE executes nothing
  // The client changes its memory and its modes before calling the list.
  client[12 + 3] = 99;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glCallList(list);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  const std::vector<GLubyte> t = texels(0, 2);
  EXPECT_EQ(t[0], 10);
  EXPECT_EQ(t[4], 20);
  // The context's own unpack modes are back after the list.
  GLint alignment = 0;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  EXPECT_EQ(alignment, 1);
  GLboolean swap = 0;
  glGetBooleanv(GL_UNPACK_SWAP_BYTES, &swap);
  EXPECT_EQ(swap, 1);
}

TEST_F(ListImageTest, SwappedAndBitmapDataAreStoredInTheDefaultLayout) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  const GLubyte be[2] = {0xFF, 0x00};  // 0xFF00 big-endian: 65280
  const GLuint list = glGenLists(2);
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE16, 1, 1, 0, GL_LUMINANCE, GL_UNSIGNED_SHORT, be);
  glEndList();
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  glCallList(list);
  GLushort l = 0;
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_SHORT, &l);
  EXPECT_EQ(l, 65280);
  // Polygon stipple: LSB-first and skipped bits at compile time.
  GLubyte pattern[32 * 4] = {};
  pattern[0] = 0x02;  // LSB first: column 1
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glNewList(list + 1, GL_COMPILE);
  glPolygonStipple(pattern);
  glEndList();
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  pattern[0] = 0;
  glCallList(list + 1);
  EXPECT_EQ(ctx_.raster.primitive.stipple_pattern[0], 1u << 30);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(ListImageTest, SubImagesThreeDimensionalImagesAndCompileAndExecute) {
  const GLubyte zero[16] = {};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, zero);
  GLubyte red[4] = {255, 0, 0, 255};
  const GLuint list = glGenLists(2);
  glNewList(list, GL_COMPILE_AND_EXECUTE);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  glEndList();
  EXPECT_EQ(texels(0, 4)[12], 255);  // executed while compiling
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, zero);
  red[0] = 1;
  glCallList(list);
  EXPECT_EQ(texels(0, 4)[12], 255);
  // 3-D: IMAGE_HEIGHT and SKIP_IMAGES at compile time.
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 2);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
  const GLubyte slices[4] = {0, 0, 42, 0};  // image 1 starts at row 2
  glNewList(list + 1, GL_COMPILE);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_LUMINANCE, 1, 1, 1, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, slices);
  glEndList();
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  glCallList(list + 1);
  GLubyte l = 0;
  glGetTexImage(GL_TEXTURE_3D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, &l);
  EXPECT_EQ(l, 42);
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
}

TEST_F(ListImageTest, ProxyTexImageExecutesImmediately) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glEndList();
  GLint w = 0;
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 16);
}

TEST_F(ListImageTest, ErrorsOfCompiledImagesAreReportedWhenTheListRuns) {
  const GLubyte t[4] = {};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, 0x1234, GL_UNSIGNED_BYTE, t);
  glEndList();
  EXPECT_EQ(glGetError(), GLenum{GL_NO_ERROR});
  glCallList(list);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(ctx_.not_compilable_calls, 0u);
}

TEST_F(ListImageTest, PixelMapsAndTransferAreCompiled) {
  const GLfloat map[2] = {0.25f, 0.75f};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, map);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 300, map);  // invalid size: an error when run, no overread
  glEndList();
  GLint size = 0;
  glGetIntegerv(GL_PIXEL_MAP_I_TO_R_SIZE, &size);
  EXPECT_EQ(size, 1);
  glCallList(list);
  EXPECT_EQ(glGetError(), GLenum{GL_INVALID_VALUE});
  glGetIntegerv(GL_PIXEL_MAP_I_TO_R_SIZE, &size);
  EXPECT_EQ(size, 2);
  EXPECT_FLOAT_EQ(ctx_.pixel_transfer.scale.r, 0.5f);
}

TEST_F(ListImageTest, TextureStateCommandsAreCompiled) {
  GLuint t = 0;
  glGenTextures(1, &t);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  const GLfloat plane[4] = {1, 2, 3, 4};
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  glActiveTexture(GL_TEXTURE1);
  glEndList();
  glCallList(list);
  GLint v = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &v);
  EXPECT_EQ(v, GL_TEXTURE1);
  EXPECT_EQ(ctx_.textures.units[0].env.mode, GLenum{GL_REPLACE});
  EXPECT_EQ(ctx_.textures.units[0].texgen[0].object_plane, glm::vec4(1, 2, 3, 4));
  glActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &v);
  EXPECT_EQ(GLuint(v), t);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
  EXPECT_EQ(v, GL_NEAREST);
}

TEST(ClientImageCopy, RepacksWithDefaultModes) {
  glpt::PixelStoreModes m;
  m.alignment = 8;
  m.skip_pixels = 1;
  m.lsb_first = true;
  const GLubyte bits[2] = {0x06, 0x00};  // LSB first, skipping bit 0: columns 0 and 1 set
  const glpt::ClientImageCopy copy =
      glpt::copy_client_image(m, glpt::ImageShape{3, 1, 1, GL_COLOR_INDEX, GL_BITMAP}, false, bits);
  ASSERT_TRUE(copy.present);
  ASSERT_EQ(copy.bytes.size(), 1u);
  EXPECT_EQ(copy.bytes[0], 0xC0);  // MSB first, no skip
  EXPECT_FALSE(
      glpt::copy_client_image(m, glpt::ImageShape{1, 1, 1, GL_RGBA, GL_BITMAP}, false, bits)
          .present);
  EXPECT_FALSE(glpt::copy_client_image(m, glpt::ImageShape{1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE},
                                       false, nullptr)
                   .present);
}

}  // namespace
