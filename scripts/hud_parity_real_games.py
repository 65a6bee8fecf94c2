#!/usr/bin/env python3
"""Whether path-traced frames of real programs keep their HUD and sky as GL draws them
(docs/classification.md, "Real programs"): replays apitrace traces four times with glpt-replay
- real Mesa (OSMesa, --backend mesa), glpt's raster mode, glpt's raster mode tinted by class
(--classify-debug) and glpt's path-traced mode (defaults) - and, per frame, finds the pixels
whose colour comes from an overlay draw alone (tinted white: (raster + 255) / 2 within 2 levels)
and from the sky alone (tinted light blue), and counts how many of them the path-traced frame
has exactly as Mesa has them, and exactly as glpt's raster mode has them (where raster mode
itself differs from Mesa, path tracing must leave the pixel as raster mode draws it). Blended HUD
edges over the world are not counted (the world under them is traced: it differs by design).
Prints a markdown table per trace, with the lowest PSNR of raster mode against Mesa over the
frames (inf: identical).

  scripts/hud_parity_real_games.py --trace NAME=FILE [--trace ...] [--frames LIST] [--every N]
                                   [--replay PATH] [--work DIR] [--reuse] [--out FILE]

--reuse: compare the images an earlier run left in --work instead of replaying.

--frames: glpt-replay's frame list (default 0-299 with --every 20). Needs a built glpt-replay
(default build/replay/glpt-replay) with OSMesa.
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile

from glpt_images import read_png

TINTS = {"overlay": (1.0, 1.0, 1.0), "sky": (0.6, 0.85, 1.0)}  # rt_core/scene/classify_debug.cpp


def replay(replay_bin, trace, out_dir, frames, every, extra):
    os.makedirs(out_dir, exist_ok=True)
    command = [replay_bin, trace, "--quiet", "--out", out_dir, "--frames", frames] + extra
    if every:
        command += ["--every", str(every)]
    result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if result.returncode != 0:
        sys.exit(f"hud_parity: {' '.join(command)} failed:\n{result.stderr[-2000:]}")


def owned(raster, tinted, tint, i):
    """Pixel i's colour in the tinted replay is its raster colour mixed half and half with
    `tint`: the pixel comes from a draw of that class alone."""
    for c in range(3):
        expected = (raster[i + c] + 255.0 * tint[c]) / 2.0
        if abs(tinted[i + c] - expected) > 2.0:
            return False
    return True


def compare_frame(paths):
    images = {}
    for name, path in paths.items():
        w, h, rgb = read_png(path)
        images[name] = rgb
    size = (w, h)
    stats = {}
    for kind, tint in TINTS.items():
        pixels = equal = equal_raster = 0
        worst = worst_raster = 0
        for i in range(0, len(images["raster"]), 3):
            if not owned(images["raster"], images["debug"], tint, i):
                continue
            pixels += 1
            diff = max(abs(images["path"][i + c] - images["mesa"][i + c]) for c in range(3))
            equal += diff == 0
            diff_raster = max(abs(images["path"][i + c] - images["raster"][i + c])
                              for c in range(3))
            equal_raster += diff_raster == 0
            worst = max(worst, diff)
            worst_raster = max(worst_raster, diff_raster)
        stats[kind] = (pixels, equal, equal_raster, worst, worst_raster)
    return size, stats, psnr(images["raster"], images["mesa"])


def psnr(a, b):
    squares = sum((x - y) * (x - y) for x, y in zip(a, b))
    if squares == 0:
        return math.inf
    return 10.0 * math.log10(255.0 * 255.0 * len(a) / squares)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--trace", action="append", required=True, metavar="NAME=FILE")
    parser.add_argument("--frames", default="0-299")
    parser.add_argument("--every", type=int, default=20)
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--replay", default=os.path.join(here, "..", "build", "replay",
                                                         "glpt-replay"))
    parser.add_argument("--work", default=None)
    parser.add_argument("--reuse", action="store_true")
    parser.add_argument("--out", default=None, help="also write the table to FILE")
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="glpt-hud.")
    lines = ["command: " + " ".join([os.path.relpath(sys.argv[0])] + sys.argv[1:]), "",
             "| program | frames | raster vs Mesa, lowest PSNR | overlay pixels | path = Mesa there "
             "| path = raster there | max diff to Mesa, to raster | sky pixels | path = Mesa there "
             "| path = raster there | max diff to Mesa, to raster |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    print(lines[0], flush=True)
    for spec in args.trace:
        name, _, trace = spec.partition("=")
        if not os.path.isfile(trace):
            sys.exit(f"hud_parity: no trace {trace}")
        dirs = {k: os.path.join(work, name, k) for k in ("mesa", "raster", "debug", "path")}
        runs = {"mesa": ["--backend", "mesa"], "raster": ["--mode", "raster"],
                "debug": ["--mode", "raster", "--classify-debug"], "path": ["--mode", "path"]}
        for kind, extra in runs.items():
            if args.reuse and os.path.isdir(dirs[kind]):
                continue
            print(f"  {name}: replaying ({kind})", file=sys.stderr, flush=True)
            replay(args.replay, trace, dirs[kind], args.frames, args.every, extra)
        frames = sorted(f for f in os.listdir(dirs["mesa"]) if f.endswith(".png"))
        totals = {k: [0, 0, 0, 0, 0] for k in TINTS}
        lowest_psnr = math.inf
        for frame in frames:
            paths = {k: os.path.join(d, frame) for k, d in dirs.items()}
            if not all(os.path.isfile(p) for p in paths.values()):
                sys.exit(f"hud_parity: {frame} missing in one of {work}/{name}/*")
            _, stats, raster_psnr = compare_frame(paths)
            lowest_psnr = min(lowest_psnr, raster_psnr)
            for kind, (pixels, equal, equal_raster, worst, worst_raster) in stats.items():
                totals[kind][0] += pixels
                totals[kind][1] += equal
                totals[kind][2] += equal_raster
                totals[kind][3] = max(totals[kind][3], worst)
                totals[kind][4] = max(totals[kind][4], worst_raster)
            print(f"  {name} {frame}: overlay {stats['overlay'][1]}/{stats['overlay'][0]} "
                  f"sky {stats['sky'][1]}/{stats['sky'][0]}", file=sys.stderr, flush=True)

        def share(kind):
            pixels, equal, equal_raster, worst, worst_raster = totals[kind]
            if pixels == 0:
                return "0 | - | - | -"
            return (f"{pixels} | {100.0 * equal / pixels:.2f} % | "
                    f"{100.0 * equal_raster / pixels:.2f} % | {worst}, {worst_raster}")

        lines.append(f"| {name} | {len(frames)} | {lowest_psnr:.1f} dB | "
                     f"{share('overlay')} | {share('sky')} |")
        print(lines[-1], flush=True)
    print(f"images: {work}", file=sys.stderr)
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
