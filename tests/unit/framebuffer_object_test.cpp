// EXT_framebuffer_object's objects, bindings, attachments, completeness and errors, as Mesa 25
// has them (src/mesa/main/fbobject.c in a compatibility context with ARB_framebuffer_object).
#include <vector>

#include "array_test_util.hpp"

namespace {

constexpr GLenum kDepthStencilAttachment = 0x821A;

GLenum error() { return glGetError(); }

GLint attachment_param(GLenum attachment, GLenum pname) {
  GLint v = -12345;
  glGetFramebufferAttachmentParameterivEXT(GL_FRAMEBUFFER_EXT, attachment, pname, &v);
  return v;
}

GLint renderbuffer_param(GLenum pname) {
  GLint v = -12345;
  glGetRenderbufferParameterivEXT(GL_RENDERBUFFER_EXT, pname, &v);
  return v;
}

GLuint texture_2d(GLsizei width, GLsizei height, GLenum internal_format = GL_RGBA8,
                  GLenum format = GL_RGBA, GLenum type = GL_UNSIGNED_BYTE) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal_format), width, height, 0, format, type, nullptr);
  return t;
}

using glpt_test::attach_renderbuffer;

TEST_F(GlTest, FramebufferNamesBecomeObjectsWhenBound) {
  GLuint f[2] = {};
  glGenFramebuffersEXT(2, f);
  EXPECT_NE(f[0], 0u);
  EXPECT_NE(f[0], f[1]);
  EXPECT_FALSE(glIsFramebufferEXT(f[0]));
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, f[0]);
  EXPECT_TRUE(glIsFramebufferEXT(f[0]));
  EXPECT_EQ(get_integer(GL_FRAMEBUFFER_BINDING_EXT), GLint(f[0]));
  // A name never generated is created by binding it (EXT_framebuffer_object).
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 500);
  EXPECT_TRUE(glIsFramebufferEXT(500));
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  // Deleting the bound framebuffer binds the window again.
  const GLuint doomed = 500;
  glDeleteFramebuffersEXT(1, &doomed);
  EXPECT_FALSE(glIsFramebufferEXT(500));
  EXPECT_EQ(get_integer(GL_FRAMEBUFFER_BINDING_EXT), 0);
  glGenFramebuffersEXT(-1, f);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glBindFramebufferEXT(GL_TEXTURE_2D, f[0]);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), GLenum{GL_FRAMEBUFFER_COMPLETE_EXT});
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_TEXTURE_2D), 0u);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  EXPECT_EQ(get_integer(GL_MAX_COLOR_ATTACHMENTS_EXT), 8);
}

TEST_F(GlTest, RenderbufferStorageAndItsErrors) {
  GLuint r = 0;
  glGenRenderbuffersEXT(1, &r);
  EXPECT_FALSE(glIsRenderbufferEXT(r));
  // Nothing bound: no storage to define.
  glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_RGBA8, 4, 4);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, r);
  EXPECT_TRUE(glIsRenderbufferEXT(r));
  EXPECT_EQ(get_integer(GL_RENDERBUFFER_BINDING_EXT), GLint(r));
  EXPECT_EQ(renderbuffer_param(GL_RENDERBUFFER_INTERNAL_FORMAT_EXT), GL_RGBA);
  EXPECT_EQ(renderbuffer_param(GL_RENDERBUFFER_WIDTH_EXT), 0);
  glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH24_STENCIL8_EXT, 16, 8);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(renderbuffer_param(GL_RENDERBUFFER_WIDTH_EXT), 16);
  EXPECT_EQ(renderbuffer_param(GL_RENDERBUFFER_HEIGHT_EXT), 8);
  EXPECT_EQ(renderbuffer_param(GL_RENDERBUFFER_DEPTH_SIZE_EXT), 24);
  EXPECT_EQ(renderbuffer_param(GL_RENDERBUFFER_STENCIL_SIZE_EXT), 8);
  EXPECT_EQ(renderbuffer_param(GL_RENDERBUFFER_RED_SIZE_EXT), 0);
  glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 4, 4);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_RGB8, -1, 4);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_RGB8, 4, 1 << 20);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glRenderbufferStorageEXT(GL_TEXTURE_2D, GL_RGB8, 4, 4);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glGetRenderbufferParameterivEXT(GL_RENDERBUFFER_EXT, GL_TEXTURE_WIDTH, nullptr);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glDeleteRenderbuffersEXT(1, &r);
  EXPECT_EQ(get_integer(GL_RENDERBUFFER_BINDING_EXT), 0);
  EXPECT_FALSE(glIsRenderbufferEXT(r));
}

