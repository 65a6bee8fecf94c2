// Texel values against real Mesa: every internal format of GL 1.5 from client images of many
// formats and types, colour indices and pixel transfer. The cases are in
// mesa_reference/texel_cases.inc; OSMesa (Mesa 25.0.7) printed the expected read-back hashes
// (mesa_reference/mesa_texel_probe.c).
#include <cstdio>
#include <string>

#include "gl_test_context.hpp"

namespace {

#include "mesa_reference/texel_cases.inc"

const unsigned long long kMesaTexelHashes[] = {
#include "mesa_reference/mesa_texel_expected.inc"
};

std::string case_name(unsigned index) {
  const unsigned sources = sizeof(kTexelSources) / sizeof(kTexelSources[0]);
  const TexelSource& s = kTexelSources[index % sources];
  char name[96];
  std::snprintf(name, sizeof name, "internal format 0x%x from format 0x%x type 0x%x setup %d",
                unsigned(kTexelInternalFormats[index / sources]), s.format, s.type, s.setup);
  return name;
}

TEST_F(GlTest, TexelsReadBackExactlyAsFromMesa) {
  static_assert(sizeof(kMesaTexelHashes) / sizeof(kMesaTexelHashes[0]) == TEXEL_CASE_COUNT);
  int mismatches = 0;
  for (unsigned i = 0; i < TEXEL_CASE_COUNT; ++i) {
    const unsigned long long h = texel_case_run(i);
    if (h != kMesaTexelHashes[i]) {
      ++mismatches;
      ADD_FAILURE() << case_name(i);
    }
  }
  EXPECT_EQ(mismatches, 0);
}

}  // namespace
