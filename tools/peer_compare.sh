#!/bin/sh
# Side by side with the GSL tracer of Wigner-GPU-Lab/numerical-simulate-mirage
# (docs/peer_comparison.md): both trace the same rays through the peer's own temperature models
# (water, conventional and porous asphalt), in one run on this machine; rays per second of each
# at several of its tolerances, and the error of each against the high-precision integration of
# tools/gen_general_paths.py.  Not part of make test (it needs the peer, built from its public
# source outside this repository).
#
#   tools/peer_compare.sh PEER_SOURCE_DIR [PEER_BUILD_DIR] [MIRAGE_BUILD_DIR]
#
# PEER_SOURCE_DIR holds the peer's sources (Eikonal.h, RungeKuttaRayBending.h, ...),
# PEER_BUILD_DIR (default PEER_SOURCE_DIR/build) its built libRungeKuttaRayBendingLib.so,
# MIRAGE_BUILD_DIR (default build) mirage's Release build with mirage and mirage_peer_rays.
# Environment: JOBS (2) for the reference, SECONDS_PER_RUN (1: CPU seconds per timed repetition,
# five repetitions), RAYS (41 elevations per model), OUT (build/peer_compare: every CSV).
set -eu
if [ $# -lt 1 ]; then
    sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'
    exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
peer_src=$(cd "$1" && pwd)
peer_build=$(cd "${2:-$peer_src/build}" && pwd)
mirage_build=$(cd "${3:-$root/build}" && pwd)
jobs=${JOBS:-2}
secs=${SECONDS_PER_RUN:-1}
nrays=${RAYS:-41}
out=${OUT:-$root/build/peer_compare}
mkdir -p "$out"

for f in "$peer_src/RungeKuttaRayBending.h" "$peer_src/Eikonal.h" "$peer_src/OdeSolverGsl.h"; do
    [ -f "$f" ] || { echo "peer_compare.sh: $f missing: give the peer's source directory" >&2; exit 1; }
done
[ -f "$peer_build/libRungeKuttaRayBendingLib.so" ] ||
    { echo "peer_compare.sh: $peer_build/libRungeKuttaRayBendingLib.so missing: build the peer first" >&2; exit 1; }
for f in mirage mirage_peer_rays; do
    [ -x "$mirage_build/$f" ] || { echo "peer_compare.sh: $mirage_build/$f missing: cmake --build $mirage_build" >&2; exit 1; }
done

# The peer's side, compiled against its own headers and library (Eigen 3.4 has the initializer
# lists the peer's eigen-initializer_list plugin adds to 3.3, so the plugin is left out).
eigen_inc=/usr/include/eigen3
[ -d "$peer_src/eigen3" ] && eigen_inc="$peer_src/eigen3"
g++ -O2 -std=c++17 -w -I"$peer_src" -I"$eigen_inc" -o "$out/peer_rays" \
    "$root/tools/peer_compare/peer_rays.cpp" -L"$peer_build" -lRungeKuttaRayBendingLib \
    -lgsl -lgslcblas -Wl,-rpath,"$peer_build"

echo "# peer_compare.sh, $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "# machine: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "# mirage $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?'); peer $(git -C "$peer_src" rev-parse --short HEAD 2>/dev/null || echo "$peer_src")"
echo "# rays per second: CPU time of the tracing thread, median of 5 repetitions of at least $secs s"

# The peer's models (Eikonal.h) with the defaults of its renderer: water 13 degC under air at
# 10 degC, conventional asphalt under air at 20 degC, porous asphalt under air at 38.5 degC;
# as mirage's forms T = T0 + DT exp(-y / H) and n - 1 = 7.86e-4 * 101 / T(K), i.e. Gladstone-Dale
# K = 0.079386 / 288.15 at the isobaric 1013.25 hPa.
gd=$(awk 'BEGIN { printf "%.17g", 0.079386 / 288.15 }')
for case in "water 10 13 10.033 3.15 20.1" "conventional 20 20 20.018 6.37 10.08" \
            "porous 38.5 38.5 38.5127 6.3119 8.35"; do
    set -- $case
    model=$1 t_amb=$2 t_base=$3 t0=$4 dt=$5 decay=$6
    scale=$(awk "BEGIN { printf \"%.17g\", 1 / $decay }")
    # Rays from the peer's default eye (1.1 m) to its default billboard distance (1000 m),
    # elevations evenly from -0.2 to +0.4 degrees: the ground, the mirror image, the direct view.
    rays="$out/${model}_rays.csv"
    awk -v n="$nrays" 'BEGIN { print "case_id,y0,elevation_rad,d";
        for (k = 0; k < n; ++k) { e = -0.2 + 0.6 * k / (n - 1);
            printf "e%+.4f,1.1,%.17g,1000\n", e, e * atan2(0, -1) / 180 } }' > "$rays"
    printf '{"kind": "peer_model", "model": "%s", "temp_amb_c": "%s", "temp_base_c": "%s", "top_m": 4}\n' \
        "$model" "$t_amb" "$t_base" > "$out/${model}_profile.json"
    echo
    echo "## $model: T = $t0 degC + $dt K exp(-$decay y), $nrays rays from 1.1 m to 1000 m"
    files=""
    for tol in 1e-3 1e-6 1e-9 1e-12; do
        f="$out/${model}_peer_$tol.csv"
        r=$("$out/peer_rays" "$model" "$t_amb" "$t_base" "$tol" "$rays" "$f" "$secs")
        echo "peer tol $tol: $r"
        files="$files $f"
    done
    for tol in 1e-8 1e-10 1e-12 1e-14; do
        f="$out/${model}_mirage_$tol.csv"
        r=$("$mirage_build/mirage_peer_rays" "$t0" "$dt" "$scale" "$gd" "$tol" "$rays" "$f" "$secs" | tr '\n' ' ')
        echo "mirage fit $tol: $r"
        files="$files $f"
    done
    # mirage_peer_rays traces what `mirage path --batch` does: the same heights, digit for digit.
    awk -F, 'NR == 1 { print "case_id,y0,i_rad,d1,d2,d3"; next }
        { printf "%s,%s,%.17g,%s,%s,%s\n", $1, $2, atan2(0, -1) / 2 - $3, $4, $4, $4 }' "$rays" > "$out/${model}_batch_in.csv"
    "$mirage_build/mirage" path --air-temperature-c "$t0" --surface-layer "$dt,$scale" --isobaric \
        --gladstone-dale "$gd" --fit-tolerance 1e-10 --batch "$out/${model}_batch_in.csv" > "$out/${model}_batch_out.csv"
    python3 - "$out/${model}_batch_out.csv" "$out/${model}_mirage_1e-10.csv" <<'PY'
import csv, sys
b = {r['case_id']: r for r in csv.DictReader(open(sys.argv[1]))}
worst = 0.0
for r in csv.DictReader(open(sys.argv[2])):
    if r['valid'] == '1':
        worst = max(worst, abs(float(b[r['case_id']]['y_d1']) - float(r['y'])))
    elif b[r['case_id']]['y_d1'] != 'nan':
        sys.exit('mirage path --batch reaches %s, mirage_peer_rays does not' % r['case_id'])
print('mirage path --batch (fit 1e-10) against mirage_peer_rays: largest height difference %.3g m' % worst)
PY
    python3 "$root/tools/peer_compare/reference.py" --jobs "$jobs" --points "$out/${model}_points.csv" \
        "$out/${model}_profile.json" "$rays" $files | tee "$out/${model}_errors.csv"
done
echo
echo "# load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
