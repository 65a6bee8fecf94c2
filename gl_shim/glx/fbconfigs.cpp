#include "gl_shim/glx/fbconfigs.hpp"

namespace glpt::glx {

std::vector<FBConfig> configs_of_screen(Display* dpy, int screen) {
  std::vector<FBConfig> out;
  XVisualInfo templ{};
  templ.screen = screen;
  templ.c_class = TrueColor;
  int n = 0;
  XVisualInfo* vi = XGetVisualInfo(dpy, VisualScreenMask | VisualClassMask, &templ, &n);
  if (vi == nullptr) return out;
  // Double-buffered configs first: that is what GL programs want.
  for (bool db : {true, false})
    for (bool alpha : {true, false})
      for (int i = 0; i < n; ++i)
        if (vi[i].depth == 24 || (vi[i].depth == 32 && alpha))
          out.push_back(FBConfig{vi[i].visualid, screen, vi[i].depth, db, alpha});
  XFree(vi);
  return out;
}

}  // namespace glpt::glx
