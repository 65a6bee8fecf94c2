// The GLX entry points libGL.so.1 exports (GLX 1.4, GLX_ARB_create_context,
// GLX_ARB_get_proc_address), declared once so every definition is checked against them.
#pragma once

#include "gl_shim/gl_types.h"
#include "gl_shim/glx/glx_types.hpp"

extern "C" {

GLPT_EXPORT XVisualInfo* glXChooseVisual(Display* dpy, int screen, int* attrib_list);
GLPT_EXPORT int glXGetConfig(Display* dpy, XVisualInfo* vis, int attrib, int* value);
GLPT_EXPORT GLXFBConfig* glXGetFBConfigs(Display* dpy, int screen, int* nelements);
GLPT_EXPORT GLXFBConfig* glXChooseFBConfig(Display* dpy, int screen, const int* attrib_list,
                                           int* nelements);
GLPT_EXPORT int glXGetFBConfigAttrib(Display* dpy, GLXFBConfig config, int attribute, int* value);
GLPT_EXPORT XVisualInfo* glXGetVisualFromFBConfig(Display* dpy, GLXFBConfig config);
GLPT_EXPORT GLXContext glXCreateContext(Display* dpy, XVisualInfo* vis, GLXContext share_list,
                                        Bool direct);
GLPT_EXPORT GLXContext glXCreateNewContext(Display* dpy, GLXFBConfig config, int render_type,
                                           GLXContext share_list, Bool direct);
GLPT_EXPORT GLXContext glXCreateContextAttribsARB(Display* dpy, GLXFBConfig config,
                                                  GLXContext share_context, Bool direct,
                                                  const int* attrib_list);
GLPT_EXPORT void glXDestroyContext(Display* dpy, GLXContext ctx);
GLPT_EXPORT Bool glXMakeCurrent(Display* dpy, GLXDrawable drawable, GLXContext ctx);
GLPT_EXPORT Bool glXMakeContextCurrent(Display* dpy, GLXDrawable draw, GLXDrawable read,
                                       GLXContext ctx);
GLPT_EXPORT void glXSwapBuffers(Display* dpy, GLXDrawable drawable);
GLPT_EXPORT const char* glXQueryExtensionsString(Display* dpy, int screen);
GLPT_EXPORT const char* glXGetClientString(Display* dpy, int name);
GLPT_EXPORT const char* glXQueryServerString(Display* dpy, int screen, int name);
GLPT_EXPORT Bool glXQueryExtension(Display* dpy, int* error_base, int* event_base);
GLPT_EXPORT Bool glXQueryVersion(Display* dpy, int* major, int* minor);
GLPT_EXPORT Bool glXIsDirect(Display* dpy, GLXContext ctx);
GLPT_EXPORT GLXContext glXGetCurrentContext(void);
GLPT_EXPORT GLXDrawable glXGetCurrentDrawable(void);
GLPT_EXPORT GLXDrawable glXGetCurrentReadDrawable(void);
GLPT_EXPORT Display* glXGetCurrentDisplay(void);
GLPT_EXPORT int glXQueryContext(Display* dpy, GLXContext ctx, int attribute, int* value);
GLPT_EXPORT GLXWindow glXCreateWindow(Display* dpy, GLXFBConfig config, Window win,
                                      const int* attrib_list);
GLPT_EXPORT void glXDestroyWindow(Display* dpy, GLXWindow win);
GLPT_EXPORT GLXPixmap glXCreatePixmap(Display* dpy, GLXFBConfig config, Pixmap pixmap,
                                      const int* attrib_list);
GLPT_EXPORT void glXDestroyPixmap(Display* dpy, GLXPixmap pixmap);
GLPT_EXPORT GLXPixmap glXCreateGLXPixmap(Display* dpy, XVisualInfo* vis, Pixmap pixmap);
GLPT_EXPORT void glXDestroyGLXPixmap(Display* dpy, GLXPixmap pixmap);
GLPT_EXPORT void glXQueryDrawable(Display* dpy, GLXDrawable draw, int attribute,
                                  unsigned int* value);
GLPT_EXPORT void glXWaitGL(void);
GLPT_EXPORT void glXWaitX(void);
GLPT_EXPORT Bool glXMakeCurrentReadSGI(Display* dpy, GLXDrawable draw, GLXDrawable read,
                                       GLXContext ctx);
GLPT_EXPORT GLXDrawable glXGetCurrentReadDrawableSGI(void);
GLPT_EXPORT GLXPbuffer glXCreatePbuffer(Display* dpy, GLXFBConfig config, const int* attrib_list);
GLPT_EXPORT void glXDestroyPbuffer(Display* dpy, GLXPbuffer pbuf);
GLPT_EXPORT void glXSelectEvent(Display* dpy, GLXDrawable draw, unsigned long event_mask);
GLPT_EXPORT void glXGetSelectedEvent(Display* dpy, GLXDrawable draw, unsigned long* event_mask);
GLPT_EXPORT void glXCopyContext(Display* dpy, GLXContext src, GLXContext dst, unsigned long mask);
GLPT_EXPORT void glXUseXFont(Font font, int first, int count, int list_base);
GLPT_EXPORT void glXSwapIntervalEXT(Display* dpy, GLXDrawable drawable, int interval);
GLPT_EXPORT int glXSwapIntervalMESA(unsigned int interval);
GLPT_EXPORT int glXGetSwapIntervalMESA(void);
GLPT_EXPORT int glXSwapIntervalSGI(int interval);
GLPT_EXPORT __GLXextFuncPtr glXGetProcAddressARB(const GLubyte* name);
GLPT_EXPORT __GLXextFuncPtr glXGetProcAddress(const GLubyte* name);

}  // extern "C"
