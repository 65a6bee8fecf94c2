// ray_ceiling: how fast can the rays of one glpt frame be traced without glpt's shading?
// Reads a GLPT_DUMP_SCENE file (rt_core/scene/scene_dump.hpp), generates a glpt-like ray mix
// over its triangles (rays.hpp) and traces it with a bare ray-query compute shader on the same
// Vulkan device as glpt (lavapipe) and with Embree 3 on the CPU. See docs/ray-ceiling.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "embree_tracer.hpp"
#include "rays.hpp"
#include "rt_core/scene/scene_dump.hpp"
#include "vk_tracer.hpp"

using namespace ray_ceiling;

namespace {

constexpr uint32_t kOptionAo = 2;  // shared_types.h: GLPT_OPTION_AO

void usage() {
  std::printf(
      "usage: ray_ceiling DUMP [options]\n"
      "  DUMP            a file written by glpt under GLPT_DUMP_SCENE=DUMP\n"
      "  --reps R        timed repetitions per tracer, interleaved (default 5)\n"
      "  --threads T     Embree trace threads (default 2)\n"
      "  --no-flat       skip the one-BLAS-per-mask Vulkan variant\n"
      "  --seed S        ray seed (default 1)\n"
      "Prints the ray mix, each tracer's median Mrays/s, hit agreement and one RESULT line.\n");
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

struct Agreement {
  size_t rays = 0, hit_miss = 0, other_triangle = 0, t_mismatch = 0, hits_a = 0, hits_b = 0;
};

// Closest-hit rays: same triangle (or same t within 1e-3 relative); shadow rays: hit/miss only.
Agreement compare(const std::vector<Ray>& rays, const std::vector<Hit>& a, const AccelInput& ia,
                  const std::vector<Hit>& b, const AccelInput& ib) {
  Agreement g;
  g.rays = rays.size();
  for (size_t i = 0; i < rays.size(); ++i) {
    const bool ha = a[i].t >= 0, hb = b[i].t >= 0;
    g.hits_a += ha;
    g.hits_b += hb;
    if (ha != hb) {
      ++g.hit_miss;
      continue;
    }
    if (!ha || (rays[i].flags & kTerminateOnFirstHit)) continue;
    if (global_triangle(ia, a[i]) != global_triangle(ib, b[i])) {
      if (std::abs(a[i].t - b[i].t) <= 1e-3f * std::max(1.0f, std::abs(b[i].t)))
        ++g.other_triangle;
      else
        ++g.t_mismatch;
    }
  }
  return g;
}

void print_agreement(const char* what, const Agreement& g) {
  std::printf(
      "[check] %-34s rays %zu | hits %zu vs %zu | hit/miss differ %zu | other triangle at same t "
      "%zu | t differs %zu\n",
      what, g.rays, g.hits_a, g.hits_b, g.hit_miss, g.other_triangle, g.t_mismatch);
}

}  // namespace

int main(int argc, char** argv) {
  std::string path;
  int reps = 5;
  unsigned threads = 2;
  bool flat = true;
  MixOptions mix;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "ray_ceiling: %s needs a value\n", arg.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (arg == "--reps")
      reps = std::max(1, std::atoi(value()));
    else if (arg == "--threads")
      threads = static_cast<unsigned>(std::max(1, std::atoi(value())));
    else if (arg == "--no-flat")
      flat = false;
    else if (arg == "--seed")
      mix.seed = static_cast<uint32_t>(std::strtoul(value(), nullptr, 10));
    else if (arg == "-h" || arg == "--help") {
      usage();
      return 0;
    } else if (!arg.empty() && arg[0] != '-' && path.empty())
      path = arg;
    else {
      usage();
      return 2;
    }
  }
  if (path.empty()) {
    usage();
    return 2;
  }
  try {
    glpt::rt::SceneDump dump;
    std::string error;
    if (!glpt::rt::read_scene_dump(path, dump, &error)) {
      std::fprintf(stderr, "ray_ceiling: %s\n", error.c_str());
      return 1;
    }
    const double glpt_mrays = dump.trace_ms > 0 ? dump.rays / dump.trace_ms / 1e3 : 0.0;
    std::printf(
        "[dump] %s: frame %llu, %ux%u, viewport %d,%d %dx%d, %zu shapes, %zu instances, %llu "
        "triangles, %zu lights, spp %u, bounces %u, options 0x%x\n",
        path.c_str(), static_cast<unsigned long long>(dump.frame), dump.width, dump.height,
        dump.viewport[0], dump.viewport[1], dump.viewport[2], dump.viewport[3], dump.shapes.size(),
        dump.instances.size(), static_cast<unsigned long long>(dump.triangle_count()),
        dump.lights.size(), dump.samples, dump.bounces, dump.options);
    std::printf("[glpt] that frame: %llu rays in trace_ms %.2f = %.3f Mrays/s\n",
                static_cast<unsigned long long>(dump.rays), dump.trace_ms, glpt_mrays);
    if (!dump.camera_valid) {
      std::fprintf(stderr, "ray_ceiling: the dump has no main camera\n");
      return 1;
    }
    mix.ao = (dump.options & kOptionAo) != 0;
    mix.bounce = dump.bounces > 0;

    const AccelInput instanced = instanced_input(dump);
    EmbreeTracer embree(threads);
    std::printf("[embree] %s | build %.1f ms\n", embree.description().c_str(),
                embree.build(instanced));
    VkTracer vk;
    std::printf("[vulkan] %s | instanced build (%zu BLAS, %zu instances) %.1f ms\n",
                vk.device_description().c_str(), instanced.shapes.size(),
                instanced.instances.size(), vk.build(instanced));
    AccelInput flat_in;
    std::unique_ptr<VkTracer> vk_flat;
    if (flat) {
      flat_in = flat_input(dump);
      vk_flat = std::make_unique<VkTracer>();
      std::printf("[vulkan] flat build (%zu BLAS, one per mask, Morton-sorted) %.1f ms\n",
                  flat_in.shapes.size(), vk_flat->build(flat_in));
    }

    // ---- the rays: waves generated from Embree's hits, so every tracer traces the same rays
    const Wave primary = primary_rays(dump);
    std::vector<Hit> primary_hits;
    embree.trace(primary.rays, 1, primary_hits);
    std::vector<Kind> kinds;
    const Wave first = first_vertex_rays(dump, primary, primary_hits, instanced, mix, kinds);
    std::vector<Hit> first_hits;
    embree.trace(first.rays, 1, first_hits);
    const Wave second = bounce_vertex_rays(dump, first, kinds, first_hits, instanced, mix);
    std::vector<Ray> secondary = first.rays;
    secondary.insert(secondary.end(), second.rays.begin(), second.rays.end());
    size_t counts[3] = {0, 0, 0};
    for (Kind k : kinds) ++counts[static_cast<uint32_t>(k)];
    size_t primary_hit_count = 0;
    for (const Hit& h : primary_hits) primary_hit_count += h.t >= 0;
    std::printf(
        "[rays] primary %zu (%zu hit) | secondary %zu: %zu shadow + %zu AO + %zu bounce at the "
        "primary hit, %zu shadow at bounce hits | %.2f per hit pixel (glpt's frame: %.2f per hit "
        "pixel, %llu rays)\n",
        primary.rays.size(), primary_hit_count, secondary.size(), counts[0], counts[1], counts[2],
        second.rays.size(),
        primary_hit_count ? static_cast<double>(secondary.size()) / primary_hit_count : 0.0,
        primary_hit_count ? static_cast<double>(dump.rays) / primary_hit_count : 0.0,
        static_cast<unsigned long long>(dump.rays));

    // ---- timed: repetitions interleaved so every tracer sees the same machine load
    std::vector<double> t_vk, t_flat, t_embree, p_vk, p_flat, p_embree;
    std::vector<Hit> h_vk, h_flat, h_embree, ph_vk, ph_flat, ph_embree;
    vk.trace(secondary, 1, h_vk);  // warm-up (first touch of buffers)
    if (vk_flat) vk_flat->trace(secondary, 1, h_flat);
    for (int r = 0; r < reps; ++r) {
      t_vk.push_back(vk.trace(secondary, 1, h_vk).front());
      if (vk_flat) t_flat.push_back(vk_flat->trace(secondary, 1, h_flat).front());
      t_embree.push_back(embree.trace(secondary, 1, h_embree).front());
      p_vk.push_back(vk.trace(primary.rays, 1, ph_vk).front());
      if (vk_flat) p_flat.push_back(vk_flat->trace(primary.rays, 1, ph_flat).front());
      p_embree.push_back(embree.trace(primary.rays, 1, ph_embree).front());
    }
    auto mrays = [](size_t n, double ms) { return ms > 0 ? n / ms / 1e3 : 0.0; };
    const double vk_rate = mrays(secondary.size(), median(t_vk));
    const double flat_rate = vk_flat ? mrays(secondary.size(), median(t_flat)) : 0.0;
    const double embree_rate = mrays(secondary.size(), median(t_embree));
    std::printf(
        "[time] secondary rays, median of %d: ray query (glpt's TLAS) %.2f ms = %.3f "
        "Mrays/s",
        reps, median(t_vk), vk_rate);
    if (vk_flat)
      std::printf(" | ray query (flat) %.2f ms = %.3f Mrays/s", median(t_flat), flat_rate);
    std::printf(" | Embree %.2f ms = %.3f Mrays/s\n", median(t_embree), embree_rate);
    std::printf("[time] primary rays (not in glpt's count): ray query %.3f",
                mrays(primary.rays.size(), median(p_vk)));
    if (vk_flat) std::printf(" | flat %.3f", mrays(primary.rays.size(), median(p_flat)));
    std::printf(" | Embree %.3f Mrays/s\n", mrays(primary.rays.size(), median(p_embree)));
    print_agreement("secondary: ray query vs Embree",
                    compare(secondary, h_vk, instanced, h_embree, instanced));
    if (vk_flat)
      print_agreement("secondary: flat vs Embree",
                      compare(secondary, h_flat, flat_in, h_embree, instanced));
    print_agreement("primary: ray query vs Embree",
                    compare(primary.rays, ph_vk, instanced, ph_embree, instanced));
    std::printf(
        "RESULT glpt_mrays=%.4f rq_mrays=%.4f rq_flat_mrays=%.4f embree_mrays=%.4f "
        "secondary_rays=%zu glpt_rays=%llu hit_pixels=%zu rq_primary_mrays=%.4f "
        "embree_primary_mrays=%.4f triangles=%llu instances=%zu\n",
        glpt_mrays, vk_rate, flat_rate, embree_rate, secondary.size(),
        static_cast<unsigned long long>(dump.rays), primary_hit_count,
        mrays(primary.rays.size(), median(p_vk)), mrays(primary.rays.size(), median(p_embree)),
        static_cast<unsigned long long>(dump.triangle_count()), dump.instances.size());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ray_ceiling: %s\n", e.what());
    return 1;
  }
  return 0;
}
