#!/bin/sh
# Instructions `mirage trace` executes to trace a scene, counted by valgrind's callgrind (a
# figure other jobs on the machine do not disturb, unlike wall-clock times): the whole run at
# the size asked for, less a 1x1 run of the same scene (parsing, setting up and writing), on
# one thread.  Prints a markdown table: straight and curved rays, and their ratio.  Run from
# the top of the repository after `make`:
#   tools/trace_instructions.sh                               # the three scenes at 640x480
#   tools/trace_instructions.sh "scenes/desert.pov" "1920x1080"
#   MIRAGE=/path/to/mirage EXTRA="--reference-sampling" tools/trace_instructions.sh
# OUT (default build/times/callgrind) keeps the callgrind files, for callgrind_annotate.
set -eu
scenes=${1:-"scenes/desert.pov scenes/road.pov scenes/looming.pov"}
sizes=${2:-"640x480"}
mirage=${MIRAGE:-build/mirage}
extra=${EXTRA:-}
out=${OUT:-build/times/callgrind}
mkdir -p "$out"
. "$(dirname "$0")/valgrind_env.sh"
valgrind_env "$mirage" "$out"

# instructions of one run: name, then mirage trace arguments
count() {
    name=$1
    shift
    valgrind --tool=callgrind --callgrind-out-file="$out/$name.callgrind" \
        "$mirage" trace "$@" --threads 1 -q >"$out/$name.log" 2>&1 ||
        { tail -5 "$out/$name.log" >&2; exit 1; }
    grep '^summary:' "$out/$name.callgrind" | awk '{print $2}'
}

echo "instructions (callgrind, one thread), tracing only: the run less a 1x1 run; millions"
echo
echo "| scene | size | straight | curved $extra | curved / straight |"
echo "|---|---|---|---|---|"
for scene in $scenes; do
    name=$(basename "$scene" .pov)
    base_s=$(count "$name-1x1-straight" "$scene" -W 1 -H 1 -o "$out/$name.png" --no-atmosphere)
    # shellcheck disable=SC2086
    base_c=$(count "$name-1x1-curved" "$scene" -W 1 -H 1 -o "$out/$name.png" $extra)
    for size in $sizes; do
        W=${size%x*}
        H=${size#*x}
        s=$(count "$name-$size-straight" "$scene" -W "$W" -H "$H" -o "$out/$name.png" \
            --no-atmosphere)
        # shellcheck disable=SC2086
        c=$(count "$name-$size-curved" "$scene" -W "$W" -H "$H" -o "$out/$name.png" $extra)
        echo "$name $size $s $base_s $c $base_c" | awk '{
            s = ($3 - $4) / 1e6; c = ($5 - $6) / 1e6;
            printf "| %s | %s | %.0f | %.0f | %.1f |\n", $1, $2, s, c, c / s }'
    done
done
