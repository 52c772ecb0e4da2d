#!/bin/sh
# Instructions per ray of the exact-path benchmarks (bench/general_path_bench.cpp), counted by
# callgrind: only inside the path kernels (make_exact_ray and sample_path for today's closed
# forms, ExactPath::make and sample_exact_path through the common interface), divided by the
# rays built.  Every iteration of those benchmarks traces a whole fan, so every case counts the
# same rays; unlike wall-clock times on a busy machine the counts repeat from run to run (within
# 1 %: how many fans a case runs depends on its speed).  Needs valgrind (Debian package valgrind).
#
#   tools/path_instructions.sh [BUILD_DIR] [BENCHMARK_REGEX]
#   tools/path_instructions.sh build 'road_sampled/18$|road_fitted_sampled/18$'
set -eu
build=${1:-build}
filter=${2:-'BM_ClosedForm|BM_General'}
bench=$build/mirage_bench
[ -x "$bench" ] || { echo "$0: no $bench (build it first)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "$0: valgrind is not installed" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/valgrind_env.sh"
valgrind_env "$bench" "$tmp"

# Collection is toggled on entering and leaving a function, so the names are whole signatures:
# a pattern that also matched a kernel's lambdas would toggle collection off inside them.
closed_build='mirage::make_exact_ray(mirage::Profile const&, double, double)'
closed_sample='mirage::sample_path(mirage::ExactRay const&, mirage::SampleSettings const&)'
general_build='mirage::ExactPath::make(mirage::Atmosphere const&, double, double)'
general_sample='mirage::sample_exact_path(mirage::ExactPath const&, mirage::SampleSettings const&)'

printf '%-55s %12s %8s\n' case instr/ray rays
"$bench" --benchmark_list_tests --benchmark_filter="$filter" | while read -r name; do
    case $name in
    BM_ClosedForm/*) build_fn=$closed_build sample_fn=$closed_sample ;;
    BM_General/*) build_fn=$general_build sample_fn=$general_sample ;;
    *) continue ;;
    esac
    out=$tmp/cg.out
    valgrind --tool=callgrind --callgrind-out-file="$out" \
        --toggle-collect="$build_fn" --toggle-collect="$sample_fn" \
        "$bench" --benchmark_filter="^${name}\$" --benchmark_min_time=0.01 </dev/null >/dev/null 2>&1
    # In the caller tree each function's "*" line follows its callers' "<" lines, which give
    # the number of calls as "(N,NNNx)": the builder's calls from the benchmark body are the rays.
    callgrind_annotate --tree=caller --inclusive=yes --threshold=100 "$out" 2>/dev/null |
        awk -v name="$name" -v builder="$build_fn" '
        /PROGRAM TOTALS/ { gsub(",", "", $1); total = $1 }
        /^ *[0-9,]+ .*< / { caller = $0 }
        /^ *[0-9,]+ .*\* / && index($0, builder) && match(caller, /\([0-9,]+x\)/) {
            n = substr(caller, RSTART + 1, RLENGTH - 3)
            gsub(",", "", n)
            rays = n
        }
        END {
            if (rays == 0) printf "%-55s %12s\n", name, "no rays counted"
            else printf "%-55s %12.0f %8d\n", name, total / rays, rays
        }'
done
