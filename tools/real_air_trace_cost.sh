#!/bin/sh
# What real air costs `mirage trace`: scenes/road.pov traced with its exponential profile
# (the closed forms), with the temperature profile that exponential was fitted to,
# T = 300 K + 20 K exp(-y / 0.3 m), through the general engine (on flat ground, and on the
# curved Earth), and with the sounding scenes/hot_road.csv.  Instructions by valgrind's
# callgrind on one thread (figures other jobs on the machine do not disturb): the run at
# W x H less a 1x1 run of the same scene (parsing, the fit, writing), and the 1x1 run's own
# count beside it.  Usage, from the top of the repository after the build:
#   tools/real_air_trace_cost.sh [W H]      (default 640 480)
set -eu
W=${1:-640}
H=${2:-480}
mirage=${MIRAGE:-build/mirage}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/valgrind_env.sh"
valgrind_env "$mirage" "$tmp"
line='#declare Mirage_Preset    = "hot-road";'
grep -q "$line" scenes/road.pov
variant() {  # NAME REPLACEMENT
    awk -v from="$line" -v to="$2" '$0 == from { print to; next } { print }' scenes/road.pov \
        > "$tmp/$1.pov"
}
cp scenes/hot_road.csv "$tmp/"
cp scenes/road.pov "$tmp/exponential.pov"
variant form_flat '#declare Mirage_Air_Temperature = 300; #declare Mirage_Ground_Temperature = 320; #declare Mirage_Scale_Height = 0.3; #declare Mirage_Lapse = 0; #declare Mirage_Earth_Radius = 0;'
variant form_curved '#declare Mirage_Air_Temperature = 300; #declare Mirage_Ground_Temperature = 320; #declare Mirage_Scale_Height = 0.3; #declare Mirage_Lapse = 0;'
variant sounding '#declare Mirage_Sounding = "hot_road.csv";'

count() {  # SCENE W H
    valgrind --tool=callgrind --callgrind-out-file="$tmp/cg" \
        "$mirage" trace "$1" -W "$2" -H "$3" --threads 1 -o "$tmp/out.png" >"$tmp/log" 2>&1 ||
        { tail -5 "$tmp/log" >&2; exit 1; }
    grep '^summary:' "$tmp/cg" | awk '{print $2}'
}

echo "scenes/road.pov at ${W}x${H}, one thread; instructions (callgrind), millions"
echo
echo "| atmosphere | set-up (1x1 run) | tracing (the run less the 1x1 run) | tracing / exponential |"
echo "|---|---|---|---|"
base=0
for v in exponential form_flat form_curved sounding; do
    one=$(count "$tmp/$v.pov" 1 1)
    all=$(count "$tmp/$v.pov" "$W" "$H")
    trace=$((all - one))
    [ "$base" -eq 0 ] && base=$trace
    echo "$v $one $trace $base" | awk '{printf "| %s | %.1f | %.1f | %.2f |\n", $1, $2 / 1e6, $3 / 1e6, $3 / $4}'
done
