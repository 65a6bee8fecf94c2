// GL matrix stacks (GL 1.5 spec 2.11.2): modelview, projection, and one texture stack per unit.
// Each entry is a MesaMatrix: values, inverses and the moments they are derived are Mesa's.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "gl_shim/gl_types.h"
#include "gl_shim/state/mesa_matrix.hpp"
#include "rt_core/record/gl_state.hpp"

namespace glpt {

class MatrixStack {
 public:
  explicit MatrixStack(size_t max_depth) : max_depth_(max_depth) {
    stack_.reserve(max_depth);
    stack_.emplace_back();
  }
  const glm::mat4& top() const { return stack_.back().matrix(); }
  const MesaMatrix& top_matrix() const { return stack_.back(); }
  MesaMatrix& top_matrix() { return stack_.back(); }
  size_t depth() const { return stack_.size(); }
  size_t max_depth() const { return max_depth_; }
  // Mesa analyses the matrix being pushed, so both copies carry its type and inverse.
  bool push() {
    if (stack_.size() >= max_depth_) return false;
    stack_.back().analyse();
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
  std::vector<MesaMatrix> stack_;
};

// Stack depths as Mesa reports them (GL_MAX_*_STACK_DEPTH; the spec's minimums are 32, 2, 2).
inline constexpr size_t kMaxModelviewStackDepth = 32;
inline constexpr size_t kMaxProjectionStackDepth = 32;
inline constexpr size_t kMaxTextureStackDepth = 10;

struct MatrixState {
  MatrixStack modelview{kMaxModelviewStackDepth};
  MatrixStack projection{kMaxProjectionStackDepth};
  std::array<MatrixStack, rec::kMaxTextureUnits> texture{
      MatrixStack{kMaxTextureStackDepth}, MatrixStack{kMaxTextureStackDepth},
      MatrixStack{kMaxTextureStackDepth}, MatrixStack{kMaxTextureStackDepth}};
  GLenum mode = 0x1700;  // GL_MODELVIEW
  // Bumped on every change of the modelview top: geometry batches end where it changes.
  uint64_t modelview_version = 0;
  uint64_t projection_version = 0;

  // The stack glMatrixMode selects; GL_TEXTURE selects the active texture unit's.
  MatrixStack& current(uint32_t active_texture);
  void changed();  // after any edit of current()'s top

  // What Mesa does to the matrices when a draw validates state (_mesa_update_state): analyses
  // the modelview and texture matrices, and the projection matrix if a clip plane is enabled.
  // Analysis decides how later products and inverses are computed, so every command that
  // validates state in Mesa must call this: glBegin, glDrawArrays/Elements/RangeElements,
  // glMultiDraw*, glRasterPos*, glBitmap, glDrawPixels, glCopyPixels, glReadPixels.
  void validate_for_draw(uint8_t clip_plane_mask);

  // The combined projection * modelview matrix the way Mesa computes it at validation
  // (_mesa_update_modelview_project): call after validate_for_draw.
  glm::mat4 model_projection() const;
};

}  // namespace glpt
