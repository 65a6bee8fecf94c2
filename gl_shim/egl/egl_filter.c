/* libEGL.so.1 is a filter on libGL.so.1 (see gl_shim/CMakeLists.txt): it defines no symbols of
   its own; every EGL entry point is libGL.so.1's (gl_shim/egl/egl.cpp). */
typedef int glpt_egl_filter_has_no_definitions;
