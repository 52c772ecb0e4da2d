#!/bin/sh
# Times POV-Ray on a scene three ways: no atmosphere, adaptive layers at a tolerance, and
# Berger's uniform layers at several counts; prints a markdown table with the compile
# report's errors.  Run from the top of the repository after `make`:
#   tools/render_times.sh scenes/desert.pov 640 480 0.5 "16 64 128"
set -eu
scene=$1; W=$2; H=$3; tol=$4; counts=${5:-"16 64 128"}
name=$(basename "$scene" .pov)
out=build/times/$name
mkdir -p "$out"
povtime() {  # seconds of wall time for: povray args...
    start=$(date +%s.%N)
    povray "$@" >"$out/povray.log" 2>&1
    end=$(date +%s.%N)
    level=$(grep -o "Max Level: [0-9]*" "$out/povray.log" | grep -o "[0-9]*$" || echo "?")
    echo "$start $end $level" | awk '{printf "%.2f %s", $2 - $1, $3}'
}
echo "| model | layers | p95 error (px) | max error (px) | POV-Ray time (s) | max trace level |"
echo "|---|---|---|---|---|---|"
set -- $(povtime -D -A +W"$W" +H"$H" +Lpov_includes +O"$out/plain.png" "$scene")
echo "| no atmosphere | 0 | - | - | $1 | $2 |"
build/mirage compile "$scene" -W "$W" -H "$H" --tolerance "$tol" -o "$out/adaptive" \
    --image "$out/adaptive.png" --json >"$out/adaptive.json"
layers=$(grep '"layers"' "$out/adaptive.json" | grep -o "[0-9]*")
p95=$(grep '"p95_error_px"' "$out/adaptive.json" | grep -o "[0-9.e+-]*,$" | tr -d ,)
mx=$(grep '"max_error_px"' "$out/adaptive.json" | head -1 | grep -o "[0-9.e+-]*,$" | tr -d ,)
set -- $(povtime "$out/adaptive/$name.ini")
echo "| adaptive, tolerance $tol px | $layers | $p95 | $mx | $1 | $2 |"
for n in $counts; do
    build/mirage compile "$scene" -W "$W" -H "$H" --layers uniform --count "$n" \
        -o "$out/uniform$n" --image "$out/uniform$n.png" --json >"$out/uniform$n.json"
    p95=$(grep '"p95_error_px"' "$out/uniform$n.json" | grep -o "[0-9.e+-]*,$" | tr -d ,)
    mx=$(grep '"max_error_px"' "$out/uniform$n.json" | head -1 | grep -o "[0-9.e+-]*,$" | tr -d ,)
    set -- $(povtime "$out/uniform$n/$name.ini")
    echo "| uniform (Berger) | $n | $p95 | $mx | $1 | $2 |"
done
