#include "replay/frame_selection.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>

namespace glpt::replay {
namespace {

bool parse_number(std::string_view text, uint64_t* value) {
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), *value);
  return ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

bool FrameSelection::parse_frames(const std::string& text, std::string* error) {
  ranges_.clear();
  std::string_view rest(text);
  while (true) {
    const size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    const size_t dash = item.find('-');
    uint64_t first = 0, last = 0;
    const bool ok = dash == std::string_view::npos
                        ? parse_number(item, &first) && ((last = first), true)
                        : parse_number(item.substr(0, dash), &first) &&
                              parse_number(item.substr(dash + 1), &last) && first <= last;
    if (!ok) {
      *error = "--frames: bad item \"" + std::string(item) +
               "\" (want frame numbers and ranges from 0, e.g. 10,20-30)";
      return false;
    }
    ranges_.emplace_back(first, last);
    if (comma == std::string_view::npos) return true;
    rest.remove_prefix(comma + 1);
  }
}

bool FrameSelection::parse_shard(const std::string& text, std::string* error) {
  const size_t slash = text.find('/');
  uint64_t index = 0, count = 0;
  if (slash == std::string::npos ||
      !parse_number(std::string_view(text).substr(0, slash), &index) ||
      !parse_number(std::string_view(text).substr(slash + 1), &count) || count == 0 ||
      count > 1000000 || index >= count) {
    *error = "--shard: want I/N with 0 <= I < N (e.g. 0/4), got \"" + text + "\"";
    return false;
  }
  shard_index_ = static_cast<uint32_t>(index);
  shard_count_ = static_cast<uint32_t>(count);
  return true;
}

bool FrameSelection::chosen(uint64_t frame) const {
  if (frame % every_ != 0) return false;
  if (ranges_.empty()) return true;
  for (const auto& [first, last] : ranges_)
    if (frame >= first && frame <= last) return true;
  return false;
}

bool FrameSelection::rendered(uint64_t frame) const {
  const uint64_t window_end = (frame / history_window_ + 1) * history_window_;  // exclusive
  for (uint64_t f = frame; f < window_end; ++f)
    if (written(f)) return true;
  return false;
}

uint64_t FrameSelection::last_chosen() const {
  if (ranges_.empty()) return UINT64_MAX;
  uint64_t last = 0;
  for (const auto& range : ranges_) last = std::max(last, range.second);
  return last;
}

}  // namespace glpt::replay
