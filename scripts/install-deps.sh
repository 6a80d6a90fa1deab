#!/usr/bin/env bash
# Installs the Debian 12 packages sphere-linkages needs, only those that are missing.
# Runs apt-get as root, or through sudo otherwise.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config          # toolchain
  libeigen3-dev libboost-dev                            # linear algebra, AutoDiff, Boost.Odeint
  nlohmann-json3-dev libcli11-dev                       # scene files, command line
  libegl-dev libegl-mesa0 libgl1-mesa-dri python3-glad  # headless GL: EGL on Mesa's llvmpipe, the GL loader
  libosmesa6-dev                                        # headless GL: OSMesa (optional; gone from Mesa 25.1)
  libstb-dev libdeflate-dev libssl-dev                  # fonts/images, PNG deflate, SHA-256
  fonts-dejavu-core ffmpeg                              # the font the frames use, video encoding
  libgtest-dev libbenchmark-dev parallel gnuplot-nox    # tests, benchmarks, sharded renders, charts
  libpng-dev                                            # a second PNG decoder for the tests
  python3-jsonschema                                    # checks scenes/scene.schema.json in the tests
  man-db                                                # the tests read the man page (man -l; groff lints it)
  clang libclang-rt-14-dev                              # fuzzing (libFuzzer) and sanitizer runtimes
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

as_root=()
[ "$(id -u)" -eq 0 ] || as_root=(sudo)
echo "install-deps: installing ${missing[*]}"
"${as_root[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
