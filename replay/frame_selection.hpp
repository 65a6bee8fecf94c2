// Which frames glpt-replay renders and writes: --frames, --every and --shard.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace glpt::replay {

class FrameSelection {
 public:
  // "10,20-30": frame indices and inclusive ranges, from 0. False + message if malformed.
  bool parse_frames(const std::string& text, std::string* error);
  // "I/N" with 0 <= I < N.
  bool parse_shard(const std::string& text, std::string* error);
  void set_every(uint64_t every) { every_ = every; }
  // --history W: frames build on the history of the frames before them in their window of W
  // (frames 0..W-1, W..2W-1, ...; rt::Renderer::start_independent_frame); 1: none.
  void set_history_window(uint32_t frames) { history_window_ = frames == 0 ? 1 : frames; }
  uint32_t history_window() const { return history_window_; }

  // Chosen by --frames and --every (all frames by default).
  bool chosen(uint64_t frame) const;
  // Written by this shard: a chosen frame whose window w (frame / W) has w % N == I: shards take
  // whole windows, so none renders another's frames for their history.
  bool written(uint64_t frame) const {
    return chosen(frame) && (frame / history_window_) % shard_count_ == shard_index_;
  }
  // Rendered by this shard: written, or before a written frame in its window (its history). The
  // other frames replay their state only.
  bool rendered(uint64_t frame) const;
  // No frame after this one is chosen (the replay can stop); UINT64_MAX without --frames.
  uint64_t last_chosen() const;

  uint32_t shard_index() const { return shard_index_; }
  uint32_t shard_count() const { return shard_count_; }

 private:
  std::vector<std::pair<uint64_t, uint64_t>> ranges_;  // inclusive; empty: all frames
  uint64_t every_ = 1;
  uint32_t shard_index_ = 0, shard_count_ = 1;
  uint32_t history_window_ = 1;
};

}  // namespace glpt::replay
