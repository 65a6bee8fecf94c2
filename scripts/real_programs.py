#!/usr/bin/env python3
"""Runs real GL programs live under glpt, path-traced and in raster mode, for 300 frames each, and
checks that what the X window shows equals the PNG glpt wrote for the same frame. Writes a table.

  scripts/real_programs.py [--libgl PATH] [--frames N] [--size WxH] [--timeout S]
                           [--programs a,b,...] [--modes raster,path] [--out docs/real-programs.md]

Programs (default): glxgears and the xscreensaver hacks gears, lament, sproingies, pipes, atlantis,
molecule (packages mesa-utils, xscreensaver-gl, xscreensaver-gl-extra), unmodified, each in the
same private Xvfb. For every program and mode: run with GLPT_OUTPUT (a PNG per frame) until the
PNG of frame N-1 exists (N frames) or --timeout passes; then freeze the program (SIGSTOP), dump its
window with `xwd`, and compare it with glpt's newest PNG pixel for pixel (if the program was
frozen between presenting a frame and writing its PNG, it is resumed briefly and frozen again, up
to five times); then stop it with SIGTERM. Result columns: frames reached, seconds, frames per
second, window == PNG (or the largest channel difference), how the run ended.
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

import glpt_images
from xscreensaver_table import HACK_DIR, death, start_xvfb, stop

DEFAULT_PROGRAMS = ["glxgears", "gears", "lament", "sproingies", "pipes", "atlantis", "molecule"]


def program_command(name, size):
    if name == "glxgears":
        return ["/usr/bin/glxgears", "-geometry", size + "+0+0"]
    return [os.path.join(HACK_DIR, name), "-geometry", size + "+0+0"]


def top_window(display):
    """The largest child window of the root (the program's window), as a hex id, or None."""
    text = subprocess.run(["xwininfo", "-root", "-children"], env=dict(os.environ, DISPLAY=display),
                          capture_output=True, text=True).stdout
    best, best_area = None, 0
    for m in re.finditer(r"^\s+(0x[0-9a-f]+) .*?\s(\d+)x(\d+)\+", text, re.M):
        area = int(m.group(2)) * int(m.group(3))
        if area > best_area:
            best, best_area = m.group(1), area
    return best


def newest_png(out):
    pngs = sorted(f for f in os.listdir(out) if re.fullmatch(r"frame_\d+\.png", f))
    return os.path.join(out, pngs[-1]) if pngs else None


def compare_window(proc, display, out, work):
    """Freezes the program and compares its window with the newest PNG: (equal, detail)."""
    detail = "no window"
    for _attempt in range(5):
        proc.send_signal(signal.SIGSTOP)
        try:
            time.sleep(0.2)  # let the X server finish the last presented image
            window = top_window(display)
            png = newest_png(out)
            if window is None or png is None:
                detail = "no window" if window is None else "no PNG"
                continue
            dump = os.path.join(work, "window.xwd")
            with open(dump, "wb") as f:
                subprocess.run(["xwd", "-silent", "-nobdrs", "-id", window], stdout=f,
                               env=dict(os.environ, DISPLAY=display), check=True)
            ww, wh, wrgb = glpt_images.read_xwd(dump)
            pw, ph, prgb = glpt_images.read_png(png)
            if (ww, wh) != (pw, ph):
                detail = f"window {ww}x{wh}, PNG {pw}x{ph}"
                continue
            worst = max((abs(a - b) for a, b in zip(wrgb, prgb)), default=0)
            if worst == 0:
                return True, f"equal ({os.path.basename(png)})"
            detail = f"max channel difference {worst} ({os.path.basename(png)})"
        finally:
            proc.send_signal(signal.SIGCONT)
        time.sleep(0.3)
    return False, detail


def run(name, mode, args, display, work):
    out = os.path.join(work, "frames")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    env = dict(os.environ, DISPLAY=display, LD_PRELOAD=args.libgl, GLPT_MODE=mode, GLPT_OUTPUT=out)
    log = open(os.path.join(work, "stderr"), "wb")
    started = time.time()
    proc = subprocess.Popen(program_command(name, args.size), env=env, stdout=subprocess.DEVNULL,
                            stderr=log)
    target = os.path.join(out, "frame_%06d.png" % (args.frames - 1))
    ended = None
    while not os.path.exists(target):
        if proc.poll() is not None:
            ended = "exited %d" % proc.returncode if proc.returncode >= 0 else \
                death(proc.returncode)
            break
        if time.time() - started > args.timeout:
            ended = "too slow (timeout)"
            break
        time.sleep(0.2)
    seconds = time.time() - started
    frames = len([f for f in os.listdir(out) if f.endswith(".png")])
    equal, detail = (False, "not compared")
    if ended is None:
        equal, detail = compare_window(proc, display, out, work)
    if proc.poll() is None:
        clean = stop(proc, 15)
        if ended is None:
            ended = "ran" if clean else \
                "hang on SIGTERM (killed)" if proc.returncode == -signal.SIGKILL else \
                "crash on exit (%s)" % proc.returncode
    log.close()
    return dict(frames=frames, seconds=seconds, fps=frames / seconds if seconds > 0 else 0.0,
                equal=equal, detail=detail, ended=ended)


def main():
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--libgl", default=os.path.join(repo, "build", "gl_shim", "libGL.so.1"))
    ap.add_argument("--frames", type=int, default=300)
    ap.add_argument("--size", default="320x240")
    ap.add_argument("--timeout", type=float, default=900.0, help="seconds per run")
    ap.add_argument("--programs", default=",".join(DEFAULT_PROGRAMS))
    ap.add_argument("--modes", default="raster,path")
    ap.add_argument("--out", default=os.path.join(repo, "docs", "real-programs.md"))
    args = ap.parse_args()
    args.libgl = os.path.abspath(args.libgl)
    if not os.path.isfile(args.libgl):
        sys.exit(f"real_programs: {args.libgl} not found (build first)")
    xvfb, display = start_xvfb("1024x768")
    work = tempfile.mkdtemp(prefix="glpt-real-")
    rows = []
    try:
        for name in args.programs.split(","):
            for mode in args.modes.split(","):
                if not os.path.exists(program_command(name, args.size)[0]):
                    rows.append((name, mode, None))
                    print(f"{name} {mode}: not installed", flush=True)
                    continue
                r = run(name, mode, args, display, work)
                rows.append((name, mode, r))
                print(f"{name} {mode}: {r['frames']} frames in {r['seconds']:.0f} s, "
                      f"{r['detail']}, {r['ended']}", flush=True)
    finally:
        xvfb.terminate()
        xvfb.wait()
        shutil.rmtree(work, ignore_errors=True)
    ok = sum(1 for _, _, r in rows if r and r["equal"] and r["ended"] == "ran"
             and r["frames"] >= args.frames)
    with open(args.out, "w") as f:
        f.write("# Real programs under glpt\n\n")
        f.write(f"Unmodified programs run live in a private Xvfb at {args.size} until glpt has "
                f"ended {args.frames} frames, in raster and path-traced mode; then frozen, their "
                "window dumped with `xwd` and compared pixel for pixel with the PNG glpt wrote "
                "for the frame the window shows. Command: "
                f"`scripts/real_programs.py --frames {args.frames} --size {args.size}` "
                f"({time.strftime('%Y-%m-%d')}; 2-core machine, lavapipe, other work running).\n\n")
        f.write(f"**{ok} of {len(rows)} runs reached {args.frames} frames, showed in the window "
                "exactly what the PNG holds and ended cleanly.**\n\n")
        f.write("| program | mode | frames | seconds | frames/s | window == PNG | end |\n")
        f.write("|---|---|---:|---:|---:|---|---|\n")
        for name, mode, r in rows:
            if r is None:
                f.write(f"| {name} | {mode} | | | | | not installed |\n")
            else:
                f.write(f"| {name} | {mode} | {r['frames']} | {r['seconds']:.0f} | {r['fps']:.1f} | "
                        f"{'yes' if r['equal'] else 'no'}: {r['detail']} | {r['ended']} |\n")
    print(f"{ok}/{len(rows)} runs ok; table in {args.out}")
    return 0 if ok == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main())
