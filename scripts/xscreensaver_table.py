#!/usr/bin/env python3
"""Runs every hack in /usr/libexec/xscreensaver under glpt (raster mode) for a few seconds each in
one private Xvfb and writes a table: hack, frames glpt ended, frames with draws, GL errors,
calls to unimplemented GL commands, how the run ended, and whether it drew.

  scripts/xscreensaver_table.py [--libgl PATH] [--seconds S] [--size WxH] [--out docs/xscreensaver.md]
                                [--filter REGEX] [--mode raster|path]

A hack "draws" when glpt ended at least one frame with a draw in it and one of the last five PNGs
it wrote (GLPT_OUTPUT, every 10th frame) is not one flat colour. "crash": the hack died of a signal other
than the SIGTERM that ends every run, or glpt/EGL/GLX reported a fatal error. Counts come from
GLPT_STATS=1 lines ("glpt: frame=..." and the running "glpt: totals ..." line).
"""
import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import zlib

import glpt_images

HACK_DIR = "/usr/libexec/xscreensaver"
# Programs in HACK_DIR that are not screen hacks: listed, not run, not counted.
NOT_HACKS = {
    "xscreensaver-gl-visual": "helper: prints the GL visual xscreensaver should use, draws nothing",
    "mapscroller.pl": "helper script that downloads map tiles for mapscroller",
}


def png_is_flat(path):
    """True when the PNG at `path` holds a single colour or cannot be read."""
    try:
        return glpt_images.is_flat(glpt_images.read_png(path)[2])
    except (OSError, ValueError, zlib.error):
        return True


def death(returncode):
    """How a process that ended by a signal or an error status ended, for the tables."""
    try:
        return "crash (%s)" % signal.Signals(-returncode).name
    except ValueError:
        return "crash (status %d)" % returncode


def stop(proc, grace):
    """SIGTERM, then SIGKILL after `grace` seconds. Returns True when the program ended cleanly
    (by the SIGTERM or status 0), False when it had to be killed or died otherwise."""
    proc.send_signal(signal.SIGTERM)
    try:
        proc.wait(timeout=grace)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
        return False
    return proc.returncode in (0, -signal.SIGTERM)


def start_xvfb(size):
    read_fd, write_fd = os.pipe()
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write_fd), "-screen", "0", f"{size}x24",
                             "-nolisten", "tcp"], pass_fds=(write_fd,),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_fd)
    with os.fdopen(read_fd) as f:
        display = f.readline().strip()
    if not display:
        xvfb.kill()
        raise RuntimeError("Xvfb did not start")
    return xvfb, ":" + display


def run_hack(path, display, libgl, seconds, size, mode, work):
    out = os.path.join(work, "frames")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    env = dict(os.environ, DISPLAY=display, LD_PRELOAD=libgl, GLPT_MODE=mode, GLPT_STATS="1",
               GLPT_OUTPUT=out, GLPT_OUTPUT_EVERY="10")
    stderr_path = os.path.join(work, "stderr")
    with open(stderr_path, "wb") as err:
        proc = subprocess.Popen([path, "-geometry", size], env=env, stdout=subprocess.DEVNULL,
                                stderr=err)
        try:
            proc.wait(timeout=seconds)
            ended = "exited %d" % proc.returncode if proc.returncode >= 0 else None
        except subprocess.TimeoutExpired:
            ended = "ran" if stop(proc, 10) else None
        if ended is None:
            ended = death(proc.returncode)
    text = open(stderr_path, "rb").read().decode("utf-8", "replace")
    frames = [m for m in re.finditer(r"^glpt: frame=\d+ .*?draws=(\d+)", text, re.M)]
    drawn = sum(1 for m in frames if int(m.group(1)) > 0)
    totals = re.findall(r"^glpt: totals gl_errors=(\d+) unimplemented_calls=(\d+)", text, re.M)
    errors, unimplemented = (int(totals[-1][0]), int(totals[-1][1])) if totals else (0, 0)
    unimplemented_names = sorted(set(re.findall(r"^glpt: (\w+) is not implemented", text, re.M)))
    fatal = re.search(r"(Segmentation fault|Aborted|terminate called|fatal)", text)
    if fatal and not ended.startswith("crash"):
        ended = f"crash ({fatal.group(1)})"
    pngs = sorted(f for f in os.listdir(out) if f.endswith(".png"))
    # Animations fade and move off-screen, so any of the last few PNGs may show the drawing.
    draws = drawn > 0 and any(not png_is_flat(os.path.join(out, p)) for p in pngs[-5:])
    last_line = ""
    if not draws:
        lines = [l for l in text.splitlines() if l.strip() and not l.startswith("glpt: frame=")
                 and not l.startswith("glpt: totals")]
        last_line = lines[-1][:100] if lines else ""
    return dict(frames=len(frames), drawn=drawn, errors=errors, unimplemented=unimplemented,
                unimplemented_names=unimplemented_names, ended=ended, draws=draws, note=last_line)


