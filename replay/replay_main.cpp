// glpt-replay: replays an apitrace trace headless into glpt (or real Mesa) and writes PNGs.
// See README.md and `glpt-replay --help`.
#include <unistd.h>

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "common/image_io.hpp"
#include "common/stopwatch.hpp"
#include "replay/backend.hpp"
#include "replay/command_line.hpp"
#include "replay/replayer.hpp"
#include "replay/trace/trace_reader.hpp"
#if GLPT_REPLAY_WINDOW
#include "replay/window_view.hpp"
#endif

namespace glpt::replay {
namespace {

// The progress line on long replays: at most every this many milliseconds.
constexpr double kProgressIntervalMs = 2000;

void print_summary(const ReplayCounts& counts, const Backend& backend, double seconds) {
  std::fprintf(stderr,
               "glpt-replay: %" PRIu64 " calls, %" PRIu64 " frames, %" PRIu64
               " rendered, in %.2f s (backend %s)\n",
               counts.calls, counts.frames, counts.frames_rendered, seconds, backend.name());
  const auto unimplemented = backend.unimplemented_calls();
  uint64_t total = 0;
  for (const auto& [name, n] : unimplemented) total += n;
  if (total > 0) {
    std::fprintf(stderr, "glpt-replay: %" PRIu64 " calls to commands %s does not implement:\n",
                 total, backend.name());
    for (const auto& [name, n] : unimplemented)
      std::fprintf(stderr, "  %-40s %" PRIu64 "\n", name.c_str(), n);
  }
  if (!counts.unknown.empty()) {
    std::fprintf(stderr, "glpt-replay: calls the replayer does not know (not replayed):\n");
    for (const auto& [name, n] : counts.unknown)
      std::fprintf(stderr, "  %-40s %" PRIu64 "\n", name.c_str(), n);
  }
  if (!counts.unresolved.empty()) {
    std::fprintf(stderr, "glpt-replay: commands backend %s has no entry point for:\n",
                 backend.name());
    for (const auto& [name, n] : counts.unresolved)
      std::fprintf(stderr, "  %-40s %" PRIu64 "\n", name.c_str(), n);
  }
  if (counts.without_context > 0)
    std::fprintf(stderr, "glpt-replay: %" PRIu64 " GL calls without a current context skipped\n",
                 counts.without_context);
  if (counts.memcpy_outside_mappings > 0)
    std::fprintf(stderr,
                 "glpt-replay: %" PRIu64 " memcpy calls outside any mapped buffer skipped\n",
                 counts.memcpy_outside_mappings);
}

#if GLPT_REPLAY_WINDOW
std::unique_ptr<WindowView> open_window(std::string* error) { return WindowView::create(error); }
#else
// Built without GLFW (Debian: libglfw3-dev).
class WindowView {
 public:
  bool show(const FrameImage&, uint64_t, std::string*) { return true; }
  void pause() {}
};
std::unique_ptr<WindowView> open_window(std::string* error) {
  *error = "--window: this build has no GLFW (install libglfw3-dev and rebuild)";
  return nullptr;
}
#endif

int run(Options options) {
  // The quality flags reach glpt's renderer as its environment variables. Replay does not
  // accumulate samples across frames (a frame's history is the denoiser's, within its window;
  // see --help) unless GLPT_ACCUMULATE=1 is set: then unchanged frames accumulate within their
  // window, which shards reproduce as they do the denoiser's history (glpt tune's accumulation
  // points). It writes the PNGs itself, so glpt's own GLPT_OUTPUT stays off.
  for (const auto& [variable, value] : options.environment)
    setenv(variable.c_str(), value.c_str(), 1);
  setenv("GLPT_ACCUMULATE", "0", /*overwrite=*/0);
  unsetenv("GLPT_OUTPUT");
  const uint32_t history_window = history_window_of(options, std::getenv("GLPT_MODE"));
  options.frames.set_history_window(history_window);

  std::string error;
  std::unique_ptr<trace::TraceReader> reader = trace::TraceReader::open(options.trace, error);
  if (!reader) {
    std::fprintf(stderr, "glpt-replay: %s\n", error.c_str());  // the reader names the file
    return kExitBadTrace;
  }
  if (!options.out_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(options.out_dir, ec);
    if (ec) {
      std::fprintf(stderr, "glpt-replay: cannot create %s: %s\n", options.out_dir.c_str(),
                   ec.message().c_str());
      return kExitReplayFailed;
    }
  }
  std::unique_ptr<WindowView> view;
  if (options.window && !(view = open_window(&error))) {
    std::fprintf(stderr, "glpt-replay: %s\n", error.c_str());
    return kExitReplayFailed;
  }
  if (view && options.paused) view->pause();
  std::unique_ptr<Backend> backend =
      options.backend == "mesa" ? create_mesa_backend(&error) : create_glpt_backend(&error);
  if (!backend) {
    std::fprintf(stderr, "glpt-replay: %s\n", error.c_str());
    return kExitReplayFailed;
  }
  backend->set_history_window(history_window);

  const Stopwatch total;
  Stopwatch since_frame, since_progress;
  bool progress_shown = false;
  bool user_quit = false;  // --window: q, Esc or closing the window
  const bool tty = isatty(STDERR_FILENO) != 0;
  auto frame_done = [&](uint64_t frame, const FrameImage& image, std::string* err) {
    const double frame_ms = since_frame.elapsed_ms();
    since_frame.restart();
    std::string path;
    if (!options.out_dir.empty()) {
      char name[64];
      std::snprintf(name, sizeof name, "/frame_%06" PRIu64 ".png", frame);
      path = options.out_dir + name;
      if (!write_png_rgba8(path, image.width, image.height, image.rgba.data(), true, err))
        return false;
    }
    if (view && !view->show(image, frame, err)) {
      user_quit = err->empty();
      return false;
    }
    if (!options.quiet) {
      if (progress_shown && tty) std::fprintf(stderr, "\r\033[K");
      progress_shown = false;
      std::printf("frame %6" PRIu64 "  %ux%u  %8.2f ms  (render %.2f ms)%s%s\n", frame, image.width,
                  image.height, frame_ms, backend->last_render_ms(), path.empty() ? "" : "  ",
                  path.c_str());
      std::fflush(stdout);
    }
    return true;
  };
  Replayer replayer(
      *backend, [&](uint64_t f) { return options.frames.rendered(f); }, frame_done,
      [&](uint64_t f) { return options.frames.written(f); });

  trace::Call call;
  int status = kExitOk;
  uint32_t passes_left = options.repeat - 1;
  while (true) {
    const trace::TraceReader::Status s = reader->next(call, error);
    if (s == trace::TraceReader::Status::End && passes_left > 0) {
      --passes_left;
      replayer.forget_signatures();  // they die with the reader being replaced
      reader.reset();
      if (!(reader = trace::TraceReader::open(options.trace, error))) {
        std::fprintf(stderr, "glpt-replay: %s\n", error.c_str());
        status = kExitBadTrace;
        break;
      }
      continue;
    }
    if (s == trace::TraceReader::Status::End) break;
    if (s == trace::TraceReader::Status::Error) {
      std::fprintf(stderr, "glpt-replay: %s\n", error.c_str());  // the reader names the file
      status = kExitBadTrace;
      break;
    }
    if (!replayer.replay(call, &error)) {
      if (user_quit) break;
      std::fprintf(stderr, "glpt-replay: %s\n", error.c_str());
      status = kExitReplayFailed;
      break;
    }
    const ReplayCounts& counts = replayer.counts();
    if (counts.frames > options.frames.last_chosen()) break;  // nothing chosen after this
    if (!options.quiet && (counts.calls & 1023) == 0 &&
        since_progress.elapsed_ms() > kProgressIntervalMs) {
      since_progress.restart();
      std::fprintf(stderr, "%sglpt-replay: %" PRIu64 " calls, frame %" PRIu64 ", %.1f s%s",
                   tty ? "\r\033[K" : "", counts.calls, counts.frames, total.elapsed_ms() / 1000,
                   tty ? "" : "\n");
      progress_shown = tty;
    }
  }
  if (progress_shown) std::fprintf(stderr, "\r\033[K");
  print_summary(replayer.counts(), *backend, total.elapsed_ms() / 1000);
  return status;
}

}  // namespace
}  // namespace glpt::replay

int main(int argc, char** argv) {
  using namespace glpt::replay;
  Options options;
  std::string error;
  if (!parse_command_line(argc, argv, &options, &error)) {
    std::fprintf(stderr, "glpt-replay: %s\n%s", error.c_str(), usage().c_str());
    return kExitUsage;
  }
  if (options.help) {
    std::fputs(usage().c_str(), stdout);
    return kExitOk;
  }
  try {
    return run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "glpt-replay: %s\n", e.what());
  }
  return kExitReplayFailed;
}
