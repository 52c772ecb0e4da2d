#!/bin/sh
# Processor time (user + system, all threads, GNU time) of the corrected camera against plain
# POV-Ray: the template rendered with no atmosphere, `mirage compile` (corrected camera), and
# POV-Ray's render of what it wrote (parse included); then the same compiled with the scene's
# own camera (--camera perspective, the layers fitted to its rays).  Each the median of RUNS
# runs (default 3).  Prints a markdown table.  Run from the top of the repository after the
# build:
#   tools/camera_cost.sh scenes/desert.pov 640 480 [--antialias] [other compile options]
set -eu
scene=$1; W=$2; H=$3; shift 3
runs=${RUNS:-3}
mirage=${MIRAGE:-build/mirage}
name=$(basename "$scene" .pov)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cpu() {  # processor seconds of: command...  (the median of $runs runs)
    for i in $(seq "$runs"); do
        /usr/bin/time -f "%U %S" -o "$out/time" "$@" >"$out/log" 2>&1 ||
            { echo "failed: $*" >&2; tail -5 "$out/log" >&2; exit 1; }
        awk '{ printf "%.3f\n", $1 + $2 }' "$out/time"
    done | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'
}
field() {  # KEY FILE: a number from the compile's JSON report
    grep "\"$1\"" "$2" | head -1 | sed 's/.*: *//; s/[",]//g'
}
plain=$(cpu povray -D -A +W"$W" +H"$H" +Lpov_includes +O"$out/plain.png" "$scene")
echo "| $name ${W}x$H $* | compile (s) | POV-Ray (s) | POV-Ray / plain | layers | seen p95 (px) | camera rays p95 / max (px) |"
echo "|---|---|---|---|---|---|---|"
echo "| plain POV-Ray, no atmosphere | - | $plain | 1 | 0 | - | - |"
for camera in corrected perspective; do
    dir=$out/$camera
    comp=$(cpu "$mirage" compile "$scene" -W "$W" -H "$H" -o "$dir" --camera "$camera" -q "$@")
    "$mirage" compile "$scene" -W "$W" -H "$H" -o "$dir" --camera "$camera" --json "$@" \
        >"$out/$camera.json"
    render=$(cpu povray -D "$dir/$name.ini")
    layers=$(field layers "$out/$camera.json")
    seen=$(field p95_seen_error_px "$out/$camera.json")
    if [ "$camera" = corrected ]; then
        cam="$(field p95_camera_error_px "$out/$camera.json") / $(field max_camera_error_px "$out/$camera.json")"
    else
        cam="-"
    fi
    ratio=$(echo "$render $plain" | awk '{ printf "%.1f", $1 / $2 }')
    echo "| $camera camera | $comp | $render | $ratio | $layers | $seen | $cam |"
done
