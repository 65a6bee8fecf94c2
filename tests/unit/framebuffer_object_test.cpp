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

// A renderbuffer of `format` and size, attached to the bound framebuffer at `attachment`.
GLuint attach_renderbuffer(GLenum attachment, GLenum format, GLsizei width, GLsizei height) {
  GLuint rb = 0;
  glGenRenderbuffersEXT(1, &rb);
  glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb);
  glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, format, width, height);
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, attachment, GL_RENDERBUFFER_EXT, rb);
  return rb;
}

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
  // A depth renderbuffer of another size: complete (ARB_framebuffer_object's rule, Mesa's).
  const GLuint depth = attach_renderbuffer(GL_DEPTH_ATTACHMENT_EXT, GL_DEPTH_COMPONENT24, 64, 64);
  EXPECT_EQ(error(), GLenum{GL_NO_ERROR});
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), GLenum{GL_FRAMEBUFFER_COMPLETE_EXT});
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
