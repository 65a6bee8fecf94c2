// A glpt::Context made current for the duration of a test, without any window system. Tests
// call the exported entry points through their generated declarations.
#pragma once

#include <gtest/gtest.h>

#include "gl_shim/context.hpp"
#include "gl_shim/gl_entry_decls.h"
#include "gl/gl_enums.h"

class GlTest : public ::testing::Test {
 protected:
  void SetUp() override { glpt::set_current_context(&ctx_); }
  void TearDown() override { glpt::set_current_context(nullptr); }
  glpt::Context ctx_{nullptr};
};
