#!/usr/bin/env python3
"""Runs piglit's OpenGL 1.0-1.5 tests on real Mesa and on glpt's raster mode, and writes the
results as a Markdown table (docs/piglit.md by default).

    scripts/piglit_gl1.py [--libgl build/gl_shim/libGL.so.1] [--filter REGEX] [--jobs 2]
                          [--timeout 120] [--out docs/piglit.md] [--groups REGEX]

The tests are those of Debian's piglit package (`piglit print-cmd opengl`) in the groups
"spec@!opengl 1.0" .. "spec@!opengl 1.5" (piglit's tests/spec/gl-1.* and the older general/
tests that need only GL 1.x); `--groups '^glx@'` runs piglit's GLX tests instead (contexts,
drawables, several contexts and threads: docs/piglit-glx.md). Each runs on the window (without piglit's -fbo: glpt implements
GL 1.5, which has no framebuffer objects), in one private Xvfb (tests/e2e/with_xvfb.sh), once
with the system libGL (Mesa llvmpipe) and once with glpt preloaded (GLPT_MODE=raster). A test's
result is its last `PIGLIT: {"result": ...}` line; no line is "crash", a timeout "timeout".
Not part of CI: it takes minutes. The command line that produced a results file is in it.
"""

import argparse
import concurrent.futures
import json
import os
import re
import shlex
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GL1_GROUPS = r"^spec@!opengl 1\.[0-5]@"
# piglit's groups for the extensions glpt advertises beyond GL 1.5's core (`--groups extensions`,
# docs/piglit-extensions.md).
EXTENSION_GROUPS = (r"^spec@((arb_point_sprite|arb_point_parameters|ext_stencil_wrap|"
                    r"ext_texture_lod_bias|ext_packed_depth_stencil|arb_texture_env_crossbar|"
                    r"arb_texture_env_combine|ext_texture_env_combine|ext_blend_func_separate|"
                    r"ext_fog_coord|ext_secondary_color|arb_window_pos|arb_transpose_matrix|"
                    r"arb_multitexture|ext_texture_rectangle|arb_texture_rectangle|"
                    r"arb_texture_border_clamp|arb_texture_mirrored_repeat|arb_depth_texture|"
                    r"arb_shadow|arb_texture_cube_map|ext_blend_minmax|ext_blend_subtract|"
                    r"ext_blend_color|arb_occlusion_query|arb_vertex_buffer_object|"
                    r"ext_compiled_vertex_array|ext_draw_range_elements|ext_multi_draw_arrays|"
                    r"arb_texture_compression|ext_texture_compression_s3tc|ext_framebuffer_object|"
                    r"ext_framebuffer_blit)@|"
                    # ARB_texture_non_power_of_two has no group of its own.
                    r"!opengl 2\.0@tex3d-npot$)")


def list_tests(groups, pattern):
    out = subprocess.run(["piglit", "print-cmd", "opengl"], capture_output=True, text=True,
                         check=True).stdout
    tests = []
    for line in out.splitlines():
        if " ::: " not in line:
            continue
        name, command = line.split(" ::: ", 1)
        if not re.search(groups, name) or (pattern and not re.search(pattern, name)):
            continue
        argv = [a for a in shlex.split(command) if a != "-fbo"]
        tests.append((name, argv))
    return tests


# Why a test skipped, from its output: the requirement it names.
SKIP_REASON = re.compile(r"(Test requires GL version [0-9.]+|Test requires \S+|requires either .*|"
                         r"Requested a OpenGL [0-9.]+|GLSL not supported|GLSL .* not supported|Function \"\w+\" not supported|\S.* is required for .*)")
# Why glpt does not pass a test Mesa passes, where that is understood (measured; shown in the
# note column when the test does not pass). Remove a line when its test passes.
KNOWN_DIFFERENCES = {
    "spec@!opengl 1.1@linestipple":
        "Line loop: 7 pixels of a line going down exactly through pixel centres; llvmpipe "
        "draws GL windows with y flipped and breaks such ties by its bottom-edge rule, lavapipe "
        "un-flipped starts the line one pixel lower, shifting the stipple (tests/conformance "
        "scene lines_stipple_piglit)",
    "spec@!opengl 1.0@gl-1.0-blend-func":
        "passes, in 301 s against Mesa's 10 s (measured alone): each of its blend states is a new "
        "Vulkan pipeline, and lavapipe compiles the whole pipeline where llvmpipe recompiles "
        "only a fragment variant; blend state as dynamic state (EXT_extended_dynamic_state3) "
        "would remove the compiles",
    "spec@arb_texture_cube_map@getteximage-targets cube":
        "needs pixel buffer objects (GL 2.1) without asking for them: it binds "
        "GL_PIXEL_PACK_BUFFER (GL_INVALID_ENUM on GL 1.5) and passes glGetTexImage the buffer "
        "offsets 0, 4096, ... as pointers, which a GL without PBOs writes to as client memory",
    "spec@ext_texture_compression_s3tc@getteximage-targets cube s3tc":
        "the same test as arb_texture_cube_map's getteximage-targets cube with DXT5 images: "
        "needs pixel buffer objects (GL 2.1) without asking for them",
}

