/* x_send_key [NAME [KEYSYM]]
 *
 * Finds the first window on $DISPLAY whose WM_NAME contains NAME (default "glxgears"), searching
 * the root's children and, for window managers that reparent, their descendants, and sends it a
 * KeyPress and a KeyRelease of KEYSYM (an X keysym name, default "Escape") with XSendEvent.
 * Exit status: 0 sent, 1 no such window, 2 usage or display error.
 */
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <string.h>

static Window find_window(Display* dpy, Window w, const char* name, int depth) {
  char* wm_name = NULL;
  if (XFetchName(dpy, w, &wm_name) && wm_name) {
    const int match = strstr(wm_name, name) != NULL;
    XFree(wm_name);
    if (match) return w;
  }
  if (depth == 0) return None;
  Window root_ret, parent_ret, *children = NULL;
  unsigned int n = 0;
  Window found = None;
  if (XQueryTree(dpy, w, &root_ret, &parent_ret, &children, &n)) {
    /* Topmost first: the last child is on top of the stacking order. */
    for (unsigned int i = n; i-- > 0 && found == None;) {
      found = find_window(dpy, children[i], name, depth - 1);
    }
    if (children) XFree(children);
  }
  return found;
}

int main(int argc, char** argv) {
  if (argc > 3 || (argc > 1 && (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")))) {
    fprintf(stderr, "usage: x_send_key [WM_NAME-substring (glxgears) [KEYSYM (Escape)]]\n");
    return 2;
  }
  const char* name = argc > 1 ? argv[1] : "glxgears";
  const char* key = argc > 2 ? argv[2] : "Escape";

  const KeySym keysym = XStringToKeysym(key);
  if (keysym == NoSymbol) {
    fprintf(stderr, "x_send_key: unknown keysym '%s'\n", key);
    return 2;
  }
  Display* dpy = XOpenDisplay(NULL);
  if (!dpy) {
    fprintf(stderr, "x_send_key: cannot open display '%s'\n", XDisplayName(NULL));
    return 2;
  }
  const KeyCode keycode = XKeysymToKeycode(dpy, keysym);
  if (keycode == 0) {
    fprintf(stderr, "x_send_key: keysym '%s' has no keycode on this display\n", key);
    XCloseDisplay(dpy);
    return 2;
  }
  const Window root = DefaultRootWindow(dpy);
  /* depth 3: root -> WM frame -> (WM decoration) -> client window */
  const Window win = find_window(dpy, root, name, 3);
  if (win == None) {
    fprintf(stderr, "x_send_key: no window whose WM_NAME contains '%s' on %s\n", name,
            DisplayString(dpy));
    XCloseDisplay(dpy);
    return 1;
  }

  XKeyEvent ev;
  memset(&ev, 0, sizeof ev);
  ev.display = dpy;
  ev.window = win;
  ev.root = root;
  ev.subwindow = None;
  ev.time = CurrentTime;
  ev.x = ev.y = ev.x_root = ev.y_root = 1;
  ev.same_screen = True;
  ev.keycode = keycode;
  ev.state = 0;
  ev.type = KeyPress;
  Status ok = XSendEvent(dpy, win, True, KeyPressMask, (XEvent*)&ev);
  ev.type = KeyRelease;
  ok = ok && XSendEvent(dpy, win, True, KeyReleaseMask, (XEvent*)&ev);
  XSync(dpy, False);
  XCloseDisplay(dpy);
  if (!ok) {
    fprintf(stderr, "x_send_key: XSendEvent failed\n");
    return 2;
  }
  printf("x_send_key: sent %s to window 0x%lx\n", key, (unsigned long)win);
  return 0;
}
