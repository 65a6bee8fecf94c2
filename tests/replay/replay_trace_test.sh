#!/usr/bin/env bash
# glpt-replay on a real trace (tests/replay/data/gearsdet.trace: tests/programs/gearsdet
# --size 96x80 --frames 3, recorded with `apitrace trace --api gl`). The commands behind the
# ctest tests in CMakeLists.txt; no X server is used (DISPLAY is unset).
#   replay_trace_test.sh mesa-vs-raster REPLAY IMGCOMPARE TRACE OUT FRAMES
#       Real Mesa (--backend mesa) and glpt's raster mode replay TRACE: both write FRAMES frames
#       with the same names, and raster mode's are within the conformance tolerance of Mesa's.
#   replay_trace_test.sh shards REPLAY TRACE OUT N
#       Path mode: N shards (--shard i/N) write byte-identical PNGs to those of one replay; also
#       with GLPT_ACCUMULATE=1, where the unchanged last frame accumulates two samples.
#   replay_trace_test.sh repeat REPLAY TRACE OUT FRAMES
#       --repeat 3 in raster and path mode: 3 x FRAMES frames, as many Vulkan objects alive at
#       the end of each pass (GLPT_STATS' vk_objects=: re-created contexts leak nothing), and in
#       raster mode each pass's frames byte-identical to the first pass's (path-traced frames
#       are seeded by their index, so they differ).
#   replay_trace_test.sh damaged REPLAY TRACE OUT
#       Damaged traces end with the bad-trace exit code (3) and a message, never a crash; a
#       trace cut short replays what it holds (exit 0).
#   replay_trace_test.sh window REPLAY TRACE OUT X_SEND_KEY WITH_XVFB
#       --window without a display fails cleanly (1); under a private Xvfb, --window --paused
#       waits at frame 0, n steps to frame 1, q quits before frame 2.
#   (window-run: the part of `window` that runs under with_xvfb.sh)
set -euo pipefail
[[ ${1:-} == window-run ]] || unset DISPLAY WAYLAND_DISPLAY
export GLPT_QUIET=1

mode=$1
shift

case "$mode" in
  mesa-vs-raster)
    replay=$1 imgcompare=$2 trace=$3 out=$4 frames=$5
    rm -rf "$out"
    "$replay" --quiet --backend mesa --out "$out/mesa" "$trace"
    "$replay" --quiet --mode raster --out "$out/raster" "$trace"
    count=$(find "$out/mesa" -name 'frame_*.png' | wc -l)
    [[ $count -eq $frames ]] || { echo "mesa wrote $count frames, expected $frames"; exit 1; }
    for reference in "$out"/mesa/frame_*.png; do
      "$imgcompare" within "$reference" "$out/raster/$(basename "$reference")"
    done
    ;;
  shards)
    replay=$1 trace=$2 out=$3 n=$4
    rm -rf "$out"
    "$replay" --quiet --mode path --out "$out/whole" "$trace"
    for ((i = 0; i < n; i++)); do
      "$replay" --quiet --mode path --shard "$i/$n" --out "$out/shards" "$trace"
    done
    whole=$(cd "$out/whole" && ls)
    shards=$(cd "$out/shards" && ls)
    [[ -n $whole && $whole == "$shards" ]] || {
      echo "different frames: whole [$whole] shards [$shards]"
      exit 1
    }
    for f in $whole; do cmp "$out/whole/$f" "$out/shards/$f"; done
    echo "identical: $(echo $whole)"
    # With GLPT_ACCUMULATE=1 unchanged frames accumulate within their history window (frames 1
    # and 2 of the trace are the same: the last has two samples), and shards still reproduce it.
    GLPT_ACCUMULATE=1 GLPT_STATS_FILE="$out/accumulate.stats" \
      "$replay" --quiet --mode path --out "$out/accumulate" "$trace"
    grep -q 'frame=2 .* spp=2 ' "$out/accumulate.stats" ||
      { echo "no accumulation: $(cat "$out/accumulate.stats")"; exit 1; }
    for ((i = 0; i < n; i++)); do
      GLPT_ACCUMULATE=1 "$replay" --quiet --mode path --shard "$i/$n" --out "$out/accumulate_shards" "$trace"
    done
    for f in $whole; do cmp "$out/accumulate/$f" "$out/accumulate_shards/$f"; done
    ! cmp -s "$out/whole/frame_000002.png" "$out/accumulate/frame_000002.png" ||
      { echo "accumulation changed nothing"; exit 1; }
    echo "accumulated and identical in shards"
    ;;
  repeat)
    replay=$1 trace=$2 out=$3 frames=$4
    rm -rf "$out"
    for mode in raster path; do
      GLPT_STATS_FILE="$out/$mode.stats" \
        "$replay" --quiet --mode "$mode" --repeat 3 --out "$out/$mode" "$trace"
      count=$(find "$out/$mode" -name 'frame_*.png' | wc -l)
      [[ $count -eq $((3 * frames)) ]] ||
        { echo "$mode: $count frames, expected $((3 * frames))"; exit 1; }
      for ((f = frames; f < 3 * frames; f++)); do
        [[ $mode == raster ]] || break
        cmp "$out/$mode/$(printf 'frame_%06d.png' $((f % frames)))" \
          "$out/$mode/$(printf 'frame_%06d.png' "$f")"
      done
      objects=$(sed -n 's/.* vk_objects=\([0-9]*\) .*/\1/p' "$out/$mode.stats")
      [[ $(wc -l <<<"$objects") -eq $((3 * frames)) ]] ||
        { echo "$mode: no vk_objects per frame in $(head -2 "$out/$mode.stats")"; exit 1; }
      ends=$(awk -v n="$frames" 'NR % n == 0' <<<"$objects" | sort -u)
      [[ $(wc -l <<<"$ends") -eq 1 ]] ||
        { echo "$mode: Vulkan objects at the end of each pass: $(echo $ends)"; exit 1; }
      echo "$mode: $((3 * frames)) frames, $ends Vulkan objects after each pass"
    done
    ;;
  damaged)
    replay=$1 trace=$2 out=$3
    rm -rf "$out"
    mkdir -p "$out"
    # Exit status of REPLAY on FILE must be WANT; a crash (>= 128) never passes.
    expect() {
      local want=$1 file=$2 status=0
      "$replay" --quiet --mode raster --out "$out/frames" "$file" >"$out/log" 2>&1 || status=$?
      if [[ $status -ne $want ]]; then
        echo "$(basename "$file"): exit $status, expected $want"
        cat "$out/log"
        exit 1
      fi
      if [[ $want -eq 3 ]] && ! grep -q "glpt-replay: " "$out/log"; then
        echo "$(basename "$file"): no message"
        exit 1
      fi
    }
    size=$(stat -c %s "$trace")
    : >"$out/empty.trace"
    expect 3 "$out/empty.trace"
    head -c 4096 /dev/zero >"$out/zeros.trace"
    expect 3 "$out/zeros.trace"
    # Bytes flipped all through the compressed stream.
    python3 - "$trace" "$out/flipped.trace" <<'PY'