TEST_F(GlTest, AttachmentsAndCompleteness) {
  GLuint fb = 0;
  glGenFramebuffersEXT(1, &fb);
  const GLuint color = texture_2d(32, 16);
  // The window's attachments cannot change.
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, color, 0);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT),
            GLenum{GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_EXT});
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, color, 0);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), GLenum{GL_FRAMEBUFFER_COMPLETE_EXT});
  EXPECT_EQ(attachment_param(GL_COLOR_ATTACHMENT0_EXT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT),
            GL_TEXTURE);
  EXPECT_EQ(attachment_param(GL_COLOR_ATTACHMENT0_EXT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT),
            GLint(color));
  EXPECT_EQ(attachment_param(GL_COLOR_ATTACHMENT0_EXT, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT),
            0);
  // An attachment without an image (level 1 is undefined) is incomplete.
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT1_EXT, GL_TEXTURE_2D, color, 1);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT),
            GLenum{GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_EXT});
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT1_EXT, GL_TEXTURE_2D, 0, 0);
  EXPECT_EQ(attachment_param(GL_COLOR_ATTACHMENT1_EXT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT),
            GL_NONE);
  attachment_param(GL_COLOR_ATTACHMENT1_EXT, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  // A depth renderbuffer of another size: EXT_framebuffer_object's rule (Mesa, which also has
  // ARB_framebuffer_object, calls it complete).
  attach_renderbuffer(GL_DEPTH_ATTACHMENT_EXT, GL_DEPTH_COMPONENT24, 64, 64);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT),
            GLenum{GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_EXT});
  const GLuint depth = attach_renderbuffer(GL_DEPTH_ATTACHMENT_EXT, GL_DEPTH_COMPONENT24, 32, 16);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), GLenum{GL_FRAMEBUFFER_COMPLETE_EXT});
  // Colour images of different internal formats; a draw or read buffer naming no image.
  const GLuint rgb = texture_2d(32, 16, GL_RGB8, GL_RGB);
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT2_EXT, GL_TEXTURE_2D, rgb, 0);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT),
            GLenum{GL_FRAMEBUFFER_INCOMPLETE_FORMATS_EXT});
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT2_EXT, GL_TEXTURE_2D, 0, 0);
  glDrawBuffer(GL_COLOR_ATTACHMENT3_EXT);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT),
            GLenum{GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER_EXT});
  glDrawBuffer(GL_NONE);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), GLenum{GL_FRAMEBUFFER_COMPLETE_EXT});
  glReadBuffer(GL_COLOR_ATTACHMENT3_EXT);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT),
            GLenum{GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER_EXT});
  glDrawBuffer(GL_COLOR_ATTACHMENT0_EXT);
  glReadBuffer(GL_COLOR_ATTACHMENT0_EXT);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), GLenum{GL_FRAMEBUFFER_COMPLETE_EXT});
  glDeleteTextures(1, &rgb);
  // A colour format at the depth attachment, and a depth format at a colour attachment.
  attach_renderbuffer(GL_DEPTH_ATTACHMENT_EXT, GL_RGBA8, 32, 16);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT),
            GLenum{GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_EXT});
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT,
                               depth);
  // Separate depth and stencil renderbuffers: what llvmpipe does not support.
  attach_renderbuffer(GL_STENCIL_ATTACHMENT_EXT, GL_STENCIL_INDEX8_EXT, 32, 16);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT),
            GLenum{GL_FRAMEBUFFER_UNSUPPORTED_EXT});
  // One packed depth-stencil renderbuffer at both: complete.
  const GLuint packed =
      attach_renderbuffer(kDepthStencilAttachment, GL_DEPTH24_STENCIL8_EXT, 32, 16);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(attachment_param(GL_STENCIL_ATTACHMENT_EXT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT),
            GLint(packed));
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), GLenum{GL_FRAMEBUFFER_COMPLETE_EXT});
  // Errors: attachment names, texture targets, levels, unknown objects.
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT + 8, GL_TEXTURE_2D, color,
                            0);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_FRONT, GL_TEXTURE_2D, color, 0);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_3D, color, 0);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, color, -1);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, 9999, 0);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT,
                               9999);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, kDepthStencilAttachment, GL_RENDERBUFFER_EXT,
                               depth);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});  // not a depth-stencil format
  // Deleting the texture detaches it from the bound framebuffer.
  glDeleteTextures(1, &color);
  EXPECT_EQ(attachment_param(GL_COLOR_ATTACHMENT0_EXT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT),
            GL_NONE);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
}

