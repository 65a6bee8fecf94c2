// GL lights as light sources of the trace pass (docs/light-transport.md, "Lights"): what each
// light looks like from a point (its cone of directions and radiance), the choice of one light
// per sample in proportion to its estimated contribution, next-event estimation, and the
// radiance a BSDF-sampled ray finds when it passes through a light. Needs: `lights`, `states`,
// `frame`, sampling.h, offset_ray.h.
#ifndef GLPT_SHADERS_TRACE_LIGHTS_H
#define GLPT_SHADERS_TRACE_LIGHTS_H

#define GLPT_MAX_STATE_LIGHTS 8

// A light as seen from one point.
struct LightView {
  vec3 direction;  // towards the light's centre
  float distance;  // to the centre (kUnboundedRay for directional lights)
  // The cone of directions the light covers: one_minus_cos == 0 is a point or an exact
  // direction (a delta light, sampled only by next-event estimation).
  float cos_max;
  float one_minus_cos;
  float sphere_radius;  // 0 unless a sphere light
  // Radiance seen by the diffuse and the specular lobe (GL lights have a colour for each). For
  // delta lights: GL's colour times attenuation and spot, which is irradiance / pi at normal
  // incidence.
  vec3 diffuse;
  vec3 specular;
  vec3 ambient;  // GL's ambient term of this light at the point (attenuated, spot-weighted)
  float weight;  // unshadowed contribution estimate, for the choice among lights (>= 0)
};

// GL 1.5 2.14.1's attenuation and spotlight factor of a positional light at distance d in
// direction -to_light. `spot_directional`: apply a spot cone to directional lights too, as GL
// does (the GL-parity evaluation); the physical mapping has spots on positional lights only.
float attenuation_gl(GpuLight light, vec3 to_light, float d, bool spot_directional) {
  float attenuation = 1.0;
  bool positional = light.position.w != 0.0;
  if (positional)
    attenuation = 1.0 / max(light.attenuation.x + light.attenuation.y * d +
                                light.attenuation.z * d * d, 1.0e-20);
  if (light.spot.w > -1.5 && (positional || spot_directional)) {
    float spot_cos = dot(-to_light, light.spot.xyz);
    attenuation *= spot_cos >= light.spot.w ? power_gl(spot_cos, light.attenuation.w) : 0.0;
  }
  return attenuation;
}

LightView view_light(GpuLight light, vec3 p, vec3 n) {
  LightView view;
  view.sphere_radius = 0.0;
  float sin2 = 0.0;
  if (light.position.w != 0.0) {
    vec3 offset = light.position.xyz / light.position.w - p;
    view.distance = max(length(offset), 1.0e-20);
    view.direction = offset / view.distance;
    float radius = uintBitsToFloat(light.params.y);
    // Inside (or on) the sphere the cone is undefined: the light acts as its centre point.
    if (radius > 0.0 && view.distance > 1.001 * radius) {
      float ratio = radius / view.distance;
      sin2 = ratio * ratio;
      view.cos_max = sqrt(max(0.0, 1.0 - sin2));
      view.one_minus_cos = sin2 / (1.0 + view.cos_max);
      view.sphere_radius = radius;
    } else {
      view.cos_max = 1.0;
      view.one_minus_cos = 0.0;
    }
  } else {
    view.direction = light.position.xyz;
    view.distance = kUnboundedRay;
    view.cos_max = frame.params.y;
    view.one_minus_cos = frame.params.z;
    sin2 = view.one_minus_cos * (1.0 + view.cos_max);
  }
  float attenuation = attenuation_gl(light, view.direction, view.distance, false);
  view.ambient = attenuation_gl(light, view.direction, view.distance, true) * light.ambient.rgb;
  // An area light's radiance is chosen so that, fully above the horizon, it gives the irradiance
  // GL's point light of the same colour does: pi * colour * attenuation * cos (for a sphere the
  // irradiance is pi L sin^2(a) cos, exactly). With GL's inverse-square attenuation alone that
  // is a physical sphere of constant radiance.
  float scale = view.one_minus_cos > 0.0 ? attenuation / sin2 : attenuation;
  view.diffuse = scale * light.diffuse.rgb;
  view.specular = scale * light.specular.rgb;
  float sin_max = sqrt(sin2);
  float cosine = clamp(dot(n, view.direction) + sin_max, 0.0, 1.0);
  view.weight = attenuation * cosine * luminance(light.diffuse.rgb + light.specular.rgb);
  if (!(view.weight >= 0.0) || isinf(view.weight)) view.weight = 0.0;
  return view;
}

