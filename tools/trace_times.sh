#!/bin/sh
# Times `mirage trace` against plain POV-Ray on the same scenes, in one run: POV-Ray on the
# plain scene (no atmosphere: mirage.inc leaves it out), `mirage trace --no-atmosphere`
# (straight rays) and `mirage trace` (exact curved rays), and, when the binary has it,
# `mirage trace --reference-sampling` (every ray sampled to its tolerance all along, as before
# the sampling near surfaces).  Each figure is the median of RUNS runs: the whole process's
# wall-clock time and processor time (user + system, all threads: on a loaded machine the
# wall clock mostly measures the wait for a core), and for the tracer its tracing time as it
# reports it (wall, and processor time where it reports that).  Prints a markdown table.
# Run from the top of the repository after `make`:
#   tools/trace_times.sh                                  # the three scenes, 640x480 and 1920x1080
#   tools/trace_times.sh "scenes/desert.pov" "640x480"    # one scene, one size
#   RUNS=5 MIRAGE=/path/to/mirage tools/trace_times.sh
#   REFERENCE=no tools/trace_times.sh                     # without the reference sampling's runs
set -eu
scenes=${1:-"scenes/desert.pov scenes/road.pov scenes/looming.pov"}
sizes=${2:-"640x480 1920x1080"}
runs=${RUNS:-3}
mirage=${MIRAGE:-build/mirage}
out=${OUT:-build/times/trace}
mkdir -p "$out"

median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

# "wall cpu" seconds of one povray run: args...
pov_once() {
    /usr/bin/time -f "%e %U %S" -o "$out/time.txt" povray "$@" >"$out/povray.log" 2>&1 ||
        { tail -5 "$out/povray.log" >&2; exit 1; }
    awk '{printf "%.3f %.3f\n", $1, $2 + $3}' "$out/time.txt"
}

# "wall cpu tracing tracing_cpu" seconds of one mirage trace run: args...
trace_once() {
    /usr/bin/time -f "%e %U %S" -o "$out/time.txt" "$mirage" trace "$@" >"$out/trace.log" 2>&1 ||
        { tail -5 "$out/trace.log" >&2; exit 1; }
    tracing=$(grep -o "[0-9.]* s," "$out/trace.log" | head -1 | tr -d ' s,')
    tracing_cpu=$(grep -o "[0-9.]* s CPU" "$out/trace.log" | head -1 | cut -d' ' -f1)
    awk -v t="$tracing" -v c="${tracing_cpu:--}" '{printf "%.3f %.3f %s %s\n", $1, $2 + $3, t, c}' \
        "$out/time.txt"
}

# medians over the runs of "wall cpu tracing tracing_cpu", then segments/ray: args...
trace_median() {
    : >"$out/runs.txt"
    i=0
    while [ $i -lt "$runs" ]; do
        trace_once "$@" >>"$out/runs.txt"
        i=$((i + 1))
    done
    for f in 1 2 3 4; do cut -d' ' -f$f "$out/runs.txt" | median | tr '\n' ' '; done
    grep -o "[0-9.]* segments/ray" "$out/trace.log" | head -1 | cut -d' ' -f1
}

reference=no
if [ "${REFERENCE:-yes}" = yes ] && "$mirage" trace --help 2>/dev/null | grep -q -- --reference-sampling; then
    reference=yes
fi

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"\
    "load average $(cut -d' ' -f1-3 /proc/loadavg); median of $runs runs; seconds, wall / processor"
echo
printf "| scene | size | POV-Ray plain, whole | straight: tracing | whole | curved: tracing |"
printf " whole | segments/ray | curved / straight (tracing) | curved / POV-Ray (whole) |"
[ $reference = yes ] && printf " reference sampling: tracing | whole |"
echo
printf "|---|---|---|---|---|---|---|---|---|---|"
[ $reference = yes ] && printf "%s" "---|---|"
echo
# "a / b" of two "wall cpu" pairs, the ratio of each ("-" where not known)
ratio() { echo "$1 $2 $3 $4" | awk '{
    w = ($3 > 0) ? sprintf("%.1f", $1 / $3) : "-";
    c = ($2 != "-" && $4 != "-" && $4 > 0) ? sprintf("%.1f", $2 / $4) : "-";
    print w " / " c }'; }
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
        pov_wall=$(cut -d' ' -f1 "$out/pov.txt" | median)
        pov_cpu=$(cut -d' ' -f2 "$out/pov.txt" | median)
        set -- $(trace_median "$scene" -W "$W" -H "$H" -o "$out/$name-straight.png" --no-atmosphere)
        s_wall=$1 s_cpu=$2 s_trace=$3 s_tcpu=$4
        set -- $(trace_median "$scene" -W "$W" -H "$H" -o "$out/$name-curved.png")
        c_wall=$1 c_cpu=$2 c_trace=$3 c_tcpu=$4 c_seg=$5
        printf "| %s | %s | %s / %s | %s / %s | %s / %s | %s / %s | %s / %s | %s | %s | %s |" \
            "$name" "$size" "$pov_wall" "$pov_cpu" "$s_trace" "$s_tcpu" "$s_wall" "$s_cpu" \
            "$c_trace" "$c_tcpu" "$c_wall" "$c_cpu" "$c_seg" \
            "$(ratio "$c_trace" "$c_tcpu" "$s_trace" "$s_tcpu")" \
            "$(ratio "$c_wall" "$c_cpu" "$pov_wall" "$pov_cpu")"
        if [ $reference = yes ]; then
            set -- $(trace_median "$scene" -W "$W" -H "$H" -o "$out/$name-reference.png" \
                --reference-sampling)
            printf " %s / %s | %s / %s |" "$3" "$4" "$1" "$2"
        fi
        echo
    done
done
