// The CPU reference tracer (reference_tracer.hpp). The path loop follows
// shaders/path_trace.comp's trace_path step by step, so that both compute the same estimator;
// each step names the shader function it mirrors.
#include "reference_tracer.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <thread>

namespace glpt::reference {
namespace {

using glm::dvec2;
using glm::dvec3;

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
// The shader's "no end" for rays (queries.h kUnboundedRay): kept, because light_hit_distance
// reports a distant light at half of it and compares with it.
constexpr double kUnbounded = 1.0e30;
// Secondary rays start this fraction of their position's magnitude off the surface, on the side
// they leave from (double has 16 digits: 1e-9 is far above rounding and far below any geometry a
// test has). As in glpt, a ray towards the other side then meets its own surface: a surface seen
// from behind does not reflect light arriving on its front.
constexpr double kRelativeEpsilon = 1.0e-9;
// glpt's lamp-marker rule (rt_core/scene/light_setup.hpp kLampMarkerMaxSceneFraction).
constexpr double kLampMarkerMaxSceneFraction = 0.1;
constexpr uint32_t kShadowBits = 6;  // GLPT_MASK_SHADOW_BITS

double max3(dvec3 v) { return std::max(v.x, std::max(v.y, v.z)); }
double luminance(dvec3 c) { return glm::dot(c, dvec3(0.2126, 0.7152, 0.0722)); }
dvec3 normalize_or(dvec3 v, dvec3 fallback) {
  const double len2 = glm::dot(v, v);
  return len2 > 1e-300 && std::isfinite(len2) ? v / std::sqrt(len2) : fallback;
}
double power_gl(double x, double e) { return e == 0.0 ? 1.0 : std::pow(std::max(x, 0.0), e); }

// ---- random numbers: xoshiro256** seeded by splitmix64 ---------------------------------------

uint64_t splitmix64(uint64_t& x) {
  uint64_t z = (x += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

class Rng {
 public:
  explicit Rng(uint64_t seed) {
    for (uint64_t& s : s_) s = splitmix64(seed);
  }
  double next() {
    const uint64_t result = std::rotl(s_[1] * 5, 7) * 9;
    const uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = std::rotl(s_[3], 45);
    return static_cast<double>(result >> 11) * 0x1.0p-53;
  }
  dvec2 next2() {
    const double u = next();
    return {u, next()};
  }

 private:
  uint64_t s_[4];
};

// ---- sampling and BSDF (shaders/trace/sampling.h, bsdf.h) in double ---------------------------

struct Basis {
  dvec3 t, b, n;
};
Basis make_basis(dvec3 n) {
  const double s = n.z >= 0.0 ? 1.0 : -1.0;
  const double a = -1.0 / (s + n.z);
  const double c = n.x * n.y * a;
  return {dvec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x), dvec3(c, s + n.y * n.y * a, -n.y), n};
}
dvec3 to_world(const Basis& b, dvec3 l) { return l.x * b.t + l.y * b.b + l.z * b.n; }
dvec3 to_local(const Basis& b, dvec3 w) {
  return {glm::dot(w, b.t), glm::dot(w, b.b), glm::dot(w, b.n)};
}

dvec3 sample_cosine_hemisphere(dvec3 n, dvec2 u) {
  const double r = std::sqrt(u.x), phi = 2.0 * kPi * u.y;
  return glm::normalize(to_world(make_basis(n), dvec3(r * std::cos(phi), r * std::sin(phi),
                                                      std::sqrt(std::max(0.0, 1.0 - u.x)))));
}
dvec3 sample_cone(dvec3 axis, double one_minus_cos_max, dvec2 u) {
  const double one_minus_cos = u.x * one_minus_cos_max;
  const double cos_theta = 1.0 - one_minus_cos;
  const double sin_theta = std::sqrt(std::max(0.0, one_minus_cos * (2.0 - one_minus_cos)));
  const double phi = 2.0 * kPi * u.y;
  return glm::normalize(to_world(
      make_basis(axis), dvec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta)));
}
double cone_pdf(double one_minus_cos_max) {
  return 1.0 / (2.0 * kPi * std::max(one_minus_cos_max, 1e-300));
}
double ggx_d(double n_dot_h, double alpha) {
  const double a2 = alpha * alpha;
  const double d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
  return a2 / (kPi * d * d);
}
double ggx_lambda(double cos_theta, double alpha) {
  const double c2 = std::max(cos_theta * cos_theta, 1e-300);
  const double tan2 = std::max(1.0 - c2, 0.0) / c2;
  return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}
double ggx_g1(double c, double alpha) { return 1.0 / (1.0 + ggx_lambda(c, alpha)); }
double ggx_g2(double nv, double nl, double alpha) {
  return 1.0 / (1.0 + ggx_lambda(nv, alpha) + ggx_lambda(nl, alpha));
}
dvec3 sample_ggx_vndf(dvec3 v, double alpha, dvec2 u) {
  const dvec3 vh = glm::normalize(dvec3(alpha * v.x, alpha * v.y, v.z));
  const double len2 = vh.x * vh.x + vh.y * vh.y;
  const dvec3 t1 = len2 > 0.0 ? dvec3(-vh.y, vh.x, 0.0) / std::sqrt(len2) : dvec3(1, 0, 0);
  const dvec3 t2 = glm::cross(vh, t1);
  const double r = std::sqrt(u.x), phi = 2.0 * kPi * u.y;
  const double p1 = r * std::cos(phi);
  double p2 = r * std::sin(phi);
  const double s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
  const dvec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  return glm::normalize(dvec3(alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)));
}
double ggx_vndf_reflection_pdf(dvec3 v, dvec3 l, double alpha) {
  if (v.z <= 0.0 || l.z <= 0.0) return 0.0;
  const dvec3 h = glm::normalize(v + l);
  return ggx_g1(v.z, alpha) * ggx_d(h.z, alpha) / (4.0 * v.z);
}
double power_heuristic(double a, double b) {
  const double a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0 ? a2 / (a2 + b2) : 0.0;
}

enum Lobe { kDiffuse = 0, kSpecular = 1 };

struct Bsdf {
  dvec3 diffuse, specular;
  double alpha;
};
Bsdf material_bsdf(dvec3 kd, dvec3 ks, double shininess) {
  const double s = std::clamp(shininess, 0.0, 128.0);
  const double scale = std::min(1.0, 8.0 * (1.0 - std::exp2(-0.5 * s - 1.0)) / (s + 2.0));
  Bsdf b;
  b.specular = glm::clamp(ks, 0.0, 1.0) * scale;
  b.diffuse = glm::clamp(kd, 0.0, 1.0) * (1.0 - max3(b.specular));
  b.alpha = std::clamp(std::sqrt(2.0 / (s + 2.0)), 0.02, 1.0);
  return b;
}
// path_trace.comp unit_reflectance_bsdf: the primary vertex's lobes with unit reflectance (the
// channels hold light per unit of reflectance), the specular lobe picked with the material's
// share of the two reflectances within [0.05, 0.95] (1/2 where both are ~0). `specular_scale`
// turns the specular lobe's results into light per unit of its reflectance.
Bsdf unit_reflectance_bsdf(const Bsdf& material, bool specular_material, double& specular_scale) {
  Bsdf unit = material;
  unit.diffuse = dvec3(1.0);
  unit.specular = dvec3(0.0);
  specular_scale = 0.0;
  if (max3(material.specular) > 0.0 || specular_material) {
    const double d = luminance(material.diffuse), s = luminance(material.specular);
    // float, as the shader computes it
    const float p =
        d + s > 1e-4 ? std::clamp(float(s) / (float(d) + float(s)), 0.05f, 0.95f) : 0.5f;
    unit.specular = dvec3(p / (1.0 - p));
    specular_scale = (1.0 - p) / p;
  }
  return unit;
}
dvec3 bsdf_lobe_cos(const Bsdf& b, int lobe, dvec3 v, dvec3 l) {
  if (l.z <= 0.0) return dvec3(0.0);
  if (lobe == kDiffuse) return b.diffuse * (l.z / kPi);
  if (v.z <= 0.0) return dvec3(0.0);
  const dvec3 h = glm::normalize(v + l);
  return b.specular * (ggx_d(h.z, b.alpha) * ggx_g2(v.z, l.z, b.alpha) / (4.0 * v.z));
}
double specular_lobe_probability(const Bsdf& b) {
  const double d = luminance(b.diffuse), s = luminance(b.specular);
  return d + s > 0.0 ? s / (d + s) : 0.0;
}
double lobe_probability(const Bsdf& b, int lobe) {
  const double p = specular_lobe_probability(b);
  return lobe == kSpecular ? p : 1.0 - p;
}
double lobe_pdf(const Bsdf& b, int lobe, dvec3 v, dvec3 l) {
  if (lobe == kDiffuse) return std::max(l.z, 0.0) / kPi;
  return ggx_vndf_reflection_pdf(v, l, b.alpha);
}
dvec3 sample_lobe(const Bsdf& b, int lobe, dvec3 v, dvec2 u) {
  if (lobe == kDiffuse) return sample_cosine_hemisphere(dvec3(0, 0, 1), u);
  const dvec3 h = sample_ggx_vndf(v, b.alpha, u);
  return glm::reflect(-v, h);
}

// ---- geometry: triangles in a BVH built with the surface area heuristic ----------------------

struct Aabb {
  dvec3 lo{kInf}, hi{-kInf};
  void extend(dvec3 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void extend(const Aabb& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  bool empty() const { return lo.x > hi.x; }
  double area() const {
    if (empty()) return 0.0;
    const dvec3 e = hi - lo;
    return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
  double diagonal() const { return empty() ? 0.0 : glm::length(hi - lo); }
  bool contains(dvec3 p) const {
    return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
  }
};

struct Triangle {
  dvec3 p[3];  // eye space
  dvec3 n[3];  // the vertex normals (eye space: the modelview is a translation)
  int object = 0;
  int instance = 0;
  Aabb box() const {
    Aabb b;
    for (const dvec3& q : p) b.extend(q);
    return b;
  }
};

struct Hit {
  double t = kInf;
  int triangle = -1;
  double b1 = 0, b2 = 0;  // barycentrics of p[1] and p[2]
};

// Möller-Trumbore, two-sided, in double.
bool intersect(const Triangle& tri, dvec3 o, dvec3 d, double t_min, double t_max, Hit& hit) {
  const dvec3 e1 = tri.p[1] - tri.p[0], e2 = tri.p[2] - tri.p[0];
  const dvec3 pv = glm::cross(d, e2);
  const double det = glm::dot(e1, pv);
  if (det == 0.0 || !std::isfinite(det)) return false;
  const double inv = 1.0 / det;
  const dvec3 tv = o - tri.p[0];
  const double u = glm::dot(tv, pv) * inv;
  if (u < 0.0 || u > 1.0) return false;
  const dvec3 qv = glm::cross(tv, e1);
  const double v = glm::dot(d, qv) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  const double t = glm::dot(e2, qv) * inv;
  if (!(t > t_min && t < t_max)) return false;
  hit.t = t;
  hit.b1 = u;
  hit.b2 = v;
  return true;
}

// Binned SAH (Wald 2007): 16 bins per axis, all three axes; cost of a split
// kTraversal + (A_L N_L + A_R N_R) / A * kIntersect against a leaf's N * kIntersect. The
// constants are the textbook's equal weights (ray-box and ray-triangle tests cost about the
// same in double on a CPU); the tests' scenes are small, so they decide little.
class Bvh {
 public:
  static constexpr int kBins = 16;
  static constexpr double kTraversal = 1.0, kIntersect = 1.0;
  static constexpr int kMaxLeaf = 8;

  explicit Bvh(std::vector<Triangle> triangles) : tris_(std::move(triangles)) {
    order_.resize(tris_.size());
    for (size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
    boxes_.reserve(tris_.size());
    centres_.reserve(tris_.size());
    for (const Triangle& t : tris_) {
      boxes_.push_back(t.box());
      centres_.push_back(0.5 * (boxes_.back().lo + boxes_.back().hi));
    }
    nodes_.reserve(2 * tris_.size() + 1);
    nodes_.push_back({});
    if (!tris_.empty()) build(0, 0, static_cast<int>(tris_.size()));
    // Leaves hold triangles in `order_`'s order: reorder once so a leaf is a contiguous range.
    std::vector<Triangle> sorted;
    sorted.reserve(tris_.size());
    for (int i : order_) sorted.push_back(tris_[size_t(i)]);
    tris_ = std::move(sorted);
  }

  const std::vector<Triangle>& triangles() const { return tris_; }

  // The closest hit in (t_min, t_max), skipping triangle `skip`; `accept`: which triangles count.
  template <typename Accept>
  bool closest(dvec3 o, dvec3 d, double t_min, double t_max, int skip, Accept accept,
               Hit& hit) const {
    hit = Hit{};
    if (tris_.empty()) return false;
    const dvec3 inv = inverse(d);
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    double best = t_max;
    while (top > 0) {
      const Node& node = nodes_[size_t(stack[--top])];
      if (!overlaps(node.box, o, inv, t_min, best)) continue;
      if (node.count > 0) {
        for (int i = node.first; i < node.first + node.count; ++i) {
          Hit h;
          if (i == skip || !accept(tris_[size_t(i)])) continue;
          if (intersect(tris_[size_t(i)], o, d, t_min, best, h)) {
            best = h.t;
            hit = h;
            hit.triangle = i;
          }
        }
      } else {
        stack[top++] = node.first;
        stack[top++] = node.first + 1;
      }
    }
    return hit.triangle >= 0;
  }

 private:
  struct Node {
    Aabb box;
    int first = 0;  // leaf: first triangle; inner: the left child (the right one follows it)
    int count = 0;  // > 0: leaf
  };

  static dvec3 inverse(dvec3 d) {
    auto inv = [](double x) { return 1.0 / (x == 0.0 ? 1e-300 : x); };
    return {inv(d.x), inv(d.y), inv(d.z)};
  }
  static bool overlaps(const Aabb& b, dvec3 o, dvec3 inv, double t_min, double t_max) {
    double lo = t_min, hi = t_max;
    for (int a = 0; a < 3; ++a) {
      double t0 = (b.lo[a] - o[a]) * inv[a], t1 = (b.hi[a] - o[a]) * inv[a];
      if (t0 > t1) std::swap(t0, t1);
      lo = std::max(lo, t0);
      hi = std::min(hi, t1 * (1.0 + 4e-16));  // keeps hits on a box's face
      if (lo > hi) return false;
    }
    return true;
  }

  void build(int index, int begin, int end) {
    Aabb box, centre_box;
    for (int i = begin; i < end; ++i) {
      box.extend(boxes_[size_t(order_[size_t(i)])]);
      centre_box.extend(centres_[size_t(order_[size_t(i)])]);
    }
    nodes_[size_t(index)].box = box;
    const int n = end - begin;
    int best_axis = -1, best_split = 0;
    double best_cost = kIntersect * n;
    if (n > 2) {
      for (int axis = 0; axis < 3; ++axis) {
        const double lo = centre_box.lo[axis], extent = centre_box.hi[axis] - lo;
        if (!(extent > 0.0)) continue;
        Aabb bins[kBins];
        int counts[kBins] = {};
        for (int i = begin; i < end; ++i) {
          const int b = bin_of(centres_[size_t(order_[size_t(i)])][axis], lo, extent);
          bins[b].extend(boxes_[size_t(order_[size_t(i)])]);
          ++counts[b];
        }
        // Sweep: the cost of splitting after bin k.
        double right_area[kBins];
        int right_count[kBins];
        Aabb acc;
        int cnt = 0;
        for (int k = kBins - 1; k > 0; --k) {
          acc.extend(bins[k]);
          cnt += counts[k];
          right_area[k] = acc.area();
          right_count[k] = cnt;
        }
        acc = Aabb{};
        cnt = 0;
        for (int k = 0; k < kBins - 1; ++k) {
          acc.extend(bins[k]);
          cnt += counts[k];
          if (cnt == 0 || right_count[k + 1] == 0) continue;
          const double cost =
              kTraversal + kIntersect *
                               (acc.area() * cnt + right_area[k + 1] * right_count[k + 1]) /
                               std::max(box.area(), 1e-300);
          if (cost < best_cost) {
            best_cost = cost;
            best_axis = axis;
            best_split = k;
          }
        }
      }
    }
    if (best_axis < 0 && n > kMaxLeaf) {
      // No split pays and the leaf is big (coincident centres): halve it by index.
      best_axis = -2;
    }
    if (best_axis == -1) {
      nodes_[size_t(index)].first = begin;
      nodes_[size_t(index)].count = n;
      return;
    }
    int middle;
    if (best_axis == -2) {
      middle = begin + n / 2;
    } else {
      const double lo = centre_box.lo[best_axis], extent = centre_box.hi[best_axis] - lo;
      middle = static_cast<int>(std::partition(order_.begin() + begin, order_.begin() + end,
                                               [&](int t) {
                                                 return bin_of(centres_[size_t(t)][best_axis], lo,
                                                               extent) <= best_split;
                                               }) -
                                order_.begin());
    }
    const int left = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    nodes_.push_back({});
    nodes_[size_t(index)].first = left;
    nodes_[size_t(index)].count = 0;
    build(left, begin, middle);
    build(left + 1, middle, end);
  }
  static int bin_of(double c, double lo, double extent) {
    return std::clamp(static_cast<int>((c - lo) / extent * kBins), 0, kBins - 1);
  }

  std::vector<Triangle> tris_;
  std::vector<int> order_;
  std::vector<Aabb> boxes_;
  std::vector<dvec3> centres_;
  std::vector<Node> nodes_;
};

// ---- lights (shaders/trace/lights.h) ----------------------------------------------------------

struct PackedLight {  // rt_core/scene/light_setup.cpp pack_light
  glm::dvec4 position;
  dvec3 ambient, diffuse, specular;
  dvec3 spot_direction;
  double spot_cos = -2.0;  // -2: no spot
  double spot_exponent = 0, kc = 1, kl = 0, kq = 0;
  double radius = 0;
  dvec3 centre() const { return position.w != 0.0 ? dvec3(position) / position.w : dvec3(0.0); }
};

struct LightView {
  dvec3 direction;
  double distance = kUnbounded;
  double cos_max = 1, one_minus_cos = 0, sphere_radius = 0;
  dvec3 diffuse{0.0}, specular{0.0}, ambient{0.0};
  double weight = 0;
};

constexpr int kMaxLights = 8;
struct LightChoice {
  int count = 0;
  std::array<LightView, kMaxLights> views;
  std::array<double, kMaxLights> probability{};
  dvec3 ambient{0.0};
};

struct Emitter {
  dvec3 p[3];
  dvec3 emission;
  double area, probability, cumulative;
};

struct Surface {
  dvec3 position, shadow_position, normal, offset_normal;
  Material material;  // GL's (float) colours
  int triangle = -1;
};

class Tracer {
 public:
  Tracer(const Scene& scene, const Options& options)
      : scene_(scene), options_(options), bvh_(triangles_of(scene)) {
    // Instances: runs of consecutive objects under one modelview (the scene's translation),
    // as glpt's batcher forms them (rt_core/scene/scene_builder.cpp).
    instance_bounds_.resize(size_t(instance_count_));
    for (const Triangle& t : bvh_.triangles()) instance_bounds_[size_t(t.instance)].extend(t.box());
    Aabb scene_box;
    for (const Aabb& b : instance_bounds_) scene_box.extend(b);
    const double angle = glm::radians(static_cast<double>(scene.trace.light_size_deg));
    distant_cos_ = std::cos(angle);
    distant_one_minus_cos_ = 2.0 * std::sin(0.5 * angle) * std::sin(0.5 * angle);
    for (size_t i = 0; i < scene.lights.size() && i < kMaxLights; ++i) {
      lights_.push_back(pack(scene.lights[i], angle));
      // Lamp markers: a small instance enclosing a positional light casts no shadow of it
      // (light_setup.cpp; a shadow bit is shared by lights 5, 6 and 7).
      for (size_t k = 0; k < instance_bounds_.size(); ++k) {
        const Aabb& b = instance_bounds_[k];
        const bool small =
            !b.empty() && b.diagonal() < kLampMarkerMaxSceneFraction * scene_box.diagonal();
        if (small && lights_.back().position.w != 0.0 && b.contains(lights_.back().centre()))
          lamp_markers_.push_back({int(k), static_cast<int>(std::min<size_t>(i, kShadowBits - 1))});
      }
    }
    // Emitters (path_tracer.cpp add_emitters / finish_emitters): triangles of lit objects with
    // emission, chosen in proportion to area x luminance.
    double total = 0.0;
    for (const Triangle& t : bvh_.triangles()) {
      const dvec3 e = dvec3(scene.objects[size_t(t.object)].material.emission);
      const double area = 0.5 * glm::length(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
      const double power = area * luminance(e);
      if (!(power > 0.0) || !std::isfinite(power)) continue;
      emitters_.push_back({{t.p[0], t.p[1], t.p[2]}, e, area, power, 0.0});
      total += power;
    }
    double cumulative = 0.0;
    emitter_of_triangle_.assign(bvh_.triangles().size(), -1);
    for (Emitter& e : emitters_) {
      cumulative += e.probability;
      e.probability /= total;
      e.cumulative = cumulative / total;
    }
    for (size_t i = 0, k = 0; i < bvh_.triangles().size(); ++i) {
      const Triangle& t = bvh_.triangles()[i];
      const dvec3 e = dvec3(scene.objects[size_t(t.object)].material.emission);
      const double area = 0.5 * glm::length(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
      if (area * luminance(e) > 0.0 && std::isfinite(area * luminance(e)))
        emitter_of_triangle_[i] = static_cast<int>(k++);
    }
  }

  // The composite colour of one sample at window position `w` (before the clamp).
  dvec3 sample(dvec2 w, Rng& rng) const {
    const Camera& c = scene_.camera;
    const double size = scene_.size;
    const double x = c.left + (c.right - c.left) * (w.x / size);
    const double y = c.bottom + (c.top - c.bottom) * (w.y / size);
    dvec3 origin, direction;
    double t_near, t_far;
    if (c.perspective) {
      origin = dvec3(0.0);
      direction = glm::normalize(dvec3(x, y, -double(c.near_plane)));
      t_near = c.near_plane / -direction.z;
      t_far = c.far_plane / -direction.z;
    } else {
      origin = dvec3(x, y, 0.0);
      direction = dvec3(0, 0, -1);
      t_near = c.near_plane;
      t_far = c.far_plane;
    }
    Hit hit;
    if (!bvh_.closest(origin, direction, t_near, t_far, -1, every, hit))
      return dvec3(scene_.clear_color);
    const Surface s = primary_surface(hit, origin + hit.t * direction);
    return dvec3(s.material.emission) + trace_path(s, rng);
  }

 private:
  static bool every(const Triangle&) { return true; }

  std::vector<Triangle> triangles_of(const Scene& scene) {
    std::vector<Triangle> out;
    instance_count_ = 0;
    glm::vec3 previous{0.0f};
    for (size_t o = 0; o < scene.objects.size(); ++o) {
      const Object& object = scene.objects[o];
      if (o == 0 || object.translation != previous) ++instance_count_;
      previous = object.translation;
      const dvec3 offset(object.translation);
      for (size_t v = 0; v + 2 < object.vertices.size(); v += 3) {
        Triangle t;
        for (int k = 0; k < 3; ++k) {
          t.p[k] = dvec3(object.vertices[v + size_t(k)].position) + offset;
          t.n[k] = dvec3(object.vertices[v + size_t(k)].normal);
        }
        t.object = static_cast<int>(o);
        t.instance = instance_count_ - 1;
        out.push_back(t);
      }
    }
    return out;
  }

  PackedLight pack(const Light& l, double angular_radius) const {
    PackedLight p;
    p.position = glm::dvec4(l.position);
    if (l.position.w == 0.0f)
      p.position = glm::dvec4(normalize_or(dvec3(l.position), dvec3(0, 0, 1)), 0.0);
    p.ambient = dvec3(l.ambient);
    p.diffuse = dvec3(l.diffuse);
    p.specular = dvec3(l.specular);
    p.spot_direction = normalize_or(dvec3(l.spot_direction), dvec3(0, 0, -1));
    if (l.spot_cutoff < 180.0f)
      p.spot_cos = std::cos(glm::radians(std::clamp(double(l.spot_cutoff), 0.0, 90.0)));
    p.spot_exponent = l.spot_exponent;
    p.kc = l.constant_attenuation;
    p.kl = l.linear_attenuation;
    p.kq = l.quadratic_attenuation;
    if (l.position.w != 0.0f) {
      const double r = scene_.trace.light_radius >= 0.0f
                           ? double(scene_.trace.light_radius)
                           : std::sin(angular_radius) * glm::length(p.centre());
      p.radius = std::isfinite(r) && r > 0.0 ? r : 0.0;
    }
    return p;
  }

  // lights.h attenuation_gl.
  double attenuation_gl(const PackedLight& l, dvec3 to_light, double d,
                        bool spot_directional) const {
    double a = 1.0;
    const bool positional = l.position.w != 0.0;
    if (positional) {
      const double dq = options_.fault == Fault::kWrongAttenuation ? d : d * d;
      a = 1.0 / std::max(l.kc + l.kl * d + l.kq * dq, 1e-20);
    }
    if (l.spot_cos > -1.5 && (positional || spot_directional)) {
      const double spot_cos = glm::dot(-to_light, l.spot_direction);
      a *= spot_cos >= l.spot_cos ? power_gl(spot_cos, l.spot_exponent) : 0.0;
    }
    return a;
  }

  // lights.h view_light.
  LightView view_light(const PackedLight& l, dvec3 p, dvec3 n) const {
    LightView v;
    double sin2 = 0.0;
    if (l.position.w != 0.0) {
      const dvec3 offset = l.centre() - p;
      v.distance = std::max(glm::length(offset), 1e-300);
      v.direction = offset / v.distance;
      if (l.radius > 0.0 && v.distance > 1.001 * l.radius) {
        const double ratio = l.radius / v.distance;
        sin2 = ratio * ratio;
        v.cos_max = std::sqrt(std::max(0.0, 1.0 - sin2));
        v.one_minus_cos = sin2 / (1.0 + v.cos_max);
        v.sphere_radius = l.radius;
      }
    } else {
      v.direction = dvec3(l.position);
      v.distance = kUnbounded;
      v.cos_max = distant_cos_;
      v.one_minus_cos = distant_one_minus_cos_;
      sin2 = v.one_minus_cos * (1.0 + v.cos_max);
    }
    const double attenuation = attenuation_gl(l, v.direction, v.distance, false);
    v.ambient = attenuation_gl(l, v.direction, v.distance, true) * l.ambient;
    const double scale = v.one_minus_cos > 0.0 ? attenuation / sin2 : attenuation;
    v.diffuse = scale * l.diffuse;
    v.specular = scale * l.specular;
    const double cosine = std::clamp(glm::dot(n, v.direction) + std::sqrt(sin2), 0.0, 1.0);
    v.weight = attenuation * cosine * luminance(l.diffuse + l.specular);
    if (!(v.weight >= 0.0) || std::isinf(v.weight)) v.weight = 0.0;
    return v;
  }

  LightChoice choose_lights(dvec3 p, dvec3 n) const {
    LightChoice c;
    c.count = static_cast<int>(lights_.size());
    c.ambient = dvec3(scene_.global_ambient);
    double total = 0.0;
    for (int i = 0; i < c.count; ++i) {
      c.views[size_t(i)] = view_light(lights_[size_t(i)], p, n);
      c.ambient += c.views[size_t(i)].ambient;
      total += c.views[size_t(i)].weight;
    }
    for (int i = 0; i < c.count; ++i)
      c.probability[size_t(i)] = options_.fault == Fault::kUniformLightChoice
                                     ? 1.0 / c.count
                                     : (total > 0.0 ? c.views[size_t(i)].weight / total : 0.0);
    return c;
  }
  static int pick_light(const LightChoice& c, double u) {
    double cumulative = 0.0;
    int last = c.count;
    for (int i = 0; i < c.count; ++i) {
      if (c.probability[size_t(i)] <= 0.0) continue;
      last = i;
      cumulative += c.probability[size_t(i)];
      if (u < cumulative) return i;
    }
    return last;
  }
  static double light_direction_pdf(const LightChoice& c, int i, dvec3 direction) {
    const LightView& v = c.views[size_t(i)];
    if (v.one_minus_cos <= 0.0 || glm::dot(direction, v.direction) < v.cos_max) return 0.0;
    return c.probability[size_t(i)] * cone_pdf(v.one_minus_cos);
  }
  static double light_hit_distance(const LightView& v, dvec3 origin, dvec3 direction,
                                   dvec3 centre) {
    if (v.one_minus_cos <= 0.0) return kUnbounded;
    if (v.sphere_radius <= 0.0)
      return glm::dot(direction, v.direction) >= v.cos_max ? 0.5 * kUnbounded : kUnbounded;
    const dvec3 oc = centre - origin;
    const double b = glm::dot(oc, direction);
    const double c = glm::dot(oc, oc) - v.sphere_radius * v.sphere_radius;
    const double disc = b * b - c;
    if (disc < 0.0) return kUnbounded;
    const double t = b - std::sqrt(disc);
    return t > 0.0 ? t : kUnbounded;
  }

  // ---- surfaces (shaders/trace/surface.h) ---------------------------------------------------

  dvec3 towards_viewer(dvec3 p) const {
    return scene_.camera.perspective ? normalize_or(-p, dvec3(0, 0, 1)) : dvec3(0, 0, 1);
  }

  // The G-buffer surface (load_gbuffer_surface): shading normal as GL lights with it, flipped
  // for faces seen from behind under two-sided lighting; rays leave on the viewer's side.
  Surface primary_surface(const Hit& hit, dvec3 position) const {
    const Triangle& t = bvh_.triangles()[size_t(hit.triangle)];
    Surface s = surface_at(hit, position);
    const dvec3 geometric = glm::normalize(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
    const dvec3 shading = shading_normal(t, hit, geometric);
    const bool back = glm::dot(geometric, towards_viewer(position)) < 0.0;
    s.offset_normal = back ? -geometric : geometric;
    s.shadow_position = offset_origin(position, s.offset_normal);
    // GL's front face is the counter-clockwise one in window coordinates: for the eye-space
    // winding here that is the face whose geometric normal points to the viewer.
    s.normal = back && scene_.two_side ? -shading : shading;
    return s;
  }
  // A surface a bounce ray hit (load_surface).
  Surface bounce_surface(const Hit& hit, dvec3 position, dvec3 ray_direction) const {
    const Triangle& t = bvh_.triangles()[size_t(hit.triangle)];
    Surface s = surface_at(hit, position);
    const dvec3 geometric = glm::normalize(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
    const dvec3 shading = shading_normal(t, hit, geometric);
    const bool from_front = glm::dot(geometric, ray_direction) < 0.0;
    s.offset_normal = from_front ? geometric : -geometric;
    s.shadow_position = offset_origin(position, s.offset_normal);
    s.normal = !from_front && scene_.two_side ? -shading : shading;
    return s;
  }
  static dvec3 shading_normal(const Triangle& t, const Hit& hit, dvec3 geometric) {
    const double w0 = 1.0 - hit.b1 - hit.b2;
    return normalize_or(w0 * t.n[0] + hit.b1 * t.n[1] + hit.b2 * t.n[2], geometric);
  }
  Surface surface_at(const Hit& hit, dvec3 position) const {
    const Triangle& t = bvh_.triangles()[size_t(hit.triangle)];
    Surface s;
    s.position = position;
    s.shadow_position = position;
    s.material = scene_.objects[size_t(t.object)].material;
    s.triangle = hit.triangle;
    return s;
  }

  // ---- queries --------------------------------------------------------------------------------

  static dvec3 offset_origin(dvec3 p, dvec3 n) {
    return p +
           n * (kRelativeEpsilon * std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1e-300}));
  }
  bool closest_from(const Surface& s, dvec3 d, double t_max, Hit& hit) const {
    return bvh_.closest(s.shadow_position, d, 0.0, t_max, -1, every, hit);
  }
  // A shadow ray of light `light` (-1: every instance, the emitter and AO rays' mask).
  bool blocked(const Surface& s, dvec3 d, double t_max, int light) const {
    Hit hit;
    const int bit = light < 0 ? -1 : std::min(light, int(kShadowBits) - 1);
    auto casts = [&](const Triangle& t) {
      if (bit < 0) return true;
      for (const auto& [instance, marker_bit] : lamp_markers_)
        if (instance == t.instance && marker_bit == bit) return false;
      return true;
    };
    return bvh_.closest(s.shadow_position, d, 0.0, t_max, -1, casts, hit);
  }
  bool ao_blocked(const Surface& s, dvec3 d) const {
    const double radius = scene_.trace.ao_radius;
    Hit hit;
    if (!closest_from(s, d, radius > 0.0 ? radius : kUnbounded, hit)) return false;
    if (radius > 0.0) return true;
    return hit.t <
           instance_bounds_[size_t(bvh_.triangles()[size_t(hit.triangle)].instance)].diagonal();
  }

  // emitters.h sample_emitter / emitter_direction_pdf.
  bool sample_emitter(dvec3 origin, double u_choice, dvec2 u, dvec3& direction, double& distance,
                      dvec3& radiance, double& pdf) const {
    size_t k = 0;
    while (k + 1 < emitters_.size() && u_choice >= emitters_[k].cumulative) ++k;
    const Emitter& e = emitters_[k];
    const double r = std::sqrt(u.x);
    const dvec3 w(1.0 - r, r * (1.0 - u.y), r * u.y);
    const dvec3 point = w.x * e.p[0] + w.y * e.p[1] + w.z * e.p[2];
    const dvec3 offset = point - origin;
    distance = glm::length(offset);
    if (!(distance > 0.0)) return false;
    direction = offset / distance;
    const dvec3 normal = glm::normalize(glm::cross(e.p[1] - e.p[0], e.p[2] - e.p[0]));
    const double c = std::abs(glm::dot(normal, direction));
    pdf = c > 0.0 ? e.probability * distance * distance / (e.area * c) : 0.0;
    radiance = e.emission;
    return pdf > 0.0 && std::isfinite(pdf);
  }
  double emitter_direction_pdf(int triangle, dvec3 direction, double t) const {
    const int k = emitter_of_triangle_[size_t(triangle)];
    if (k < 0) return 0.0;
    const Emitter& e = emitters_[size_t(k)];
    const dvec3 normal = glm::normalize(glm::cross(e.p[1] - e.p[0], e.p[2] - e.p[0]));
    const double c = std::abs(glm::dot(normal, direction));
    return c > 0.0 ? e.probability * t * t / (e.area * c) : 0.0;
  }

  // ---- the path (path_trace.comp trace_path), all channels summed -----------------------------

  // What a path brings through each lobe of the vertex it leaves.
  struct Lobes {
    dvec3 diffuse{0.0}, specular{0.0};
    dvec3 sum() const { return diffuse + specular; }
  };

  // The primary vertex is traced with unit reflectances and its lobes' light multiplied by the
  // material's reflectances at the end, as the composite pass does (gbuffer_material.h: where
  // the albedo is below 1/1000 but GL's ambient or diffuse colour is not, the diffuse light is
  // radiance as it is; GL's ambient term is dropped where both are below 1/1000).
  dvec3 trace_path(const Surface& first, Rng& rng) const {
    Lobes primary;       // the path's light by the primary vertex's lobe, per unit of reflectance
    dvec3 ambient(0.0);  // GL's ambient term at the primary vertex (radiance)
    int first_lobe = kDiffuse;
    const Bsdf material = material_bsdf(dvec3(first.material.diffuse),
                                        dvec3(first.material.specular), first.material.shininess);
    double specular_scale = 1.0;
    Surface s = first;
    dvec3 to_viewer = towards_viewer(s.position);
    dvec3 throughput(1.0);
    int bounces = scene_.trace.bounces;
    if (options_.fault == Fault::kDroppedBounce) bounces = std::max(bounces - 1, 0);
    double emission_weight = 1.0;
    auto add = [&](bool direct_at_primary, const Lobes& value) {
      if (direct_at_primary) {
        primary.diffuse += value.diffuse;
        primary.specular += value.specular;
      } else if (first_lobe == kSpecular) {
        primary.specular += value.sum();
      } else {
        primary.diffuse += value.sum();
      }
    };
    for (int depth = 0;; ++depth) {
      const Basis basis = make_basis(s.normal);
      const dvec3 v = to_local(basis, to_viewer);
      if (depth > 0)
        add(false, {throughput * dvec3(s.material.emission) * emission_weight, dvec3(0.0)});
      Bsdf bsdf = depth == 0 ? unit_reflectance_bsdf(
                                   material, max3(dvec3(s.material.specular)) > 0.0, specular_scale)
                             : material_bsdf(dvec3(s.material.diffuse), dvec3(s.material.specular),
                                             s.material.shininess);
      if (v.z <= 1e-4) bsdf.specular = dvec3(0.0);
      const LightChoice choice = choose_lights(s.position, s.normal);
      const bool bounce = depth < bounces;

      if (depth == 0) {
        const dvec3 brings = dvec3(s.material.ambient) * choice.ambient;
        if (!scene_.trace.ao) {
          ambient += brings;
        } else if (max3(brings) > 0.0) {
          const dvec3 d = sample_cosine_hemisphere(s.normal, rng.next2());
          if (glm::dot(d, s.offset_normal) > 0.0 && !ao_blocked(s, d)) ambient += brings;
        }
      }
      if (choice.count > 0) {
        const int i = pick_light(choice, rng.next());
        const dvec2 u = rng.next2();
        if (i < choice.count) {
          const Lobes l = light_sample(s, bsdf, basis, v, choice, i, bounce, u);
          add(depth == 0, {throughput * l.diffuse, throughput * l.specular});
        }
      }
      if (!emitters_.empty()) {
        const double u_choice = rng.next();
        const Lobes e = emitter_sample(s, bsdf, basis, v, bounce, u_choice, rng.next2());
        add(depth == 0, {throughput * e.diffuse, throughput * e.specular});
      }
      if (!bounce) break;

      const double p_specular = specular_lobe_probability(bsdf);
      if (max3(bsdf.diffuse) <= 0.0 && p_specular <= 0.0) break;
      const int lobe = rng.next() < p_specular ? kSpecular : kDiffuse;
      const double p_lobe = lobe == kSpecular ? p_specular : 1.0 - p_specular;
      const dvec3 l = sample_lobe(bsdf, lobe, v, rng.next2());
      const double pdf = p_lobe * lobe_pdf(bsdf, lobe, v, l);
      if (l.z <= 0.0 || pdf <= 0.0) break;
      const dvec3 direction = glm::normalize(to_world(basis, l));
      if (glm::dot(direction, s.offset_normal) <= 0.0) break;
      const dvec3 weight = bsdf_lobe_cos(bsdf, lobe, v, l) / pdf;
      if (depth == 0) first_lobe = lobe;

      Hit hit;
      const bool found = closest_from(s, direction, kUnbounded, hit);
      const double t_hit = found ? hit.t : kUnbounded;
      for (int i = 0; i < choice.count; ++i) {
        const LightView& view = choice.views[size_t(i)];
        const double t_light =
            light_hit_distance(view, s.shadow_position, direction, lights_[size_t(i)].centre());
        if (t_light >= t_hit) continue;
        const double light_pdf = light_direction_pdf(choice, i, direction);
        if (light_pdf <= 0.0) continue;
        const dvec3 l_radiance = lobe == kSpecular ? view.specular : view.diffuse;
        const dvec3 value = throughput * weight * l_radiance * power_heuristic(pdf, light_pdf);
        add(depth == 0, lobe == kSpecular ? Lobes{dvec3(0.0), value} : Lobes{value, dvec3(0.0)});
      }
      emission_weight = 1.0;
      if (found) {
        const double e_pdf = emitter_direction_pdf(hit.triangle, direction, hit.t);
        if (e_pdf > 0.0) emission_weight = power_heuristic(pdf, e_pdf);
      }
      throughput *= weight;
      if (!found) break;  // GLPT_ENVIRONMENT=black, no sky
      if (depth >= 1) {
        const double keep = std::clamp(max3(throughput), 0.05, 0.95);
        if (rng.next() >= keep) break;
        throughput /= keep;
      }
      s = bounce_surface(hit, s.shadow_position + hit.t * direction, direction);
      to_viewer = -direction;
    }
    // The composite pass's reflectances.
    dvec3 radiance(0.0);
    for (int c = 0; c < 3; ++c) {
      const double albedo = material.diffuse[c];
      const bool raw = albedo < 1e-3 && std::max(double(first.material.ambient[c]),
                                                 double(first.material.diffuse[c])) >= 1e-3;
      radiance[c] += albedo * primary.diffuse[c] + (raw || albedo >= 1e-3 ? ambient[c] : 0.0);
      radiance[c] += material.specular[c] * specular_scale * primary.specular[c];
    }
    return radiance;
  }

  // light_ray: what next-event estimation of light i brings through both lobes (unoccluded
  // part only: the shadow ray is traced here).
  Lobes light_sample(const Surface& s, const Bsdf& bsdf, const Basis& basis, dvec3 v,
                     const LightChoice& choice, int i, bool mis, dvec2 u) const {
    const LightView& view = choice.views[size_t(i)];
    const double probability = choice.probability[size_t(i)];
    if (probability <= 0.0) return {};
    const bool area = view.one_minus_cos > 0.0;
    const dvec3 d = area ? sample_cone(view.direction, view.one_minus_cos, u) : view.direction;
    const dvec3 l = to_local(basis, d);
    if (l.z <= 0.0) return {};
    const dvec3 f_d = bsdf_lobe_cos(bsdf, kDiffuse, v, l);
    const dvec3 f_s = bsdf_lobe_cos(bsdf, kSpecular, v, l);
    if (max3(f_d + f_s) <= 0.0) return {};
    Lobes brings;
    if (!area) {
      brings = {kPi * f_d * view.diffuse / probability, kPi * f_s * view.specular / probability};
    } else {
      const double pdf = probability * cone_pdf(view.one_minus_cos);
      double w_d = 1.0, w_s = 1.0;
      if (mis) {
        w_d =
            power_heuristic(pdf, lobe_probability(bsdf, kDiffuse) * lobe_pdf(bsdf, kDiffuse, v, l));
        w_s = power_heuristic(pdf,
                              lobe_probability(bsdf, kSpecular) * lobe_pdf(bsdf, kSpecular, v, l));
      }
      brings = {w_d * f_d * view.diffuse / pdf, w_s * f_s * view.specular / pdf};
    }
    if (scene_.trace.shadows && blocked(s, d, view.distance - view.sphere_radius, i)) return {};
    return brings;
  }

  Lobes emitter_sample(const Surface& s, const Bsdf& bsdf, const Basis& basis, dvec3 v, bool mis,
                       double u_choice, dvec2 u) const {
    dvec3 d, e_radiance;
    double distance, pdf;
    if (!sample_emitter(s.position, u_choice, u, d, distance, e_radiance, pdf)) return {};
    if (max3(e_radiance) <= 0.0) return {};
    const dvec3 l = to_local(basis, d);
    if (l.z <= 0.0 || glm::dot(d, s.offset_normal) <= 0.0) return {};
    const dvec3 f_d = bsdf_lobe_cos(bsdf, kDiffuse, v, l);
    const dvec3 f_s = bsdf_lobe_cos(bsdf, kSpecular, v, l);
    double w_d = 1.0, w_s = 1.0;
    if (mis) {
      w_d = power_heuristic(pdf, lobe_probability(bsdf, kDiffuse) * lobe_pdf(bsdf, kDiffuse, v, l));
      w_s =
          power_heuristic(pdf, lobe_probability(bsdf, kSpecular) * lobe_pdf(bsdf, kSpecular, v, l));
    }
    const Lobes brings{w_d * f_d * e_radiance / pdf, w_s * f_s * e_radiance / pdf};
    if (max3(brings.sum()) <= 0.0) return {};
    // Stop short of the emitter itself (emitter_ray): only what lies between blocks it.
    if (scene_.trace.shadows && blocked(s, d, distance * (1.0 - 1e-3), -1)) return {};
    return brings;
  }

  const Scene& scene_;
  Options options_;
  int instance_count_ = 0;
  Bvh bvh_;
  std::vector<Aabb> instance_bounds_;
  std::vector<PackedLight> lights_;
  std::vector<std::pair<int, int>> lamp_markers_;  // (instance, shadow bit)
  std::vector<Emitter> emitters_;
  std::vector<int> emitter_of_triangle_;
  double distant_cos_ = 1.0, distant_one_minus_cos_ = 0.0;
};

// path_tracer.cpp halton: the radical inverse of `index` in `base`.
double halton(uint32_t index, uint32_t base) {
  double result = 0.0, fraction = 1.0;
  for (; index > 0; index /= base) {
    fraction /= base;
    result += fraction * (index % base);
  }
  return result;
}

}  // namespace

Estimate render(const Scene& scene, const Options& options) {
  Estimate estimate;
  estimate.size = scene.size;
  estimate.options = options;
  estimate.pixels.resize(size_t(scene.size) * size_t(scene.size));
  const Tracer tracer(scene, options);
  const int positions = std::max(options.jitter_positions, 1);
  auto work = [&](int thread) {
    for (int y = thread; y < scene.size; y += std::max(options.threads, 1)) {
      for (int x = 0; x < scene.size; ++x) {
        uint64_t seed = options.seed * 0x100000001B3ull + uint64_t(y) * 65537ull + uint64_t(x);
        Rng rng(splitmix64(seed));
        PixelEstimate& p = estimate.pixels[size_t(y) * size_t(scene.size) + size_t(x)];
        // Welford's running mean and variance.
        dvec3 mean(0.0), m2(0.0);
        for (int i = 0; i < options.samples; ++i) {
          // The sample's jitter position: GLPT_REFERENCE's pass i mod 64. A pass moves the
          // geometry by +jitter pixels (raster_ff.vert), so the pixel samples its centre minus it.
          const uint32_t pass = static_cast<uint32_t>(i % positions);
          const dvec2 jitter =
              pass == 0 ? dvec2(0.0) : dvec2(halton(pass, 2), halton(pass, 3)) - 0.5;
          const dvec3 c = tracer.sample(dvec2(x + 0.5, y + 0.5) - jitter, rng);
          const dvec3 delta = c - mean;
          mean += delta / double(i + 1);
          m2 += delta * (c - mean);
        }
        p.mean = mean;
        p.variance = options.samples > 1 ? m2 / double(options.samples - 1) : dvec3(0.0);
        // A 1-sample frame at the pixel's centre, as 8-bit values: raw moments, then central.
        dvec3 s1(0.0), s2(0.0), s3(0.0), s4(0.0);
        for (int i = 0; i < options.center_samples; ++i) {
          const dvec3 c = tracer.sample(dvec2(x + 0.5, y + 0.5), rng);
          const dvec3 q = glm::floor(255.0 * glm::clamp(c, 0.0, 1.0) + 0.5);
          s1 += q;
          s2 += q * q;
          s3 += q * q * q;
          s4 += q * q * q * q;
        }
        if (options.center_samples > 1) {
          const double n = options.center_samples;
          const dvec3 m = s1 / n;
          p.q_mean = m;
          p.q_variance = (s2 / n - m * m) * (n / (n - 1.0));
          p.q_m4 = s4 / n - 4.0 * m * s3 / n + 6.0 * m * m * s2 / n - 3.0 * m * m * m * m;
        }
      }
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < std::max(options.threads, 1); ++t) threads.emplace_back(work, t);
  work(0);
  for (std::thread& t : threads) t.join();
  return estimate;
}

}  // namespace glpt::reference
