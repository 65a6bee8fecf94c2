// Which varyings a raster pipeline's shaders must declare (rt_core/raster/pipeline_key.hpp,
// shaders/raster_varyings.h): every one the fragment stage reads, and no other.
#include <gtest/gtest.h>

#include "raster_types.h"
#include "rt_core/raster/pipeline_key.hpp"

namespace glpt::rt {
namespace {

TEST(PipelineVaryings, AnUntexturedUnfoggedOneSidedDrawReadsOnlyTheFrontColour) {
  EXPECT_EQ(varyings_read(PipelineKey()), 0u);
}

TEST(PipelineVaryings, EachFragmentFeatureNeedsItsVaryings) {
  PipelineKey two_side;
  two_side.constants[GLPT_SC_FS_FLAGS] = GLPT_FS_TWO_SIDE;
  EXPECT_EQ(varyings_read(two_side), uint32_t{GLPT_VARYING_BACK});

  PipelineKey color_sum;
  color_sum.constants[GLPT_SC_FS_FLAGS] = GLPT_FS_COLOR_SUM;
  EXPECT_EQ(varyings_read(color_sum), uint32_t{GLPT_VARYING_SECONDARY});

  for (uint32_t fog_mode = 1; fog_mode <= 3; ++fog_mode) {
    PipelineKey fog;
    fog.constants[GLPT_SC_FS_ALPHA_FOG] = fog_mode << 12;
    EXPECT_EQ(varyings_read(fog), uint32_t{GLPT_VARYING_FOG}) << fog_mode;
  }
  PipelineKey alpha_test_only;  // bits 8-10: the alpha test reads no varying
  alpha_test_only.constants[GLPT_SC_FS_ALPHA_FOG] = 7u << 8;
  EXPECT_EQ(varyings_read(alpha_test_only), 0u);

  for (int unit = 0; unit < GLPT_RASTER_MAX_UNITS; ++unit) {
    PipelineKey textured;
    textured.constants[GLPT_SC_UNIT0 + unit] = 2;  // a 2D texture
    EXPECT_EQ(varyings_read(textured), uint32_t{GLPT_VARYING_TEXCOORDS}) << unit;
  }
  PipelineKey environment_only;  // an env mode on a unit without a target samples nothing
  environment_only.constants[GLPT_SC_UNIT0] = 3u << 3;
  EXPECT_EQ(varyings_read(environment_only), 0u);
}

TEST(PipelineVaryings, GeometryShadersPixelRectanglesAndTheGBufferTakeAll) {
  PipelineKey unfilled, pixels, gbuffer;
  unfilled.unfilled = 1;
  pixels.pixels = 1;
  gbuffer.gbuffer = 1;
  EXPECT_EQ(varyings_read(unfilled), uint32_t{GLPT_VARYINGS_ALL});
  EXPECT_EQ(varyings_read(pixels), uint32_t{GLPT_VARYINGS_ALL});
  EXPECT_EQ(varyings_read(gbuffer), uint32_t{GLPT_VARYINGS_ALL});
}

}  // namespace
}  // namespace glpt::rt
