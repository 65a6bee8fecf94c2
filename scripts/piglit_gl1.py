#!/usr/bin/env python3
"""Runs piglit's OpenGL 1.0-1.5 tests on real Mesa and on glpt's raster mode, and writes the
results as a Markdown table (docs/piglit.md by default).

    scripts/piglit_gl1.py [--libgl build/gl_shim/libGL.so.1] [--filter REGEX] [--jobs 2]
                          [--timeout 120] [--out docs/piglit.md]

The tests are those of Debian's piglit package (`piglit print-cmd opengl`) in the groups
"spec@!opengl 1.0" .. "spec@!opengl 1.5" (piglit's tests/spec/gl-1.* and the older general/
tests that need only GL 1.x). Each runs on the window (without piglit's -fbo: glpt implements
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
GROUPS = re.compile(r"^spec@!opengl 1\.[0-5]@")


def list_tests(pattern):
    out = subprocess.run(["piglit", "print-cmd", "opengl"], capture_output=True, text=True,
                         check=True).stdout
    tests = []
    for line in out.splitlines():
        if " ::: " not in line:
            continue
        name, command = line.split(" ::: ", 1)
        if not GROUPS.search(name) or (pattern and not re.search(pattern, name)):
            continue
        argv = [a for a in shlex.split(command) if a != "-fbo"]
        tests.append((name, argv))
    return tests


def run_one(argv, env, timeout):
    start = time.monotonic()
    try:
        # Commands are relative to piglit's launcher in /usr/bin.
        p = subprocess.run(argv, cwd="/usr/bin", env=env, capture_output=True, text=True,
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", time.monotonic() - start
    result = "crash"
    for line in (p.stdout + p.stderr).splitlines():
        m = re.match(r'PIGLIT: (\{.*\})', line.strip())
        if m:
            try:
                data = json.loads(m.group(1))
            except json.JSONDecodeError:
                continue
            if "result" in data:
                result = data["result"]
    return result, time.monotonic() - start


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--libgl", default=os.path.join(ROOT, "build/gl_shim/libGL.so.1"))
    ap.add_argument("--filter", default="", help="only tests whose name matches this regex")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=int, default=120, help="seconds per test run")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs/piglit.md"))
    args = ap.parse_args()

    if "DISPLAY" not in os.environ or not os.environ.get("GLPT_PIGLIT_UNDER_XVFB"):
        env = dict(os.environ, GLPT_PIGLIT_UNDER_XVFB="1")
        os.execvpe(os.path.join(ROOT, "tests/e2e/with_xvfb.sh"),
                   [os.path.join(ROOT, "tests/e2e/with_xvfb.sh"), sys.executable] + sys.argv,
                   env)

    libgl = os.path.realpath(args.libgl)
    if not os.path.isfile(libgl):
        sys.exit(f"piglit_gl1: libGL not found: {libgl}")
    tests = list_tests(args.filter)
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

    mesa_pass = [n for n, (m, _) in results.items() if m[0] == "pass"]
    both_pass = [n for n in mesa_pass if results[n][1][0] == "pass"]
    ratio = len(both_pass) / len(mesa_pass) if mesa_pass else 0.0
    elapsed = time.monotonic() - started
    command = "scripts/piglit_gl1.py" + "".join(
        f" {flag} {shlex.quote(str(value))}" for flag, value in
        (("--filter", args.filter), ("--jobs", args.jobs), ("--timeout", args.timeout)) if value)
    lines = [
        "# piglit: OpenGL 1.0-1.5 tests, real Mesa vs glpt raster mode",
        "",
        f"Produced by `{command}` ({len(tests)} tests, {elapsed:.0f} s, "
        f"{time.strftime('%Y-%m-%d')}). Mesa is the system libGL (llvmpipe, "
        "Mesa 25.0.7 from bookworm-backports); glpt is `GLPT_MODE=raster`. Tests run on the window "
        "(no `-fbo`).",
        "",
        f"**glpt passes {len(both_pass)} of the {len(mesa_pass)} tests Mesa passes "
        f"({100 * ratio:.1f} %).**",
        "",
        "| test | Mesa | glpt |",
        "|---|---|---|",
    ]
    for name in sorted(results):
        (m, _), (g, _) = results[name]
        mark = " ⚠" if m == "pass" and g != "pass" else ""
        lines.append(f"| {name.replace('|', '/')} | {m} | {g}{mark} |")
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"glpt passes {len(both_pass)} of {len(mesa_pass)} tests Mesa passes "
          f"({100 * ratio:.1f} %); table in {args.out}")


if __name__ == "__main__":
    main()
