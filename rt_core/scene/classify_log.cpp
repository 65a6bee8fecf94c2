#include "rt_core/scene/classify_log.hpp"

#include <cerrno>
#include <cinttypes>
#include <cstring>

namespace glpt::rt {

ClassifyLog::ClassifyLog(const std::string& path, std::string* error) {
  file_.reset(std::fopen(path.c_str(), "a"));
  if (!file_ && error != nullptr)
    *error = "GLPT_CLASSIFY_LOG: cannot open " + path + ": " + std::strerror(errno);
}

void ClassifyLog::write(const FrameClassification& classification) {
  if (!file_) return;
  for (const CommandLabel& label : classification.labels) {
    if (label.kind == DrawKind::kNone || label.calls == 0) continue;
    std::fprintf(file_.get(),
                 "{\"frame\": %" PRIu64 ", \"class\": \"%s\", \"calls\": %" PRIu32
                 ", \"id\": %" PRIu64 "}\n",
                 frame_, draw_kind_name(label.kind), label.calls, label.id);
  }
}

void ClassifyLog::end_frame() {
  ++frame_;
  if (file_) std::fflush(file_.get());
}

}  // namespace glpt::rt
