// GL matrix stacks (GL 1.5 spec 2.11.2): modelview, projection, and one texture stack per unit.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "gl_shim/gl_types.h"
#include "rt_core/record/gl_state.hpp"

namespace glpt {

class MatrixStack {
 public:
  explicit MatrixStack(size_t max_depth) : max_depth_(max_depth) {
    stack_.reserve(max_depth);
    stack_.push_back(glm::mat4(1.0f));
  }
  const glm::mat4& top() const { return stack_.back(); }
  glm::mat4& top() { return stack_.back(); }
  size_t depth() const { return stack_.size(); }
  size_t max_depth() const { return max_depth_; }
  bool push() {
    if (stack_.size() >= max_depth_) return false;
    stack_.push_back(stack_.back());
    return true;
  }
  bool pop() {
    if (stack_.size() <= 1) return false;
    stack_.pop_back();
    return true;
  }

 private:
  size_t max_depth_;
  std::vector<glm::mat4> stack_;
};

struct MatrixState {
  MatrixStack modelview{32};
  MatrixStack projection{4};
  std::array<MatrixStack, rec::kMaxTextureUnits> texture{MatrixStack{4}, MatrixStack{4},
                                                         MatrixStack{4}, MatrixStack{4}};
  GLenum mode = 0x1700;  // GL_MODELVIEW
  // Bumped on every change of the modelview top: geometry batches end where it changes.
  uint64_t modelview_version = 0;
  uint64_t projection_version = 0;

  // The stack glMatrixMode selects; GL_TEXTURE selects the active texture unit's.
  MatrixStack& current(uint32_t active_texture);
  void changed();  // after any edit of current()'s top
};

}  // namespace glpt
