#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine (as root) and for CI:
#   bash .ci/setup.sh demo   install what is missing, build (Release), segment a bundled map
#   bash .ci/setup.sh test   install what is missing, build (Release), run the whole test suite
# BUILD_DIR (default build) and JOBS (default: number of cores) can be set in the environment.
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-demo}"
BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc)}"

packages=(build-essential cmake pkg-config libcgal-dev libopencv-dev libeigen3-dev libboost-dev
          libboost-program-options-dev libboost-graph-dev nlohmann-json3-dev libyaml-cpp-dev
          libgtest-dev libgmock-dev libbenchmark-dev zlib1g-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "== installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

echo "== configuring and building in $BUILD_DIR (Release, $JOBS jobs)"
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD_DIR" -j "$JOBS"

case "$mode" in
  demo)
    mkdir -p out
    "$BUILD_DIR/topocut" segment maps/floorplan.yaml \
      --out-labels out/floorplan_labels.png --out-color out/floorplan_rooms.png \
      --out-json out/floorplan_rooms.json --out-svg out/floorplan_rooms.svg
    echo "== wrote out/floorplan_labels.png (16-bit labels), out/floorplan_rooms.png (overlay),"
    echo "   out/floorplan_rooms.json (rooms and passages), out/floorplan_rooms.svg"
    ;;
  test)
    cd "$BUILD_DIR"
    ctest --output-on-failure -j "$JOBS"
    ;;
  *)
    echo "usage: bash .ci/setup.sh demo|test" >&2
    exit 2
    ;;
esac
