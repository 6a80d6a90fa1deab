#!/usr/bin/env bash
# The gallery and the README's pictures, made from the shipped scenes by the program itself, so that they show
# what it draws today: run after a change to the look, and commit the images with it.
#
#   scripts/gallery.sh [build/linkage]
#
# Writes docs/gallery/<scene>.png (a key frame of every scenes/*.json at 640x360, by `linkage still`) and
# docs/gallery/<scene>-dark.png (the same frame in the dark theme, view.theme = dark, for dark slides),
# docs/gallery.md (each picture with one sentence on what to look at) and the README's frame pictures in
# docs/images/. Deterministic: the same program gives the same files. Fails if a shipped scene has no line below.
set -euo pipefail
cd "$(dirname "$0")/.."
linkage=${1:-build/linkage}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# scene <TAB> key time <TAB> what to look at. One line per shipped scene; the one place these sentences live.
scenes=$(cat <<'EOF'
comparison	15	The two published methods drift apart: the divergence plot climbs over decades while both chains, nested in the linkage panel, still look alike.
connect	5	Three force-free motions between the same two shapes, found by shooting and arriving together at t = 6: the shortest is the kinetic distance between the shapes.
curvature	10	The path crosses the colour map of the Gaussian curvature K; the colour bar gives the values.
cut-locus	3.6	A half fan of 48 geodesics from one shape over the distance from it: the two sides of the wavefront meet on the cut locus (white), and the wavefront folds where it touches the conjugate locus (magenta).
default	10	The drag-release geodesic on the configuration sphere beside its four-rod chain, hinge 2 trailing its recent positions.
fan	7	Where K > 0 the fan of 32 geodesics from one start focuses again: the wavefront shrinks to a point.
five-rods	10	Five rods move on S³, drawn in a ball: the distance from the centre is the angle from the start over π.
holonomy	5.9	Three motions end where the next begins, a triangle on the sphere: the arrows carry one vector round it, and the plot climbs to the holonomy, the curvature the triangle holds (angle sum − π = ∫K dA).
jacobi	8	The Jacobi field's zeros are conjugate points: each is marked on the path and written with its time in the plot.
masses-curvature	10	All the mass on the rods: the rods are drawn thick, the massless hinges without balls, over the reshaped curvature.
masses	10	One push, three mass placements, three different paths; ball and rod sizes in the linkage panel show where the mass sits.
massive-rods	10	Rods with mass (thick rods) against the default chain from the same drag-release start: the paths part on the sphere and the divergence plot says how far the two metrics carry the chains apart.
periodic	12	The three simple closed geodesics of the four-rod chain at L = 3, drawn whole as faint curves, each run repeating one, with its length and whether it is stable (elliptic) or not (hyperbolic).
pole-passage	10	Through a pole of the chart: the published method stops (grey, crossed out), chart switching and chart-free carry on.
rope	1	A 200-rod rope whipped by a push near one end: the arrow marks the push in the first frames, the rope fills its panel.
seam	5	Starting on the seam t = π/2: the published run stops at once, as the divergence plot says, while the exact run carries on.
sensitivity	15	A cloud of starts 10⁻⁸ apart spreads at L = 2.01 and stays together at L = 3.
stiffness	10	The ellipses show how stiff the constraints are across the configuration sphere.
EOF
)

# scene, time, size, output file[, more options]: one frame by `linkage still`.
still() {
  "$linkage" still "scenes/$1.json" --time "$2" --size "$3" --out "$4" --quiet "${@:5}"
}

mkdir -p docs/gallery
for file in scenes/*.json; do
  name=$(basename "$file" .json)
  [ "$name" = scene.schema ] && continue
  grep -q "^$name	" <<<"$scenes" || { echo "gallery.sh: no key frame and sentence for $file" >&2; exit 1; }
done
{
  echo "# Gallery"
  echo
  echo "A key frame of every shipped scene (\`scenes/*.json\`) at 640x360, made by \`scripts/gallery.sh\` with"
  echo "\`linkage still\`: rerun it after a change to the look. Render a whole scene with \`linkage render\`. The"
  echo "right-hand picture is the same frame in the dark theme (\`--set view.theme=dark\`), the look for dark slides."
  echo
  echo "| scene | key frame | dark theme | what to look at |"
  echo "|---|---|---|---|"
  while IFS=$'\t' read -r name time sentence; do
    still "$name" "$time" 640x360 "docs/gallery/$name.png"
    still "$name" "$time" 640x360 "docs/gallery/$name-dark.png" --set view.theme=dark
    echo "| [\`$name.json\`](../scenes/$name.json), t = $time | ![$name at t = $time](gallery/$name.png) |" \
      "![$name at t = $time, dark theme](gallery/$name-dark.png) | $sentence |"
  done <<<"$scenes"
} >"$work/gallery.md"
mv "$work/gallery.md" docs/gallery.md

# The README's frame pictures: scene, frame number at the scene's 30 fps, size.
readme() {
  still "$1" "$(awk -v k="$2" 'BEGIN { printf "%.17g", k / 30 }')" "$3" "docs/images/$1-frame$2.png"
}
readme masses 300 640x360
readme fan 40 960x540
readme jacobi 240 960x540
still holonomy 2.5 960x540 docs/images/holonomy-t2.5.png

# The curvature map of the chart at L = 3 (geometry --maps draws it with gnuplot).
"$linkage" geometry scenes/curvature.json --maps "$work/maps" --quiet
cp "$work/maps/curvature.png" docs/images/curvature-L3.png
echo "gallery.sh: docs/gallery.md, docs/gallery/*.png and the README's docs/images/ pictures made by $linkage"
