#!/usr/bin/env bash
# The GPU path, measured where there is one (docs/rendering.md, "GL backends"): renders default.json and fan.json
# (64 members) at 1280x720 and 3840x2160 through the GPU (--gl egl-gpu) and through llvmpipe (--gl egl), and
# prints for each: frames per second, CPU seconds per frame, and the share of pixels that differ by more than 3
# levels between the two (a GPU's pixels are not llvmpipe's: never use them for golden frames made on llvmpipe).
#
#   scripts/gpu-check.sh [build/linkage] [FRAMES]      FRAMES: a --frames range, default 0:120
#
# On a machine without a GPU (or without its EGL driver) it says so and exits 0 having drawn nothing.
set -euo pipefail
cd "$(dirname "$0")/.."
linkage=$(realpath "${1:-build/linkage}")
frames=${2:-0:120}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Is there a GPU EGL can draw on? A one-frame still through it answers (and names the renderer).
if ! "$linkage" still scenes/default.json --time 0 --size 160x90 --gl egl-gpu --out "$work/probe.png" \
     > "$work/probe.log" 2>&1; then
  echo "gpu-check: no GPU to draw on here: $(grep -m1 -o 'egl-gpu: .*' "$work/probe.log" || tail -1 "$work/probe.log")"
  echo "gpu-check: nothing measured (on a machine with an NVIDIA GPU, install its driver's EGL library, e.g." \
       "libnvidia-egl / nvidia-driver, and run this again)"
  exit 0
fi
echo "gpu-check: GPU renderer: $(LINKAGE_GL=egl-gpu "$linkage" --version | sed -n 's/^GL renderer: //p')"

printf '%-8s %-10s %-8s %10s %12s %16s\n' scene size backend frames/s "CPU ms/frame" "pixels >3 levels"
for scene in default fan; do
  extra=()
  [[ $scene == fan ]] && extra=(--set 'runs[0].family.count=64')
  for size in 1280x720 3840x2160; do
    for backend in egl egl-gpu; do
      out="$work/$scene-$size-$backend"
      # %e wall, %U + %S CPU of the whole command (simulation, drawing, read-back, PNG, hashes)
      /usr/bin/time -f '%e %U %S' -o "$out.time" "$linkage" render "scenes/$scene.json" "${extra[@]}" \
        --size "$size" --frames "$frames" --gl "$backend" --out "$out" --quiet
      read -r wall user system < "$out.time"
      count=$(grep -c '"frame":' "$out/manifest.json")
      differ=-
      if [[ $backend == egl-gpu ]]; then
        # The worst frame's share of pixels differing beyond 3 levels, against llvmpipe's frames.
        differ=$("$linkage" diff "$work/$scene-$size-egl" "$out" --pixel-tol 3 --max-differing 100 --quiet \
                   | grep -o '[0-9.]*% of' | sort -g | tail -1 | cut -d% -f1 || true)
        differ="${differ:-0}%"
      fi
      awk -v s="$scene" -v z="$size" -v b="$backend" -v n="$count" -v w="$wall" -v u="$user" -v y="$system" \
          -v d="$differ" 'BEGIN { printf "%-8s %-10s %-8s %10.1f %12.2f %16s\n", s, z, b, n / w, 1000 * (u + y) / n, d }'
    done
  done
done
