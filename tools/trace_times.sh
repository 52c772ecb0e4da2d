#!/bin/sh
# Times `mirage trace` against plain POV-Ray on the same scenes, in one run: POV-Ray on the
# plain scene (no atmosphere: mirage.inc leaves it out), `mirage trace --no-atmosphere`
# (straight rays) and `mirage trace` (exact curved rays), and, when the binary has it,
# `mirage trace --reference-sampling` (every ray sampled to its tolerance all along, as before
# the sampling near surfaces).  Each figure is the median of RUNS runs: the whole process's
# wall-clock time, and for the tracer its tracing time as it reports it.  Prints a markdown
# table.  Run from the top of the repository after `make`:
#   tools/trace_times.sh                                  # the three scenes, 640x480 and 1920x1080
#   tools/trace_times.sh "scenes/desert.pov" "640x480"    # one scene, one size
#   RUNS=5 MIRAGE=/path/to/mirage tools/trace_times.sh
set -eu
scenes=${1:-"scenes/desert.pov scenes/road.pov scenes/looming.pov"}
sizes=${2:-"640x480 1920x1080"}
runs=${RUNS:-3}
mirage=${MIRAGE:-build/mirage}
out=${OUT:-build/times/trace}
mkdir -p "$out"

now() { date +%s.%N; }
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

# wall seconds of one povray run: args...
pov_once() {
    start=$(now)
    povray "$@" >"$out/povray.log" 2>&1 || { tail -5 "$out/povray.log" >&2; exit 1; }
    end=$(now)
    echo "$start $end" | awk '{printf "%.3f\n", $2 - $1}'
}

# "wall tracing" seconds of one mirage trace run: args...
trace_once() {
    start=$(now)
    "$mirage" trace "$@" >"$out/trace.log" 2>&1 || { tail -5 "$out/trace.log" >&2; exit 1; }
    end=$(now)
    tracing=$(grep -o "[0-9.]* s," "$out/trace.log" | head -1 | tr -d ' s,')
    echo "$start $end $tracing" | awk '{printf "%.3f %s\n", $2 - $1, $3}'
}

# median wall and median tracing time over the runs: args...
trace_median() {
    : >"$out/runs.txt"
    i=0
    while [ $i -lt "$runs" ]; do
        trace_once "$@" >>"$out/runs.txt"
        i=$((i + 1))
    done
    wall=$(cut -d' ' -f1 "$out/runs.txt" | median)
    tracing=$(cut -d' ' -f2 "$out/runs.txt" | median)
    segments=$(grep -o "[0-9.]* segments/ray" "$out/trace.log" | head -1 | cut -d' ' -f1)
    echo "$wall $tracing $segments"
}

reference=no
if "$mirage" trace --help 2>/dev/null | grep -q -- --reference-sampling; then reference=yes; fi

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"\
    "load average $(cut -d' ' -f1-3 /proc/loadavg); median of $runs runs; seconds"
echo
printf "| scene | size | POV-Ray plain, wall | straight: tracing | wall | curved: tracing | wall |"
printf " segments/ray | curved / straight (tracing) | curved / POV-Ray (wall) |"
[ $reference = yes ] && printf " reference sampling: tracing | wall |"
echo
printf "|---|---|---|---|---|---|---|---|---|---|"
[ $reference = yes ] && printf "%s" "---|---|"
echo
for scene in $scenes; do
    name=$(basename "$scene" .pov)
    for size in $sizes; do
        W=${size%x*}
        H=${size#*x}
        : >"$out/pov.txt"
        i=0
        while [ $i -lt "$runs" ]; do
            pov_once -D -A +W"$W" +H"$H" +Lpov_includes +O"$out/$name-pov.png" "$scene" \
                >>"$out/pov.txt"
            i=$((i + 1))
        done
        pov=$(median <"$out/pov.txt")
        set -- $(trace_median "$scene" -W "$W" -H "$H" -o "$out/$name-straight.png" --no-atmosphere)
        s_wall=$1 s_trace=$2
        set -- $(trace_median "$scene" -W "$W" -H "$H" -o "$out/$name-curved.png")
        c_wall=$1 c_trace=$2 c_seg=$3
        ratio=$(echo "$c_trace $s_trace" | awk '{printf "%.1f", $1 / $2}')
        vs_pov=$(echo "$c_wall $pov" | awk '{printf "%.2f", $1 / $2}')
        printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" "$name" "$size" "$pov" \
            "$s_trace" "$s_wall" "$c_trace" "$c_wall" "$c_seg" "$ratio" "$vs_pov"
        if [ $reference = yes ]; then
            set -- $(trace_median "$scene" -W "$W" -H "$H" -o "$out/$name-reference.png" \
                --reference-sampling)
            printf " %s | %s |" "$2" "$1"
        fi
        echo
    done
done
