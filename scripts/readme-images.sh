#!/usr/bin/env bash
# The README's frame pictures, made from the shipped scenes by the program itself, so that they show what it
# draws today: run after a change to the look (and commit the images with it).
#
#   scripts/readme-images.sh [build/linkage]
set -euo pipefail
cd "$(dirname "$0")/.."
linkage=${1:-build/linkage}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# scene, frame, size: docs/images/<scene>-frame<frame>.png
frame() {
  "$linkage" render "scenes/$1.json" --frames "$2" --size "$3" --out "$work/$1" --quiet
  cp "$work/$1/$(printf 'frame_%05d.png' "$2")" "docs/images/$1-frame$2.png"
}
frame masses 300 640x360
frame fan 40 960x540
frame jacobi 240 960x540

# The curvature map of the chart at L = 3 (geometry --maps draws it with gnuplot).
"$linkage" geometry scenes/curvature.json --maps "$work/maps" --quiet
cp "$work/maps/curvature.png" docs/images/curvature-L3.png
echo "readme-images: docs/images/ masses-frame300, fan-frame40, jacobi-frame240, curvature-L3 made by $linkage"