// ARB_framebuffer_object's attachment queries (which Mesa answers through the EXT command), on
// the window and on an object; the values are Mesa 25's on llvmpipe (measured), except the
// window's colour encoding (Mesa's visuals are sRGB-capable, glpt's window is not).
constexpr GLenum kColorEncoding = 0x8210, kComponentType = 0x8211, kRedSize = 0x8212,
                 kAlphaSize = 0x8215, kDepthSize = 0x8216, kStencilSize = 0x8217;
constexpr GLint kFramebufferDefault = 0x8218, kUnsignedNormalized = 0x8C17;

TEST_F(GlTest, WindowAttachmentQueriesAnswerAsTheDefaultFramebuffer) {
  // The test context's drawable: double-buffered RGBA8 with 24 depth and 8 stencil bits.
  EXPECT_EQ(attachment_param(GL_BACK_LEFT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT),
            kFramebufferDefault);
  EXPECT_EQ(attachment_param(GL_FRONT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT),
            kFramebufferDefault);
  EXPECT_EQ(attachment_param(GL_BACK_RIGHT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT), GL_NONE);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(attachment_param(GL_FRONT_LEFT, kRedSize), 8);
  EXPECT_EQ(attachment_param(GL_FRONT_LEFT, kAlphaSize), 8);
  EXPECT_EQ(attachment_param(GL_FRONT_LEFT, kDepthSize), 0);
  EXPECT_EQ(attachment_param(GL_FRONT_LEFT, kComponentType), kUnsignedNormalized);
  EXPECT_EQ(attachment_param(GL_FRONT_LEFT, kColorEncoding), GL_LINEAR);
  // One packed depth-stencil image.
  EXPECT_EQ(attachment_param(GL_DEPTH, kDepthSize), 24);
  EXPECT_EQ(attachment_param(GL_STENCIL, kDepthSize), 24);
  EXPECT_EQ(attachment_param(GL_STENCIL, kStencilSize), 8);
  EXPECT_EQ(attachment_param(GL_DEPTH, kRedSize), 0);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  // No name, level or face; sizes only of buffers that exist; no colour attachments.
  EXPECT_EQ(attachment_param(GL_BACK_LEFT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT), -12345);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  attachment_param(GL_BACK_LEFT, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  attachment_param(GL_BACK_RIGHT, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  attachment_param(GL_BACK_RIGHT, kRedSize);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  attachment_param(GL_BACK_RIGHT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  for (GLenum attachment : {GLenum{GL_COLOR_ATTACHMENT0_EXT}, GLenum{GL_DEPTH_ATTACHMENT_EXT},
                            GLenum{GL_ACCUM}, GLenum{GL_AUX0}, GLenum{GL_NONE}}) {
    EXPECT_EQ(attachment_param(attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT), -12345);
    EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM}) << attachment;
  }
  attachment_param(GL_BACK_LEFT, 0x1234);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
}

TEST_F(GlTest, ObjectAttachmentSizesComeFromTheStoredFormat) {
  GLuint fb = 0;
  glGenFramebuffersEXT(1, &fb);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
  const GLuint color = texture_2d(8, 8, GL_R3_G3_B2, GL_RGB);
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, color, 0);
  EXPECT_EQ(attachment_param(GL_COLOR_ATTACHMENT0_EXT, kRedSize), 3);
  EXPECT_EQ(attachment_param(GL_COLOR_ATTACHMENT0_EXT, kRedSize + 2), 2);  // blue
  EXPECT_EQ(attachment_param(GL_COLOR_ATTACHMENT0_EXT, kAlphaSize), 0);
  EXPECT_EQ(attachment_param(GL_COLOR_ATTACHMENT0_EXT, kComponentType), kUnsignedNormalized);
  EXPECT_EQ(attachment_param(GL_COLOR_ATTACHMENT0_EXT, kColorEncoding), GL_LINEAR);
  const GLuint luminance = texture_2d(8, 8, GL_LUMINANCE8, GL_LUMINANCE);
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT1_EXT, GL_TEXTURE_2D, luminance,
                            0);
  EXPECT_EQ(attachment_param(GL_COLOR_ATTACHMENT1_EXT, kRedSize), 0);  // luminance is no red
  attach_renderbuffer(kDepthStencilAttachment, GL_DEPTH24_STENCIL8_EXT, 8, 8);
  EXPECT_EQ(attachment_param(GL_STENCIL_ATTACHMENT_EXT, kDepthSize), 24);
  EXPECT_EQ(attachment_param(kDepthStencilAttachment, kStencilSize), 8);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  // Depth and stencil of one image have no one component type.
  attachment_param(kDepthStencilAttachment, kComponentType);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  attachment_param(GL_COLOR_ATTACHMENT2_EXT, kRedSize);  // nothing attached
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  attachment_param(GL_DEPTH_ATTACHMENT_EXT, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL_EXT);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});  // a renderbuffer has no level
  attachment_param(GL_BACK_LEFT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});  // the window's buffers are not an object's
}

