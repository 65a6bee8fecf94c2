#include "rt_core/scene/classify_log.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <cstring>

namespace glpt::rt {

ClassifyLog::ClassifyLog(const std::string& path, std::string* error) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0 && error != nullptr)
    *error = "GLPT_CLASSIFY_LOG: cannot open " + path + ": " + std::strerror(errno);
}

ClassifyLog::~ClassifyLog() {
  if (fd_ >= 0) ::close(fd_);
}

void ClassifyLog::write(const FrameClassification& classification) {
  if (fd_ < 0) return;
  text_.clear();
  char line[160];
  for (size_t i = 0; i < classification.labels.size(); ++i) {
    const CommandLabel& label = classification.labels[i];
    if (label.kind == DrawKind::kNone || label.calls == 0) continue;
    // A blended draw traced where its fragments are opaque says so (DrawClass::kSplitByAlpha).
    const bool split =
        i < classification.classes.size() && classification.classes[i] == DrawClass::kSplitByAlpha;
    const int n = std::snprintf(line, sizeof line,
                                "{\"frame\": %" PRIu64 ", \"class\": \"%s\", \"calls\": %" PRIu32
                                ", \"id\": %" PRIu64 "%s}\n",
                                frame_, draw_kind_name(label.kind), label.calls, label.id,
                                split ? ", \"split_by_alpha\": true" : "");
    if (n > 0) text_.append(line, static_cast<size_t>(n));
  }
  // One write per record, straight to the file: a program killed at any moment (SIGTERM ends
  // most screen hacks) leaves whole lines, never half of one sitting in a stdio buffer.
  size_t done = 0;
  while (done < text_.size()) {
    const ssize_t written = ::write(fd_, text_.data() + done, text_.size() - done);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) break;  // a full disk: the log ends there, drawing goes on
    done += static_cast<size_t>(written);
  }
}

void ClassifyLog::end_frame() { ++frame_; }

}  // namespace glpt::rt