def main():
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--libgl", default=os.path.join(repo, "build", "gl_shim", "libGL.so.1"))
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--size", default="320x240")
    ap.add_argument("--mode", default="raster", choices=("raster", "path"))
    ap.add_argument("--filter", default="")
    ap.add_argument("--out", default=os.path.join(repo, "docs", "xscreensaver.md"))
    args = ap.parse_args()
    libgl = os.path.abspath(args.libgl)
    if not os.path.isfile(libgl):
        sys.exit(f"xscreensaver_table: {libgl} not found (build first)")
    if not os.path.isdir(HACK_DIR):
        sys.exit(f"xscreensaver_table: {HACK_DIR} not found (package xscreensaver-gl)")
    hacks = sorted(h for h in os.listdir(HACK_DIR)
                   if os.access(os.path.join(HACK_DIR, h), os.X_OK) and re.search(args.filter, h)
                   and h not in NOT_HACKS)
    xvfb, display = start_xvfb("1024x768")
    rows = []
    work = tempfile.mkdtemp(prefix="glpt-xss-")
    started = time.time()
    try:
        for i, hack in enumerate(hacks):
            r = run_hack(os.path.join(HACK_DIR, hack), display, libgl, args.seconds,
                         args.size + "+0+0", args.mode, work)
            rows.append((hack, r))
            print(f"[{i + 1}/{len(hacks)}] {hack}: frames={r['frames']} drawn={r['drawn']} "
                  f"errors={r['errors']} unimplemented={r['unimplemented']} {r['ended']} "
                  f"{'draws' if r['draws'] else 'DOES NOT DRAW'}", flush=True)
    finally:
        xvfb.terminate()
        xvfb.wait()
        shutil.rmtree(work, ignore_errors=True)
    drawing = sum(1 for _, r in rows if r["draws"])
    crashes = sum(1 for _, r in rows if r["ended"].startswith("crash"))
    share = 100.0 * drawing / len(rows) if rows else 0.0
    with open(args.out, "w") as f:
        f.write("# xscreensaver hacks under glpt\n\n")
        f.write(f"Every hack in `{HACK_DIR}` run for {args.seconds:g} s at {args.size} in "
                f"{args.mode} mode (GLPT_MODE={args.mode}) in a private Xvfb, by\n"
                f"`scripts/xscreensaver_table.py --seconds {args.seconds:g} --size {args.size} "
                f"--mode {args.mode}` ({time.strftime('%Y-%m-%d')}, "
                f"{time.time() - started:.0f} s in all).\n\n")
        f.write(f"**{drawing} of {len(rows)} hacks draw ({share:.1f} %); {crashes} crash.** "
                "A hack draws when glpt ended a frame with draws in it and one of its last five "
                "PNGs (every 10th frame) is not one flat colour. Frames: frames glpt ended (slow machine: 2 cores, lavapipe). "
                "GL errors: every GL error glpt recorded (GL keeps only the first until read). "
                "Unimplemented: calls to GL commands glpt does not implement. End: `ran` = ran "
                "until stopped with SIGTERM.\n\n")
        f.write("| hack | frames | with draws | GL errors | unimplemented | end | draws | note |\n")
        f.write("|---|---:|---:|---:|---:|---|---|---|\n")
        for hack, reason in sorted(NOT_HACKS.items()):
            if os.path.exists(os.path.join(HACK_DIR, hack)):
                f.write(f"| {hack} | | | | | not run | | {reason} |\n")
        for hack, r in rows:
            note = r["note"].replace("|", "\\|")
            if r["unimplemented_names"]:
                note = ", ".join(r["unimplemented_names"]) + ((" — " + note) if note else "")
            f.write(f"| {hack} | {r['frames']} | {r['drawn']} | {r['errors']} | "
                    f"{r['unimplemented']} | {r['ended']} | {'yes' if r['draws'] else '**no**'} | "
                    f"{note} |\n")
    print(f"{drawing}/{len(rows)} draw ({share:.1f} %), {crashes} crash; table in {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
