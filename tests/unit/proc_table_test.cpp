#include <gtest/gtest.h>

#include <cstring>

#include "gl_shim/dispatch.hpp"

namespace {

TEST(ProcTable, IsSortedAndCoversGl1x) {
  size_t n = 0;
  const glpt::GlProcEntry* t = glpt::gl_proc_table(&n);
  ASSERT_GT(n, 300u);  // GL 1.0-1.5 alone has over 400 commands
  for (size_t i = 1; i < n; ++i) EXPECT_LT(std::strcmp(t[i - 1].name, t[i].name), 0) << t[i].name;
}

TEST(ProcTable, ImplementedNamesResolveUnimplementedAndUnknownDoNot) {
  EXPECT_NE(glpt::lookup_gl_proc("glVertex3f"), nullptr);
  EXPECT_NE(glpt::lookup_gl_proc("glCallList"), nullptr);
  // An ARB alias of an implemented core command resolves to its own entry point.
  EXPECT_NE(glpt::lookup_gl_proc("glMultTransposeMatrixfARB"), nullptr);
  EXPECT_EQ(glpt::lookup_gl_proc("glPolygonOffsetEXT"), nullptr);  // exported, not implemented
  EXPECT_EQ(glpt::lookup_gl_proc("glNotAFunction"), nullptr);
  EXPECT_EQ(glpt::lookup_gl_proc(nullptr), nullptr);
}

}  // namespace
