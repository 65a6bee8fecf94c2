#include "rays.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ray_ceiling {
namespace {

constexpr uint32_t kMaskVisible = 0x80;  // shared_types.h: GLPT_MASK_VISIBLE
constexpr uint32_t kTile = 8;            // GLPT_TILE_SIZE

struct V3 {
  float x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(float s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
float dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
V3 normalize(V3 a) {
  const float l = std::sqrt(dot(a, a));
  return l > 0 ? (1.0f / l) * a : V3{0, 0, 1};
}

// PCG-style hash for reproducible random numbers per pixel and purpose.
uint32_t hash(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}
float random01(uint32_t& state) {
  state = hash(state + 0x9E3779B9u);
  return static_cast<float>(state >> 8) * (1.0f / 16777216.0f);
}

uint32_t morton3(float x, float y, float z) {
  auto spread = [](uint32_t v) {
    v = (v | (v << 16)) & 0x030000FF;
    v = (v | (v << 8)) & 0x0300F00F;
    v = (v | (v << 4)) & 0x030C30C3;
    v = (v | (v << 2)) & 0x09249249;
    return v;
  };
  auto q = [](float f) { return static_cast<uint32_t>(std::clamp(f, 0.0f, 1.0f) * 1023.0f); };
  return spread(q(x)) | (spread(q(y)) << 1) | (spread(q(z)) << 2);
}

Ray make_ray(V3 origin, V3 direction, float tmax, uint32_t flags, uint32_t mask) {
  Ray r{};
  r.org[0] = origin.x;
  r.org[1] = origin.y;
  r.org[2] = origin.z;
  r.tmin = 0.0f;
  r.dir[0] = direction.x;
  r.dir[1] = direction.y;
  r.dir[2] = direction.z;
  r.tmax = tmax;
  r.flags = flags;
  r.mask = mask;
  return r;
}

// A hit's eye-space point, geometric normal facing the ray's origin, and an origin for rays
// leaving it (lifted off the surface by a relative epsilon).
struct Surface {
  V3 position, normal, origin;
};
Surface surface_of(const glpt::rt::SceneDump& dump, const Ray& ray, const Hit& hit,
                   int64_t triangle) {
  const float* t = &dump.eye_triangles[static_cast<size_t>(triangle) * 9];
  const V3 a{t[0], t[1], t[2]}, b{t[3], t[4], t[5]}, c{t[6], t[7], t[8]};
  const V3 d{ray.dir[0], ray.dir[1], ray.dir[2]};
  Surface s;
  s.position = V3{ray.org[0], ray.org[1], ray.org[2]} + hit.t * d;
  s.normal = normalize(cross(b - a, c - a));
  if (dot(s.normal, d) > 0) s.normal = -1.0f * s.normal;
  const float scale =
      std::max({1.0f, std::abs(s.position.x), std::abs(s.position.y), std::abs(s.position.z)});
  s.origin = s.position + (1.0e-4f * scale) * s.normal;
  return s;
}

V3 cosine_direction(V3 n, uint32_t& rng) {
  const float u1 = random01(rng), u2 = random01(rng);
  const float r = std::sqrt(u1), phi = 6.2831853f * u2;
  const V3 helper = std::abs(n.x) > 0.9f ? V3{0, 1, 0} : V3{1, 0, 0};
  const V3 tx = normalize(cross(helper, n)), ty = cross(n, tx);
  const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
  return normalize((r * std::cos(phi)) * tx + (r * std::sin(phi)) * ty + z * n);
}

// A shadow ray from `s` to a light chosen at random; false when the light is below the surface.
bool shadow_ray(const glpt::rt::SceneDump& dump, const Surface& s, uint32_t& rng, Ray& out) {
  if (dump.lights.empty()) return false;
  const size_t index =
      std::min(dump.lights.size() - 1, static_cast<size_t>(random01(rng) * dump.lights.size()));
  const glpt::rt::SceneDumpLight& light = dump.lights[index];
  V3 direction;
  float tmax = kUnbounded;
  if (light.position[3] != 0.0f) {
    const V3 centre =
        (1.0f / light.position[3]) * V3{light.position[0], light.position[1], light.position[2]};
    const V3 offset = centre - s.origin;
    const float distance = std::sqrt(dot(offset, offset));
    if (!(distance > light.radius)) return false;
    direction = (1.0f / distance) * offset;
    tmax = distance - light.radius;
  } else {
    direction = normalize(V3{light.position[0], light.position[1], light.position[2]});
  }
  if (dot(direction, s.normal) <= 0.0f) return false;
  out = make_ray(s.origin, direction, tmax, kTerminateOnFirstHit, light.shadow_mask);
  return true;
}

}  // namespace

AccelInput instanced_input(const glpt::rt::SceneDump& dump) {
  AccelInput input;
  for (const glpt::rt::SceneDumpShape& shape : dump.shapes) input.shapes.push_back(shape.positions);
  for (const glpt::rt::SceneDumpInstance& instance : dump.instances) {
    input.instances.push_back({instance.shape, instance.mask, instance.transform});
    std::vector<uint32_t>& global = input.global.emplace_back(instance.triangle_count);
    std::iota(global.begin(), global.end(), static_cast<uint32_t>(instance.first_triangle));
  }
  return input;
}

AccelInput flat_input(const glpt::rt::SceneDump& dump) {
  AccelInput input;
  std::vector<uint32_t> masks;
  for (const glpt::rt::SceneDumpInstance& instance : dump.instances)
    if (std::find(masks.begin(), masks.end(), instance.mask) == masks.end())
      masks.push_back(instance.mask);
  float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
  for (size_t i = 0; i < dump.eye_triangles.size(); ++i)
    if (std::isfinite(dump.eye_triangles[i])) {
      lo[i % 3] = std::min(lo[i % 3], dump.eye_triangles[i]);
      hi[i % 3] = std::max(hi[i % 3], dump.eye_triangles[i]);
    }
  for (uint32_t mask : masks) {
    std::vector<std::pair<uint32_t, uint32_t>> keyed;  // morton code, global triangle
    for (const glpt::rt::SceneDumpInstance& instance : dump.instances) {
      if (instance.mask != mask) continue;
      for (uint32_t p = 0; p < instance.triangle_count; ++p) {
        const uint64_t t = instance.first_triangle + p;
        const float* v = &dump.eye_triangles[t * 9];
        float c[3];
        for (int k = 0; k < 3; ++k) {
          const float centre = (v[k] + v[3 + k] + v[6 + k]) / 3.0f;
          c[k] = hi[k] > lo[k] ? (centre - lo[k]) / (hi[k] - lo[k]) : 0.0f;
          if (!std::isfinite(c[k])) c[k] = 0.0f;
        }
        keyed.push_back({morton3(c[0], c[1], c[2]), static_cast<uint32_t>(t)});
      }
    }
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<float>& shape = input.shapes.emplace_back();
    std::vector<uint32_t>& global = input.global.emplace_back();
    for (const auto& [code, t] : keyed) {
      shape.insert(shape.end(), &dump.eye_triangles[size_t{t} * 9],
                   &dump.eye_triangles[size_t{t} * 9] + 9);
      global.push_back(t);
    }
    input.instances.push_back({static_cast<uint32_t>(input.shapes.size() - 1),
                               mask,
                               {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}});
  }
  return input;
}

int64_t global_triangle(const AccelInput& input, const Hit& hit) {
  if (hit.t < 0 || hit.instance < 0 || static_cast<size_t>(hit.instance) >= input.global.size())
    return -1;
  const std::vector<uint32_t>& global = input.global[static_cast<size_t>(hit.instance)];
  if (hit.primitive < 0 || static_cast<size_t>(hit.primitive) >= global.size()) return -1;
  return global[static_cast<size_t>(hit.primitive)];
}

Wave primary_rays(const glpt::rt::SceneDump& dump) {
  Wave wave;
  // Column-major projection; invert it (general 4x4, doubles).
  double m[16], inv[16];
  for (int i = 0; i < 16; ++i) m[i] = dump.projection[i];
  inv[0] = m[5] * m[10] * m[15] - m[5] * m[11] * m[14] - m[9] * m[6] * m[15] + m[9] * m[7] * m[14] +
           m[13] * m[6] * m[11] - m[13] * m[7] * m[10];
  inv[4] = -m[4] * m[10] * m[15] + m[4] * m[11] * m[14] + m[8] * m[6] * m[15] -
           m[8] * m[7] * m[14] - m[12] * m[6] * m[11] + m[12] * m[7] * m[10];
  inv[8] = m[4] * m[9] * m[15] - m[4] * m[11] * m[13] - m[8] * m[5] * m[15] + m[8] * m[7] * m[13] +
           m[12] * m[5] * m[11] - m[12] * m[7] * m[9];
  inv[12] = -m[4] * m[9] * m[14] + m[4] * m[10] * m[13] + m[8] * m[5] * m[14] -
            m[8] * m[6] * m[13] - m[12] * m[5] * m[10] + m[12] * m[6] * m[9];
  inv[1] = -m[1] * m[10] * m[15] + m[1] * m[11] * m[14] + m[9] * m[2] * m[15] -
           m[9] * m[3] * m[14] - m[13] * m[2] * m[11] + m[13] * m[3] * m[10];
  inv[5] = m[0] * m[10] * m[15] - m[0] * m[11] * m[14] - m[8] * m[2] * m[15] + m[8] * m[3] * m[14] +
           m[12] * m[2] * m[11] - m[12] * m[3] * m[10];
  inv[9] = -m[0] * m[9] * m[15] + m[0] * m[11] * m[13] + m[8] * m[1] * m[15] - m[8] * m[3] * m[13] -
           m[12] * m[1] * m[11] + m[12] * m[3] * m[9];
  inv[13] = m[0] * m[9] * m[14] - m[0] * m[10] * m[13] - m[8] * m[1] * m[14] + m[8] * m[2] * m[13] +
            m[12] * m[1] * m[10] - m[12] * m[2] * m[9];
  inv[2] = m[1] * m[6] * m[15] - m[1] * m[7] * m[14] - m[5] * m[2] * m[15] + m[5] * m[3] * m[14] +
           m[13] * m[2] * m[7] - m[13] * m[3] * m[6];
  inv[6] = -m[0] * m[6] * m[15] + m[0] * m[7] * m[14] + m[4] * m[2] * m[15] - m[4] * m[3] * m[14] -
           m[12] * m[2] * m[7] + m[12] * m[3] * m[6];
  inv[10] = m[0] * m[5] * m[15] - m[0] * m[7] * m[13] - m[4] * m[1] * m[15] + m[4] * m[3] * m[13] +
            m[12] * m[1] * m[7] - m[12] * m[3] * m[5];
  inv[14] = -m[0] * m[5] * m[14] + m[0] * m[6] * m[13] + m[4] * m[1] * m[14] - m[4] * m[2] * m[13] -
            m[12] * m[1] * m[6] + m[12] * m[2] * m[5];
  inv[3] = -m[1] * m[6] * m[11] + m[1] * m[7] * m[10] + m[5] * m[2] * m[11] - m[5] * m[3] * m[10] -
           m[9] * m[2] * m[7] + m[9] * m[3] * m[6];
  inv[7] = m[0] * m[6] * m[11] - m[0] * m[7] * m[10] - m[4] * m[2] * m[11] + m[4] * m[3] * m[10] +
           m[8] * m[2] * m[7] - m[8] * m[3] * m[6];
  inv[11] = -m[0] * m[5] * m[11] + m[0] * m[7] * m[9] + m[4] * m[1] * m[11] - m[4] * m[3] * m[9] -
            m[8] * m[1] * m[7] + m[8] * m[3] * m[5];
  inv[15] = m[0] * m[5] * m[10] - m[0] * m[6] * m[9] - m[4] * m[1] * m[10] + m[4] * m[2] * m[9] +
            m[8] * m[1] * m[6] - m[8] * m[2] * m[5];
  const double det = m[0] * inv[0] + m[1] * inv[4] + m[2] * inv[8] + m[3] * inv[12];
  if (det == 0.0 || !dump.camera_valid) return wave;
  auto unproject = [&](double x, double y, double z) {
    double out[4];
    for (int r = 0; r < 4; ++r)
      out[r] = (inv[r] * x + inv[4 + r] * y + inv[8 + r] * z + inv[12 + r]) / det;
    return V3{static_cast<float>(out[0] / out[3]), static_cast<float>(out[1] / out[3]),
              static_cast<float>(out[2] / out[3])};
  };
  const int32_t vx = dump.viewport[0], vy = dump.viewport[1];
  const uint32_t w = std::min<uint32_t>(dump.width, std::max(dump.viewport[2], 0));
  const uint32_t h = std::min<uint32_t>(dump.height, std::max(dump.viewport[3], 0));
  for (uint32_t ty = 0; ty < h; ty += kTile)
    for (uint32_t tx = 0; tx < w; tx += kTile)
      for (uint32_t y = ty; y < std::min(h, ty + kTile); ++y)
        for (uint32_t x = tx; x < std::min(w, tx + kTile); ++x) {
          const double nx = 2.0 * (x + 0.5) / dump.viewport[2] - 1.0;
          const double ny = 2.0 * (y + 0.5) / dump.viewport[3] - 1.0;
          const V3 near = unproject(nx, ny, -1.0), far = unproject(nx, ny, 1.0);
          wave.rays.push_back(make_ray(near, normalize(far - near), kUnbounded, 0, kMaskVisible));
          wave.pixel.push_back(static_cast<uint32_t>(vy + static_cast<int32_t>(y)) * dump.width +
                               static_cast<uint32_t>(vx + static_cast<int32_t>(x)));
        }
  return wave;
}

Wave first_vertex_rays(const glpt::rt::SceneDump& dump, const Wave& primary,
                       const std::vector<Hit>& hits, const AccelInput& input,
                       const MixOptions& options, std::vector<Kind>& kinds) {
  Wave wave;
  kinds.clear();
  for (size_t i = 0; i < primary.rays.size(); ++i) {
    const int64_t triangle = global_triangle(input, hits[i]);
    if (triangle < 0) continue;
    const Surface s = surface_of(dump, primary.rays[i], hits[i], triangle);
    uint32_t rng = hash(primary.pixel[i] * 747796405u + options.seed);
    if (options.ao) {
      wave.rays.push_back(
          make_ray(s.origin, cosine_direction(s.normal, rng), kUnbounded, 0, kMaskVisible));
      wave.pixel.push_back(primary.pixel[i]);
      kinds.push_back(Kind::kAo);
    }
    Ray shadow;
    if (shadow_ray(dump, s, rng, shadow)) {
      wave.rays.push_back(shadow);
      wave.pixel.push_back(primary.pixel[i]);
      kinds.push_back(Kind::kShadow);
    }
    if (options.bounce) {
      wave.rays.push_back(
          make_ray(s.origin, cosine_direction(s.normal, rng), kUnbounded, 0, kMaskVisible));
      wave.pixel.push_back(primary.pixel[i]);
      kinds.push_back(Kind::kBounce);
    }
  }
  return wave;
}

Wave bounce_vertex_rays(const glpt::rt::SceneDump& dump, const Wave& first,
                        const std::vector<Kind>& kinds, const std::vector<Hit>& hits,
                        const AccelInput& input, const MixOptions& options) {
  Wave wave;
  for (size_t i = 0; i < first.rays.size(); ++i) {
    if (kinds[i] != Kind::kBounce) continue;
    const int64_t triangle = global_triangle(input, hits[i]);
    if (triangle < 0) continue;
    const Surface s = surface_of(dump, first.rays[i], hits[i], triangle);
    uint32_t rng = hash(first.pixel[i] * 2891336453u + options.seed + 17u);
    Ray shadow;
    if (shadow_ray(dump, s, rng, shadow)) {
      wave.rays.push_back(shadow);
      wave.pixel.push_back(first.pixel[i]);
    }
  }
  return wave;
}

}  // namespace ray_ceiling
