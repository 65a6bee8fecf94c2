// What one executed frame record cost, per stage (GLPT_STATS=1 prints it).
#pragma once

#include <array>
#include <cstdint>

namespace glpt::rt {

struct FrameStats {
  // Milliseconds per stage: host work (upload_ms, readback_ms), or the device time of the
  // stage's submissions (timestamps). The passes of a frame overlap host and device work, so
  // their sum is not the frame's wall-clock time.
  double upload_ms = 0, blas_ms = 0, tlas_ms = 0, trace_ms = 0, readback_ms = 0;
  double raster_ms = 0;  // raster pipelines (raster mode, and overlays in path-traced mode)
  // Path-traced mode: the denoiser's passes, and the composite pass (in trace_ms when the
  // denoiser did not run: trace and composite are then one submission).
  double denoise_ms = 0, composite_ms = 0;
  double taa_ms = 0;      // temporal anti-aliasing (TemporalAaPass)
  uint32_t denoised = 0;  // frames (records) whose samples the denoiser filtered
  // The 32x8-pixel tiles it filtered (those with a pixel the tracer shaded: the rest it skips).
  uint32_t denoised_tiles = 0;
  // Host time of classification and identity matching (scene/classify.hpp), when classified.
  double classify_ms = 0;
  // BLASes built, refit in place to a deformed shape (BlasCache), and reused unchanged.
  uint32_t blas_builds = 0, blas_refits = 0, blas_reused = 0;
  // Bytes written into GPU-visible memory: state uniforms, vertices, pixels, textures, BLAS
  // inputs and shading data, instance tables, TLAS instances.
  uint64_t upload_bytes = 0;
  // TLAS builds, and updates in place (the same instances with new transforms).
  uint32_t tlas_builds = 0, tlas_updates = 0;
  // `rays`: rays actually traced this frame (primary + shadow + bounce), counted on the GPU.
  uint64_t triangles = 0, rays = 0;
  // Path samples whose radiance was NaN or infinite: dropped (not averaged in, not shown).
  uint64_t non_finite_samples = 0;
  // Bad input GL accepts and draws nothing of (Mesa alike): primitives dropped for a vertex
  // position that is NaN or infinite, and draws under a modelview-projection with a NaN or an
  // infinity (every clip coordinate of theirs is then non-finite, so clipping drops them all).
  uint64_t non_finite_primitives = 0;
  uint32_t non_finite_draws = 0;
  // Emissive triangles next-event estimation sampled (the frame's emitter table).
  uint32_t emitters = 0;
  // Samples per pixel in the image now shown.
  uint32_t accumulated_samples = 0;
  uint32_t draws = 0;  // Draw commands executed
  // Of those, draws drawn by an earlier draw's Vulkan draw (raster/draw_merging.hpp).
  uint32_t merged_draws = 0;
  // Path-traced mode, per class (docs/classification.md): draws traced (G-buffer and rays), of
  // the sky, and drawn by raster mode only (blended, lines, overlays...); TLAS instances built
  // from them (world and sky).
  uint32_t traced_draws = 0, sky_draws = 0, raster_draws = 0, instances = 0;
  // Draws (and pixel commands) of each DrawKind (scene/classify.hpp), when classified
  // (path-traced mode, or GLPT_CLASSIFY_LOG): indexed by the kind's value.
  std::array<uint32_t, 14> kind_draws{};
  // Draws whose vertices were already on the GPU from an earlier record (resident geometry).
  uint32_t resident_draws = 0;
  uint32_t pipelines_created = 0;  // raster pipelines compiled for this record (0 once warm)
  uint32_t inexpressible = 0;      // commands drawn approximately (state raster cannot express)
  // Runs of draws rasterized upside down as Mesa renders them (raster/mesa_orientation.cpp):
  // each costs two copies of a colour buffer.
  uint32_t upside_down_runs = 0;
  // Times the host waited for the device: 1 per frame (at its end) unless something had to be
  // read back in between (glAccum, occlusion queries) or a resource to be replaced.
  uint32_t host_waits = 0;

  // Adds another record's (or pass's) costs and counts; the samples are the later one's.
  FrameStats& operator+=(const FrameStats& s) {
    upload_ms += s.upload_ms;
    blas_ms += s.blas_ms;
    tlas_ms += s.tlas_ms;
    trace_ms += s.trace_ms;
    readback_ms += s.readback_ms;
    raster_ms += s.raster_ms;
    denoise_ms += s.denoise_ms;
    composite_ms += s.composite_ms;
    taa_ms += s.taa_ms;
    denoised += s.denoised;
    denoised_tiles += s.denoised_tiles;
    classify_ms += s.classify_ms;
    blas_builds += s.blas_builds;
    blas_refits += s.blas_refits;
    blas_reused += s.blas_reused;
    upload_bytes += s.upload_bytes;
    tlas_builds += s.tlas_builds;
    tlas_updates += s.tlas_updates;
    triangles += s.triangles;
    rays += s.rays;
    non_finite_samples += s.non_finite_samples;
    non_finite_primitives += s.non_finite_primitives;
    non_finite_draws += s.non_finite_draws;
    emitters = s.emitters;
    accumulated_samples = s.accumulated_samples;
    draws += s.draws;
    traced_draws += s.traced_draws;
    sky_draws += s.sky_draws;
    raster_draws += s.raster_draws;
    instances += s.instances;
    for (size_t k = 0; k < kind_draws.size(); ++k) kind_draws[k] += s.kind_draws[k];
    resident_draws += s.resident_draws;
    merged_draws += s.merged_draws;
    pipelines_created += s.pipelines_created;
    inexpressible += s.inexpressible;
    upside_down_runs += s.upside_down_runs;
    host_waits += s.host_waits;
    return *this;
  }
};

}  // namespace glpt::rt