import sys
data = bytearray(open(sys.argv[1], "rb").read())
for i in range(64, len(data), 499):
    data[i] ^= 0x5A
open(sys.argv[2], "wb").write(data)
PY
    expect 3 "$out/flipped.trace"
    for cut in 1 2 17 $((size / 3)) $((size / 2)) $((size - 1)); do
      head -c "$cut" "$trace" >"$out/cut.trace"
      status=0
      "$replay" --quiet --mode raster --out "$out/frames" "$out/cut.trace" >"$out/log" 2>&1 ||
        status=$?
      # A cut inside the header is not a trace (3); a cut later ends the replay early (0).
      if [[ $status -ne 0 && $status -ne 3 ]]; then
        echo "cut at $cut bytes: exit $status"
        cat "$out/log"
        exit 1
      fi
    done
    echo "damaged traces rejected cleanly"
    ;;
  window)
    replay=$1 trace=$2 out=$3 send_key=$4 with_xvfb=$5
    rm -rf "$out"
    mkdir -p "$(dirname "$out")"
    status=0
    "$replay" --quiet --window "$trace" >"$out.log" 2>&1 || status=$?
    if [[ $status -ne 1 ]] || ! grep -q -- "--window" "$out.log"; then
      echo "--window without a display: exit $status"
      cat "$out.log"
      exit 1
    fi
    "$with_xvfb" "$0" window-run "$replay" "$trace" "$out" "$send_key"
    ;;
  window-run)
    replay=$1 trace=$2 out=$3 send_key=$4
    "$replay" --window --paused --mode raster --out "$out" "$trace" >"$out.log" 2>&1 &
    pid=$!
    # Waits up to 20 s for FILE to appear.
    wait_for() {
      for _ in $(seq 1 200); do
        [[ -e $1 ]] && return 0
        sleep 0.1
      done
      echo "timed out waiting for $1"
      cat "$out.log"
      kill "$pid" 2>/dev/null || true
      exit 1
    }
    wait_for "$out/frame_000000.png"
    sleep 0.5
    [[ ! -e $out/frame_000001.png ]] || { echo "not paused at frame 0"; exit 1; }
    "$send_key" glpt-replay n
    wait_for "$out/frame_000001.png"
    sleep 0.5
    [[ ! -e $out/frame_000002.png ]] || { echo "did not stop after one step"; exit 1; }
    "$send_key" glpt-replay q
    status=0
    wait "$pid" || status=$?
    [[ $status -eq 0 ]] || { echo "exit $status after q"; cat "$out.log"; exit 1; }
    [[ ! -e $out/frame_000002.png ]] || { echo "frame 2 written after q"; exit 1; }
    echo "paused, stepped and quit"
    ;;
  *)
    echo "unknown mode $mode" >&2
    exit 2
    ;;
esac
