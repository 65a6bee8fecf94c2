#!/usr/bin/python3
"""Writes the measured part of docs/BENCHMARKS.md from `glpt tune` CSVs (bench_tradeoffs.sh).

usage: tradeoffs_report.py --report FILE --command TEXT --images DIR TUNE_CSV...

Replaces the text between the markers <!-- tradeoffs:begin --> and <!-- tradeoffs:end --> in
FILE (creating FILE with the markers when it does not exist; the hand-written text around them
stays): the machine, the command, per scene a table of every setting sorted by time with the
Pareto front marked, and the three largest costs of a frame at the default settings. Copies each
scene's plot (pareto.png next to its CSV) to DIR/SCENE.png and links it.
"""
import argparse
import csv
import datetime
import os
import platform
import shutil
import subprocess

BEGIN = "<!-- tradeoffs:begin -->"
END = "<!-- tradeoffs:end -->"
PASSES = ["capture_ms", "upload_ms", "raster_ms", "blas_ms", "tlas_ms", "trace_ms",
          "denoise_ms", "composite_ms"]


def machine():
    cpu = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    try:
        mesa = subprocess.run(["dpkg-query", "-W", "-f", "${Version}", "mesa-vulkan-drivers"],
                              capture_output=True, text=True).stdout.strip()
    except OSError:
        mesa = "?"
    return f"{os.cpu_count()} cores, {cpu}, {platform.system()} {platform.release()}, " \
           f"lavapipe from mesa-vulkan-drivers {mesa}"


def scene_section(path, images):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return ""
    scene = rows[0]["scene"]
    ok = [r for r in rows if not r["failure"]]
    failed = [r for r in rows if r["failure"]]
    ok.sort(key=lambda r: float(r["frame_ms"]))
    lines = [f"### {scene}", ""]
    plot = os.path.join(os.path.dirname(path), "pareto.png")
    if os.path.exists(plot):
        os.makedirs(images, exist_ok=True)
        shutil.copy(plot, os.path.join(images, scene + ".png"))
        lines += [f"![{scene}: time against error](benchmarks/{scene}.png)", ""]
    compared = max((int(r["compared_frames"]) for r in ok), default=0)
    timed = min((int(r["timed_frames"]) for r in ok), default=0)
    lines += [f"{len(ok)} settings; errors are means over {compared} frames, times medians over "
              f"at least {timed} frames. **Bold**: on the Pareto front (no setting is both "
              f"faster and closer to the reference).", ""]
    lines += ["| setting | ms/frame | FLIP | relMSE | PSNR dB | trace ms | denoise ms | "
              "raster ms | Mrays/s | flags |",
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    for r in ok:
        name = f"**{r['setting']}**" if r["pareto"] == "1" else r["setting"]
        lines.append(
            f"| {name} | {float(r['frame_ms']):.1f} | {float(r['flip']):.4f} | "
            f"{float(r['relmse']):.5f} | {float(r['psnr_db']):.2f} | "
            f"{float(r['trace_ms']):.1f} | {float(r['denoise_ms']):.1f} | "
            f"{float(r['raster_ms']):.1f} | {float(r['mrays_per_s']):.3f} | `{r['flags']}` |")
    for r in failed:
        lines.append(f"| {r['setting']} | failed: {r['failure']} | | | | | | | | |")
    default = next((r for r in ok if r["setting"] == "default"), None)
    if default:
        costs = sorted(((float(default[p]), p[:-3]) for p in PASSES), reverse=True)[:3]
        total = float(default["frame_ms"])
        lines += ["", "Largest costs of a frame at the default settings: " +
                  ", ".join(f"{name} {ms:.1f} ms ({100 * ms / total:.0f} %)" if total > 0
                            else f"{name} {ms:.1f} ms" for ms, name in costs) +
                  f" of {total:.1f} ms."]
    lines.append("")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--report", required=True)
    parser.add_argument("--command", required=True)
    parser.add_argument("--images", required=True)
    parser.add_argument("csvs", nargs="*")
    args = parser.parse_args()
    body = [BEGIN, "",
            f"Measured {datetime.date.today().isoformat()} on {machine()}.", "",
            "Reproduce with:", "", "```", args.command, "```", ""]
    for path in args.csvs:
        body.append(scene_section(path, args.images))
    body.append(END)
    text = ""
    if os.path.exists(args.report):
        with open(args.report) as f:
            text = f.read()
    if BEGIN in text and END in text:
        text = text[:text.index(BEGIN)] + "\n".join(body) + text[text.index(END) + len(END):]
    else:
        text = text + ("\n" if text else "") + "\n".join(body) + "\n"
    with open(args.report, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
