// glGetString(GL_EXTENSIONS) promises only what works: every command of every advertised
// extension is exported and implemented, and the string is Mesa-shaped (names separated and
// followed by one space).
#include <set>
#include <sstream>
#include <string>

#include "gl_shim/dispatch.hpp"
#include "gl_shim/state/extension_override.hpp"
#include "gl_test_context.hpp"

namespace {

std::set<std::string> implemented_commands() {
  size_t count = 0;
  const glpt::GlProcEntry* table = glpt::gl_proc_table(&count);
  std::set<std::string> names;
  for (size_t i = 0; i < count; ++i)
    if (table[i].implemented) names.insert(table[i].name);
  return names;
}

TEST_F(GlTest, EveryCommandOfAnAdvertisedExtensionIsImplemented) {
  const std::set<std::string> implemented = implemented_commands();
  size_t count = 0;
  const char* const* promised = glpt::advertised_extension_commands(&count);
  ASSERT_GT(count, 50u);  // multitexture, window_pos, secondary_color, buffer objects, ...
  for (size_t i = 0; i < count; ++i) {
    EXPECT_TRUE(implemented.count(promised[i])) << promised[i];
    EXPECT_NE(glpt::lookup_gl_proc(promised[i]), nullptr) << promised[i];
  }
}

TEST_F(GlTest, ExtensionStringListsGl1xExtensionsEachFollowedByASpace) {
  const auto* s = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  ASSERT_NE(s, nullptr);
  const std::string extensions = s;
  ASSERT_FALSE(extensions.empty());
  EXPECT_EQ(extensions.back(), ' ');
  EXPECT_EQ(extensions.find("  "), std::string::npos);
  std::istringstream words(extensions);
  std::set<std::string> names;
  for (std::string name; words >> name;) {
    EXPECT_EQ(name.rfind("GL_", 0), 0u) << name;
    EXPECT_TRUE(names.insert(name).second) << "listed twice: " << name;
  }
  // What programs of the GL 1.x era look for (and piglit's GL 1.x tests require).
  for (const char* wanted :
       {"GL_ARB_multitexture", "GL_ARB_window_pos", "GL_ARB_depth_texture", "GL_EXT_blend_minmax",
        "GL_ARB_vertex_buffer_object", "GL_ARB_occlusion_query"})
    EXPECT_TRUE(names.count(wanted)) << wanted;
  // Not implemented: not advertised.
  EXPECT_FALSE(names.count("GL_ARB_imaging"));
}

}  // namespace

// GLPT_EXTENSION_OVERRIDE, as MESA_EXTENSION_OVERRIDE: "+NAME" (or a bare name) adds an extension
// not advertised, "-NAME" hides one; the result keeps Mesa's form.
TEST(ExtensionOverride, AddsAndRemovesNames) {
  const std::string base = "GL_A GL_B GL_C ";
  EXPECT_EQ(glpt::apply_extension_override(base, ""), base);
  EXPECT_EQ(glpt::apply_extension_override(base, "+GL_D"), "GL_A GL_B GL_C GL_D ");
  EXPECT_EQ(glpt::apply_extension_override(base, "-GL_B"), "GL_A GL_C ");
  EXPECT_EQ(glpt::apply_extension_override(base, "  -GL_A   GL_E +GL_C - + -GL_X"),
            "GL_B GL_C GL_E ");
}
