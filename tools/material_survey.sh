#!/bin/bash
# Material survey: renders POV-Ray 3.7's example scenes (Debian's povray-examples, outside
# animations/ and portfolio/) with POV-Ray and with `mirage trace --no-atmosphere`, and
# compares the 8-bit images.  One line per scene in OUT/results.csv:
#   scene,status,psnr_db,first_error
# status: match (PSNR >= 35 dB), differ, trace_failed, trace_timeout, pov_failed.
# POV-Ray's renders are kept (OUT/pov/...) and reused while the scene file is unchanged.
#
#   tools/material_survey.sh [OUT] [W] [H] [FILTER]
#     OUT     default build/material_survey
#     W H     default 160 120
#     FILTER  a grep -E pattern on the scene's path (default: every scene)
# Run from the top of the repository after `make`.  Prints a summary per folder and the
# most common first errors.
set -u
out=${1:-build/material_survey}
mkdir -p "$out" && out=$(cd "$out" && pwd)
W=${2:-160}
H=${3:-120}
filter=${4:-.}
src=/usr/share/povray-3.7/scenes
pov_timeout=${POV_TIMEOUT:-120}
trace_timeout=${TRACE_TIMEOUT:-60}
mirage=$(pwd)/build/mirage
[ -d "$src" ] || { echo "no $src: apt-get install povray-examples" >&2; exit 2; }
[ -x "$mirage" ] || { echo "no $mirage: build first (make)" >&2; exit 2; }
mkdir -p "$out/scenes" "$out/pov" "$out/trace"
# POV-Ray reads and writes only below its working directory (and /tmp): work on a copy.
cp -ru "$src/." "$out/scenes/"
csv=$out/results.csv
echo "scene,status,psnr_db,first_error" >"$csv"
cd "$out/scenes" || exit 2
find . -name '*.pov' | sed 's|^\./||' | grep -v -e '^animations/' -e '^portfolio/' |
    grep -E "$filter" | sort | while read -r scene; do
    dir=$(dirname "$scene")
    name=$(basename "$scene" .pov)
    key=$(echo "$scene" | sed 's|/|__|g; s|\.pov$||')
    pov_png=$out/pov/$key.png
    trace_png=$out/trace/$key.png
    if [ ! -s "$pov_png" ] || [ "$scene" -nt "$pov_png" ]; then
        (cd "$dir" && timeout "$pov_timeout" povray -D -A +FN8 +W"$W" +H"$H" +I"$name.pov" \
            +O"/tmp/material_survey_$$.png" >"/tmp/material_survey_$$.log" 2>&1) &&
            mv "/tmp/material_survey_$$.png" "$pov_png"
        cp "/tmp/material_survey_$$.log" "$out/pov/$key.log" 2>/dev/null
    fi
    if [ ! -s "$pov_png" ]; then
        echo "$scene,pov_failed,," >>"$csv"
        continue
    fi
    rm -f "$trace_png"
    msg=$( (cd "$dir" && timeout "$trace_timeout" "$mirage" trace "$name.pov" -W "$W" -H "$H" \
        --no-atmosphere -q --threads 1 -o "$trace_png") 2>&1)
    rc=$?
    if [ $rc -eq 124 ]; then
        echo "$scene,trace_timeout,," >>"$csv"
        continue
    fi
    if [ $rc -ne 0 ] || [ ! -s "$trace_png" ]; then
        first=$(echo "$msg" | head -1 | sed 's/^mirage trace: //; s/,/;/g; s/"//g' | cut -c1-200)
        echo "$scene,trace_failed,,\"$first\"" >>"$csv"
        continue
    fi
    psnr=$(idiff "$pov_png" "$trace_png" 2>&1 | sed -n 's/.*Peak SNR = \([0-9.inf]*\).*/\1/p')
    [ -z "$psnr" ] && psnr=inf  # idiff prints no PSNR for identical images
    status=$(awk -v p="$psnr" 'BEGIN { print (p == "inf" || p + 0 >= 35) ? "match" : "differ" }')
    echo "$scene,$status,$psnr," >>"$csv"
done
awk -F, 'NR > 1 { split($1, p, "/"); d = p[1]; n[d]++; s[d, $2]++; all[$2]++; t++ }
    END {
        printf "%-12s %6s %6s %6s %8s %8s\n", "folder", "scenes", "match", "differ", "failed", "pov_fail"
        for (d in n) printf "%-12s %6d %6d %6d %8d %8d\n", d, n[d], s[d, "match"], s[d, "differ"],
            s[d, "trace_failed"] + s[d, "trace_timeout"], s[d, "pov_failed"]
        printf "%-12s %6d %6d %6d %8d %8d\n", "all", t, all["match"], all["differ"],
            all["trace_failed"] + all["trace_timeout"], all["pov_failed"]
        printf "match: %.1f %% of all scenes\n", 100 * all["match"] / t
    }' "$csv"
echo "most common first errors:"
grep trace_failed "$csv" | cut -d, -f4- | sed 's/^"[^:]*:[0-9]*:[0-9]*: //; s/"$//' |
    sed "s/'[^']*'/'X'/g" | sort | uniq -c | sort -rn | head -25
