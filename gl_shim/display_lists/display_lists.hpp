// Display list names and contents (GL 1.5 spec 5.4). Shared between contexts created with a
// share_list, hence held through a shared_ptr by each Context.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <unordered_map>

#include "gl_shim/display_lists/list_stream.hpp"
#include "gl_shim/gl_types.h"

namespace glpt {

struct DisplayListStore {
  struct Entry {
    // Immutable once defined, and held by each glCallList running it: a context of the share
    // group on another thread may redefine or delete the list meanwhile.
    std::shared_ptr<const ListStream> stream;
    bool defined = false;  // glGenLists reserves names; glEndList defines them
  };
  // Guards `lists`: contexts of a share group may be current on several threads (GL leaves the
  // order of their changes to the program, but they must never corrupt the store).
  std::mutex mutex;
  std::unordered_map<GLuint, Entry> lists;
};

struct DisplayListState {
  std::shared_ptr<DisplayListStore> store = std::make_shared<DisplayListStore>();
  // While compiling: the name, the mode, and the stream being filled (committed at glEndList,
  // so a list calling itself while being redefined still sees its old contents).
  GLuint compiling_name = 0;
  GLenum compiling_mode = 0;
  ListStream pending;
  GLuint list_base = 0;
  int call_depth = 0;  // nesting of glCallList, limited to GL_MAX_LIST_NESTING
  static constexpr int kMaxNesting = 64;

  bool compiling() const { return compiling_name != 0; }
};

}  // namespace glpt
