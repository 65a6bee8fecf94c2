/* A shared library that loads and does nothing: what the command-line tests preload where they
   only check what `glpt run` passes on (glpt run refuses a library that cannot be loaded). */
int glpt_fake_preload_marker(void);
int glpt_fake_preload_marker(void) { return 1; }
