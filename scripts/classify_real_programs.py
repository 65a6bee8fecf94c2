#!/usr/bin/env python3
"""What glpt's classification makes of real programs (docs/classification.md): runs xscreensaver
hacks for a few seconds each in one private Xvfb, and replays apitrace traces of games headless,
with GLPT_CLASSIFY_LOG, and writes a markdown table: program, frames, drawing commands per frame,
the share of commands in each class, and identity churn (the share of entries of a frame, after
the first, whose id the frame before did not have: 0 for a scene whose draws all persist).

  scripts/classify_real_programs.py [--libgl PATH] [--replay PATH] [--seconds S]
                                    [--hacks "gears pipes ..."] [--trace NAME=FILE ...]
                                    [--mode path|raster] [--out FILE]

Traces are replayed with glpt-replay (--frames limits them: --trace-frames, default 0-199).
"""
import argparse
import collections
import json
import os
import signal
import subprocess
import sys
import tempfile

from xscreensaver_table import start_xvfb  # the same private Xvfb

HACK_DIR = "/usr/libexec/xscreensaver"
KINDS = ["static", "moving", "deforming", "blended", "particles", "multipass", "decal", "overlay",
         "sky", "shadow", "viewmodel", "lines", "hidden"]


def summarize(log_path):
    frames = collections.OrderedDict()
    with open(log_path) as f:
        for line in f:
            line = line.strip()
            if not line:
                continue
            try:
                e = json.loads(line)
            except json.JSONDecodeError:
                continue  # a program killed mid-line (older glpt builds)
            frames.setdefault(e["frame"], []).append(e)
    calls = collections.Counter()
    churn_new = churn_total = 0
    previous = None
    for entries in frames.values():
        ids = {e["id"] for e in entries}
        for e in entries:
            calls[e["class"]] += e["calls"]
        if previous is not None:
            churn_total += len(entries)
            churn_new += sum(1 for e in entries if e["id"] not in previous)
        previous = ids
    total = sum(calls.values())
    return dict(frames=len(frames), calls=total, per_class=calls,
                churn=(churn_new / churn_total) if churn_total else 0.0)


def run_hack(hack, display, libgl, seconds, mode, log):
    env = dict(os.environ, DISPLAY=display, LD_PRELOAD=libgl, GLPT_MODE=mode, GLPT_QUIET="1",
               GLPT_CLASSIFY_LOG=log)
    proc = subprocess.Popen([os.path.join(HACK_DIR, hack), "-geometry", "320x240"], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        proc.wait(timeout=seconds)
    except subprocess.TimeoutExpired:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


def run_trace(trace, replay, frames, mode, log):
    env = dict(os.environ, GLPT_CLASSIFY_LOG=log, GLPT_QUIET="1")
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([replay, "--mode", mode, "--quiet", "--frames", frames, "--out", out, trace],
                       env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)


def row(name, s):
    per = s["calls"] / s["frames"] if s["frames"] else 0
    shares = []
    for k in KINDS:
        if s["per_class"][k]:
            shares.append(f"{k} {100.0 * s['per_class'][k] / s['calls']:.0f}%")
    return (f"| {name} | {s['frames']} | {per:.0f} | {', '.join(shares) or '-'} | "
            f"{100.0 * s['churn']:.1f}% |")


def main():
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--libgl", default=os.path.join(repo, "build", "gl_shim", "libGL.so.1"))
    ap.add_argument("--replay", default=os.path.join(repo, "build", "replay", "glpt-replay"))
    ap.add_argument("--seconds", type=float, default=8.0)
    ap.add_argument("--hacks", default="")
    ap.add_argument("--trace", action="append", default=[], metavar="NAME=FILE")
    ap.add_argument("--trace-frames", default="0-199")
    ap.add_argument("--mode", default="path", choices=("path", "raster"))
    ap.add_argument("--out", default="")
    args = ap.parse_args()
    lines = ["| program | frames | drawing commands per frame | classes (share of commands) | "
             "identity churn |", "|---|---|---|---|---|"]
    work = tempfile.mkdtemp(prefix="glpt-classify-")
    hacks = args.hacks.split()
    if hacks:
        xvfb, display = start_xvfb("1024x768")
        try:
            for hack in hacks:
                log = os.path.join(work, hack + ".jsonl")
                run_hack(hack, display, os.path.abspath(args.libgl), args.seconds, args.mode, log)
                if os.path.exists(log):
                    lines.append(row(hack, summarize(log)))
                else:
                    lines.append(f"| {hack} | no log | | | |")
                print(lines[-1], flush=True)
        finally:
            xvfb.kill()
            xvfb.wait()
    for spec in args.trace:
        name, _, trace = spec.partition("=")
        log = os.path.join(work, name + ".jsonl")
        run_trace(trace, args.replay, args.trace_frames, args.mode, log)
        lines.append(row(name + " (trace)", summarize(log)) if os.path.exists(log)
                     else f"| {name} | no log | | | |")
        print(lines[-1], flush=True)
    text = "\n".join(lines) + "\n"
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    print(f"logs in {work}", file=sys.stderr)


if __name__ == "__main__":
    main()
