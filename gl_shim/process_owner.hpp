// Which process created an object that holds process-wide resources (an X connection, its
// shared-memory segments, a Vulkan device and its threads). A program that forks a child which
// exits without exec'ing (xscreensaver's image-loading hacks do when xscreensaver-getimage is
// missing) runs glpt's static destructors in the child, on the parent's resources: a request or
// xcb_disconnect's shutdown() of the shared socket would break the parent's connection, and a
// Vulkan teardown would wait for threads that exist only in the parent. Destructors tear down
// only in the process that created the object; a child leaves everything to the kernel.
#pragma once

#include <unistd.h>

namespace glpt {

class ProcessOwner {
 public:
  bool is_this_process() const { return ::getpid() == pid_; }

 private:
  pid_t pid_ = ::getpid();
};

}  // namespace glpt
