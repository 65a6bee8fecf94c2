// The kinds of the enabled lights that select the vertex shader's code per light
// (GLPT_SC_LIGHT_MASK, rt_core/raster/state_uniforms.hpp): they must say what the shader's tests
// of the packed light would have said (position.w != 0; spot.w > -1.5), derived here from GL's
// definitions (GL 1.5 2.14.1: w == 0 is a directional light, a cutoff of 180 no spotlight).
#include <gtest/gtest.h>

#include "raster_types.h"
#include "rt_core/raster/state_uniforms.hpp"

namespace glpt::rt {
namespace {

TEST(LightKinds, EachEnabledLightSaysWhetherItIsPositionalAndASpotlight) {
  rec::LightingState lighting;
  EXPECT_EQ(light_kind_bits(lighting), 0u);  // no light enabled
  lighting.light_mask = 0b1011;
  lighting.lights[0].position = glm::vec4(0, 0, 1, 0);  // directional, no spotlight
  lighting.lights[1].position = glm::vec4(1, 2, 3, 1);  // positional
  lighting.lights[1].spot_cutoff = 45.0f;
  lighting.lights[3].position = glm::vec4(0, 1, 0, 0);  // a directional spotlight
  lighting.lights[3].spot_cutoff = 0.0f;
  lighting.lights[2].position = glm::vec4(1, 1, 1, 1);  // disabled: never counted
  lighting.lights[2].spot_cutoff = 10.0f;
  EXPECT_EQ(light_kind_bits(lighting),
            (GLPT_LIGHT_POSITIONAL << 1) | (GLPT_LIGHT_SPOT << 1) | (GLPT_LIGHT_SPOT << 3));
  // The packed cutoff the shader compares: cos(45 degrees), and -2 without a spotlight.
  EXPECT_NEAR(packed_spot_cosine(lighting.lights[1]), 0.70710678f, 1e-6f);
  EXPECT_EQ(packed_spot_cosine(lighting.lights[0]), -2.0f);
}

}  // namespace
}  // namespace glpt::rt