BEYOND_GL15 = re.compile(r"OpenGL [2-9]|GL version [2-9]|GLSL|requires (GL_\w+)|Function|"
                         r"requires (GLX_\w+)")
# Tests that skip on glpt without naming their requirement in a way BEYOND_GL15 reads, but that
# need more than GL 1.5 and GLX 1.4 (read in piglit's sources): shown as beyond, with the reason.
BEYOND_BY_SOURCE = {
    "glx@glx-shader-sharing": "needs GL 2.0: shares GLSL programs between contexts",
    "glx@glx_arb_create_context@current with no framebuffer":
        "needs a GL 3.0 context (made current without a drawable)",
    "glx@glx_arb_create_context@color-index render type with 3.0": "needs a GL 3.0 context",
    "glx@glx-multithread-clearbuffer": "needs GL 3.0 and GL_ARB_clear_buffer_object",
    "spec@ext_texture_compression_s3tc@s3tc-errors_gles2": "needs an OpenGL ES 2.0 context",
    "spec@ext_texture_compression_s3tc@s3tc-teximage_gles2": "needs an OpenGL ES 2.0 context",
    "spec@ext_texture_compression_s3tc@s3tc-texsubimage_gles2": "needs an OpenGL ES 2.0 context",
}


def run_one(argv, env, timeout):
    """(result, seconds, note): piglit's result, and for a skip the requirement it named."""
    start = time.monotonic()
    try:
        # Commands are relative to piglit's launcher in /usr/bin.
        p = subprocess.run(argv, cwd="/usr/bin", env=env, capture_output=True, text=True,
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", time.monotonic() - start, ""
    except OSError:  # piglit lists a few tests whose binaries Debian does not ship
        return "missing", time.monotonic() - start, ""
    result, note = "crash", ""
    for line in (p.stdout + p.stderr).splitlines():
        m = re.match(r'PIGLIT: (\{.*\})', line.strip())
        if m:
            try:
                data = json.loads(m.group(1))
            except json.JSONDecodeError:
                continue
            if "result" in data:
                result = data["result"]
        r = SKIP_REASON.search(line)
        if r and not note:
            note = r.group(1)
    return result, time.monotonic() - start, note if result == "skip" else ""


def beyond_gl15(note, advertised):
    """True when a skip's requirement is outside GL 1.5 and what glpt advertises: a later GL
    version, GLSL, or an extension glpt does not claim."""
    m = BEYOND_GL15.search(note)
    if not m:
        return False
    # A GLX_ requirement (group 2) is never among the GL extensions glpt advertises: piglit skips
    # only for GLX extensions glpt's GLX does not have.
    return not (m.group(1) and m.group(1) in advertised)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--libgl", default=os.path.join(ROOT, "build/gl_shim/libGL.so.1"))
    ap.add_argument("--filter", default="", help="only tests whose name matches this regex")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=int, default=120, help="seconds per test run")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs/piglit.md"))
    ap.add_argument("--groups", default=GL1_GROUPS,
                    help="tests whose name matches this regex (default: the GL 1.0-1.5 groups; "
                         "'extensions': the groups of the extensions glpt advertises)")
    args = ap.parse_args()
    if args.groups == "extensions":
        args.groups = EXTENSION_GROUPS

    if "DISPLAY" not in os.environ or not os.environ.get("GLPT_PIGLIT_UNDER_XVFB"):
        env = dict(os.environ, GLPT_PIGLIT_UNDER_XVFB="1")
        os.execvpe(os.path.join(ROOT, "tests/e2e/with_xvfb.sh"),
                   [os.path.join(ROOT, "tests/e2e/with_xvfb.sh"), sys.executable] + sys.argv,
                   env)

    libgl = os.path.realpath(args.libgl)
    if not os.path.isfile(libgl):
        sys.exit(f"piglit_gl1: libGL not found: {libgl}")
    tests = list_tests(args.groups, args.filter)
    mesa_env = dict(os.environ)
    glpt_env = dict(os.environ, LD_PRELOAD=libgl, GLPT_MODE="raster", GLPT_QUIET="1")
    results = {}

    def job(item):
        name, argv = item
        return name, run_one(argv, mesa_env, args.timeout), run_one(argv, glpt_env, args.timeout)

    started = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for i, (name, mesa, glpt) in enumerate(pool.map(job, tests), 1):
            results[name] = (mesa, glpt)
            print(f"[{i}/{len(tests)}] {name}: mesa={mesa[0]} glpt={glpt[0]}", flush=True)

    advertised = glpt_extensions(glpt_env)
    mesa_pass = [n for n, (m, _) in results.items() if m[0] == "pass"]
    both_pass = [n for n in mesa_pass if results[n][1][0] == "pass"]
    # Tests Mesa passes that skip on glpt because they need more than GL 1.5 (framebuffer
    # objects, integer textures, GLSL, GL 3.0): not GL 1.x tests as far as glpt is concerned.
    beyond = [n for n in mesa_pass
              if results[n][1][0] == "skip" and (n in BEYOND_BY_SOURCE or
                                                 beyond_gl15(results[n][1][2], advertised))]
    gl1 = [n for n in mesa_pass if n not in beyond]
    ratio = len(both_pass) / len(mesa_pass) if mesa_pass else 0.0
    ratio_gl1 = len(both_pass) / len(gl1) if gl1 else 0.0
    elapsed = time.monotonic() - started
    command = "scripts/piglit_gl1.py" + "".join(
        f" {flag} {shlex.quote(str(value))}" for flag, value in
        (("--filter", args.filter), ("--jobs", args.jobs), ("--timeout", args.timeout),
         ("--groups", args.groups if args.groups != GL1_GROUPS else "")) if value)
    what = ("OpenGL 1.0-1.5 tests" if args.groups == GL1_GROUPS
            else f"tests matching `{args.groups}`")
    lines = [
        f"# piglit: {what}, real Mesa vs glpt raster mode",
        "",
        f"Produced by `{command}` ({len(tests)} tests, {elapsed:.0f} s, "
        f"{time.strftime('%Y-%m-%d')}). Mesa is the system libGL (llvmpipe, "
        "Mesa 25.0.7 from bookworm-backports); glpt is `GLPT_MODE=raster`. Tests run on the window "
        "(no `-fbo`).",
        "",
        f"**glpt passes {len(both_pass)} of the {len(gl1)} tests Mesa passes that need only "
        f"GL 1.5 and the extensions glpt advertises ({100 * ratio_gl1:.1f} %)**; "
        f"{len(both_pass)} of all {len(mesa_pass)} tests Mesa passes ({100 * ratio:.1f} %). "
        f"The other {len(beyond)} skip on glpt because they require more than GL 1.5 (the note "
        "says what: piglit's groups hold tests written for GL 1.x entry points that also use "
        "framebuffer objects, integer textures, GLSL or a GL 3.0 context, or a GLX extension "
        "beyond GLX 1.4 that glpt does not implement).",
        "",
        "⚠ marks a test Mesa passes that glpt does not pass; ➚ one beyond GL 1.5.",
        "",
        "| test | Mesa | glpt | note |",
        "|---|---|---|---|",
    ]
    for name in sorted(results):
        (m, _, _), (g, _, note) = results[name]
        mark = ""
        if m == "pass" and g != "pass":
            mark = " ➚" if name in beyond else " ⚠"
            note = BEYOND_BY_SOURCE.get(name, "") or note or KNOWN_DIFFERENCES.get(name, "")
        lines.append(f"| {name.replace('|', '/')} | {m} | {g}{mark} | {note} |")
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"glpt passes {len(both_pass)} of {len(gl1)} GL 1.5 tests Mesa passes "
          f"({100 * ratio_gl1:.1f} %), {len(both_pass)} of all {len(mesa_pass)} "
          f"({100 * ratio:.1f} %); table in {args.out}")


def glpt_extensions(env):
    """glpt's GL_EXTENSIONS, from glxinfo run under it (empty if that fails)."""
    try:
        out = subprocess.run(["glxinfo"], env=env, capture_output=True, text=True,
                             timeout=60).stdout
    except (OSError, subprocess.TimeoutExpired):
        return set()
    m = re.search(r"OpenGL extensions:\n((?:\s+.*\n)+)", out)
    return set(re.findall(r"GL_\w+", m.group(1))) if m else set()


if __name__ == "__main__":
    main()
