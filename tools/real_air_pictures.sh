#!/bin/sh
# The pictures of the real-air scenes in docs/: each scene traced by `mirage trace`, beside
# the same scene without the feature it shows, captioned.  Usage: tools/real_air_pictures.sh
# [BUILD_DIR] (default build); writes docs/fata_morgana.png, docs/looming_coast.png and
# docs/hot_road.png.
set -eu
build=${1:-build}
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
caption() {  # IN TEXT OUT
    oiiotool "$1" --text:x=10:y=24:size=18:color=0,0,0:font="$font" "$2" -o "$3"
}
# The same scene with its inversion made negligible (1e-4 K): the standard atmosphere.
standard() {  # SCENE OUT
    sed 's|^#declare Mirage_Inversion  *= <\([0-9]*\), \([0-9]*\), [0-9.]*>;.*|#declare Mirage_Inversion = <\1, \2, 0.0001>;|' "$1" > "$2"
    grep -q '0.0001>' "$2"
}

standard scenes/fata_morgana.pov "$tmp/fata_morgana_standard.pov"
"$build/mirage" trace scenes/fata_morgana.pov -W 900 -H 300 -o "$tmp/fm.png"
"$build/mirage" trace "$tmp/fata_morgana_standard.pov" -W 900 -H 300 -o "$tmp/fm_std.png"
caption "$tmp/fm_std.png" "standard atmosphere: the coast 40 km away from 54 m" "$tmp/a.png"
caption "$tmp/fm.png" "2 K inversion from 50 to 60 m (Young): the Fata Morgana" "$tmp/b.png"
oiiotool "$tmp/a.png" "$tmp/b.png" --mosaic:pad=6 1x2 -o docs/fata_morgana.png

standard scenes/looming_coast.pov "$tmp/looming_coast_standard.pov"
"$build/mirage" trace scenes/looming_coast.pov -W 1000 -H 250 -o "$tmp/lc.png"
"$build/mirage" trace "$tmp/looming_coast_standard.pov" -W 1000 -H 250 -o "$tmp/lc_std.png"
caption "$tmp/lc_std.png" "standard atmosphere: the town 30 km away is below the horizon" "$tmp/a.png"
caption "$tmp/lc.png" "10 K warmer over the lowest 100 m: looming" "$tmp/b.png"
oiiotool "$tmp/a.png" "$tmp/b.png" --mosaic:pad=6 1x2 -o docs/looming_coast.png

"$build/mirage" trace scenes/hot_road.pov -W 960 -H 360 --no-atmosphere -o "$tmp/hr_none.png"
"$build/mirage" trace scenes/hot_road.pov -W 960 -H 360 -o "$tmp/hr.png"
caption "$tmp/hr_none.png" "straight rays" "$tmp/a.png"
caption "$tmp/hr.png" "the sounding scenes/hot_road.csv: 55 degC at the asphalt" "$tmp/b.png"
oiiotool "$tmp/a.png" "$tmp/b.png" --mosaic:pad=6 1x2 -o docs/hot_road.png