// The lights of a state and the probability of choosing each for a sample at one point.
struct LightChoice {
  uint count;
  LightView views[GLPT_MAX_STATE_LIGHTS];
  uint indices[GLPT_MAX_STATE_LIGHTS];  // into `lights`
  float probability[GLPT_MAX_STATE_LIGHTS];
  vec3 ambient;  // the state's global ambient plus every light's ambient term
};

LightChoice choose_lights(uint state, vec3 p, vec3 n) {
  LightChoice choice;
  choice.count = min(states[state].info.x, uint(GLPT_MAX_STATE_LIGHTS));
  choice.ambient = states[state].global_ambient.rgb;
  float total = 0.0;
  for (uint i = 0u; i < choice.count; ++i) {
    choice.indices[i] = states[state].lights[i >> 2u][i & 3u];
    choice.views[i] = view_light(lights[choice.indices[i]], p, n);
    choice.ambient += choice.views[i].ambient;
    total += choice.views[i].weight;
  }
  for (uint i = 0u; i < choice.count; ++i) {
    float p_i;
    if (frame.options.y == GLPT_LIGHT_CHOICE_ALL)
      p_i = 1.0;
    else if (frame.options.y == GLPT_LIGHT_CHOICE_UNIFORM)
      p_i = 1.0 / float(choice.count);
    else
      p_i = total > 0.0 ? choice.views[i].weight / total : 0.0;
    choice.probability[i] = p_i;
  }
  return choice;
}

// The light of `choice` a uniform number u picks (in proportion to the probabilities); count when
// no light can contribute.
uint pick_light(LightChoice choice, float u) {
  float cumulative = 0.0;
  uint last = choice.count;
  for (uint i = 0u; i < choice.count; ++i) {
    if (choice.probability[i] <= 0.0) continue;
    last = i;
    cumulative += choice.probability[i];
    if (u < cumulative) return i;
  }
  return last;  // rounding: the last light that can be chosen
}

// The density with which next-event estimation produces `direction` from light i (0 for delta
// lights: no other technique can find them).
float light_direction_pdf(LightChoice choice, uint i, vec3 direction) {
  LightView view = choice.views[i];
  if (view.one_minus_cos <= 0.0) return 0.0;
  if (dot(direction, view.direction) < view.cos_max) return 0.0;
  return choice.probability[i] * cone_pdf(view.one_minus_cos);
}

// Where a ray from `origin` first meets light i's sphere or cone (kUnboundedRay: never; a
// distant light is met at infinity, reported as kUnboundedRay * 0.5).
float light_hit_distance(LightView view, vec3 origin, vec3 direction, vec3 light_centre) {
  if (view.one_minus_cos <= 0.0) return kUnboundedRay;
  if (view.sphere_radius <= 0.0)
    return dot(direction, view.direction) >= view.cos_max ? 0.5 * kUnboundedRay : kUnboundedRay;
  vec3 oc = light_centre - origin;
  float b = dot(oc, direction);
  float c = dot(oc, oc) - view.sphere_radius * view.sphere_radius;
  float disc = b * b - c;
  if (disc < 0.0) return kUnboundedRay;
  float t = b - sqrt(disc);
  return t > 0.0 ? t : kUnboundedRay;
}

vec3 light_centre(GpuLight light) {
  return light.position.w != 0.0 ? light.position.xyz / light.position.w : vec3(0.0);
}

#endif  // GLPT_SHADERS_TRACE_LIGHTS_H
