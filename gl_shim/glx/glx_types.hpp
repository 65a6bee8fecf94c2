// GLX handle types as the GLX ABI defines them (matching Mesa's <GL/glx.h>), without pulling in
// the system GL headers, whose prototypes would collide with glpt's own entry points.
#pragma once

#include <X11/Xlib.h>
#include <X11/Xutil.h>

typedef struct __GLXcontextRec* GLXContext;
typedef struct __GLXFBConfigRec* GLXFBConfig;
typedef XID GLXDrawable;
typedef XID GLXWindow;
typedef XID GLXPixmap;
typedef XID GLXPbuffer;
typedef XID GLXContextID;
typedef void (*__GLXextFuncPtr)(void);