// Drawing, clearing and reading an incomplete framebuffer object: the errors Mesa 25 raises
// (measured; its pixel-rectangle draws answer GL_INVALID_OPERATION instead).
TEST_F(GlTest, IncompleteFramebufferRaisesInvalidFramebufferOperation) {
  constexpr GLenum kInvalidFramebufferOperation = 0x0506;
  GLuint fb = 0;
  glGenFramebuffersEXT(1, &fb);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
  const GLuint empty = texture_2d(0, 0);  // an attachment without an image: incomplete
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, empty, 0);
  ASSERT_NE(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), GLenum{GL_FRAMEBUFFER_COMPLETE_EXT});
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  glBegin(GL_TRIANGLES);
  EXPECT_EQ(error(), kInvalidFramebufferOperation);
  glEnd();  // glBegin did not begin
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  const GLfloat vertices[] = {0, 0, 1, 0, 0, 1};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, vertices);
  glDrawArrays(GL_TRIANGLES, 0, 0);  // even with nothing to draw
  EXPECT_EQ(error(), kInvalidFramebufferOperation);
  glDrawArrays(GL_TRIANGLES + 100, 0, 3);  // argument errors come first
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
  const GLubyte indices[] = {0, 1, 2};
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, indices);
  EXPECT_EQ(error(), kInvalidFramebufferOperation);
  glClear(0);
  EXPECT_EQ(error(), kInvalidFramebufferOperation);
  glClear(0x80000000);
  EXPECT_EQ(error(), GLenum{GL_INVALID_VALUE});
  GLubyte pixels[16 * 4] = {};
  glReadPixels(0, 0, 2, 2, 0x1234, GL_UNSIGNED_BYTE, pixels);  // before the format's error
  EXPECT_EQ(error(), kInvalidFramebufferOperation);
  const GLuint copy = texture_2d(4, 4);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2);
  EXPECT_EQ(error(), kInvalidFramebufferOperation);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, 2, 2, 0);
  EXPECT_EQ(error(), kInvalidFramebufferOperation);
  glRasterPos2f(0.0f, 0.0f);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  glCopyPixels(0, 0, 2, 2, GL_COLOR);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  glBitmap(2, 2, 0, 0, 1, 1, pixels);
  EXPECT_EQ(error(), GLenum{GL_INVALID_OPERATION});
  // Defining the attached image while bound makes the object complete: drawing proceeds.
  glBindTexture(GL_TEXTURE_2D, empty);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  glDisableClientState(GL_VERTEX_ARRAY);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
  glClear(GL_COLOR_BUFFER_BIT);  // the window is always complete
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  glDeleteTextures(1, &copy);
}

TEST_F(GlTest, GenerateMipmapFillsTheLevels) {
  std::vector<GLubyte> texels(8 * 8 * 4, 200);
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glGenerateMipmapEXT(GL_TEXTURE_2D);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  GLint width = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 3, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 1);
  GLubyte texel[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 3, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  EXPECT_EQ(texel[0], 200);
  glGenerateMipmapEXT(GL_TEXTURE_RECTANGLE_ARB);
  EXPECT_EQ(error(), GLenum{GL_INVALID_ENUM});
}

}  // namespace
