#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine (as root) and for CI:
#   bash .ci/setup.sh demo   install what is missing, build the topocut command alone (Release),
#                            segment a bundled map
#   bash .ci/setup.sh test   install what is missing, build (Release), run the whole test suite
#   bash .ci/setup.sh sanitize
#                            build with AddressSanitizer + UndefinedBehaviorSanitizer (GCC, -O1) in
#                            build-asan and run the whole test suite there
#   bash .ci/setup.sh fuzz SECONDS [TARGET...]
#                            install clang, build the libFuzzer targets (fuzz/) in build-fuzz and run
#                            each for SECONDS (fuzz/run.sh; findings in build-fuzz/findings/)
# BUILD_DIR (default build, build-asan, build-fuzz by mode), JOBS (default: number of cores) and
# TOPOCUT_WERROR (ON: warnings are errors, as .ci/run builds; default OFF) can be set in the environment.
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-demo}"
case "$mode" in
  sanitize) BUILD_DIR="${BUILD_DIR:-build-asan}" ;;
  fuzz) BUILD_DIR="${BUILD_DIR:-build-fuzz}" ;;
  demo|test) BUILD_DIR="${BUILD_DIR:-build}" ;;
  *) echo "usage: bash .ci/setup.sh demo|test|sanitize|fuzz SECONDS [TARGET...]" >&2; exit 2 ;;
esac
JOBS="${JOBS:-$(nproc)}"

packages=(build-essential cmake pkg-config libcgal-dev libopencv-dev libboost-dev
          libboost-program-options-dev libboost-graph-dev nlohmann-json3-dev libyaml-cpp-dev
          libgtest-dev libgmock-dev libbenchmark-dev zlib1g-dev libpng-dev libjpeg62-turbo-dev libtiff-dev
          pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib python3-venv python3-pip)
# ROS 1 from Debian: the node (ros/) and its loopback test (rosmaster, rospy publishing the maps);
# genmsg's generators and the definitions of the messages topocut_msgs uses (ros-*-msgs), from which
# the build generates topocut_msgs; actionlib for the node's action (libactionlib-dev; genaction and
# the actionlib_msgs definitions; python3-actionlib for the example's client); the commands of the
# README's ROS session (roscore and roslaunch, rostopic, rosservice, rosnode, rosmsg/rossrv, rosrun).
packages+=(libroscpp-dev libactionlib-dev libactionlib-msgs-dev python3-actionlib python3-actionlib-msgs
           ros-actionlib-msgs python3-yaml
           libnav-msgs-dev libsensor-msgs-dev libvisualization-msgs-dev libstd-msgs-dev
           libgeometry-msgs-dev python3-rosmaster python3-rospy python3-rosgraph python3-nav-msgs
           python3-sensor-msgs python3-visualization-msgs python3-std-msgs python3-geometry-msgs
           python3-genmsg python3-gencpp python3-genpy ros-std-msgs ros-geometry-msgs ros-nav-msgs ros-sensor-msgs
           python3-roslaunch python3-rostopic python3-rosservice python3-rosnode python3-rosmsg rosbash)
# Only the test suites need these: headless Chromium opens evaluate's report page, shapely and
# networkx take the Python results' to_shapely() / to_networkx(), PIL reads the CLI's label images
# in the ROS node's test.
case "$mode" in
  test|sanitize) packages+=(chromium python3-shapely python3-networkx python3-sklearn python3-xgboost python3-pil) ;;
esac
# libFuzzer comes with clang only; the other modes build with GCC.
[ "$mode" = fuzz ] && packages+=(clang libclang-rt-14-dev)
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

case "$mode" in
  demo)
    # The command and the libraries it links, nothing else (tests, benchmarks, bindings and the node
    # build with the test command, or by name: cmake --build build --target topocut_node).
    echo "== configuring and building the topocut command in $BUILD_DIR (Release, $JOBS jobs)"
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$BUILD_DIR" -j "$JOBS" --target topocut
    ;;
  test)
    echo "== configuring and building in $BUILD_DIR (Release, $JOBS jobs)"
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DTOPOCUT_WERROR="${TOPOCUT_WERROR:-OFF}" >/dev/null
    cmake --build "$BUILD_DIR" -j "$JOBS"
    ;;
  sanitize)
    # -O1 keeps the suite fast enough while the sanitizers still see every access; -g1 gives line
    # numbers in reports. Benchmarks are not built (timings under ASan mean nothing), nor the Python
    # extension (cmake/python.cmake); the tests' own code is compiled at -O0 (CMakeLists.txt).
    echo "== configuring and building in $BUILD_DIR (ASan + UBSan, -O1, $JOBS jobs)"
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
      -DTOPOCUT_SANITIZE=ON -DTOPOCUT_BUILD_BENCHMARKS=OFF -DTOPOCUT_WERROR="${TOPOCUT_WERROR:-OFF}" >/dev/null
    cmake --build "$BUILD_DIR" -j "$JOBS"
    ;;
  fuzz)
    seconds="${2:?usage: bash .ci/setup.sh fuzz SECONDS [TARGET...]}"
    echo "== configuring and building the fuzz targets in $BUILD_DIR (clang, libFuzzer + ASan + UBSan)"
    cmake -S . -B "$BUILD_DIR" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DTOPOCUT_FUZZ=ON -DTOPOCUT_BUILD_TESTS=OFF \
      -DTOPOCUT_BUILD_BENCHMARKS=OFF >/dev/null
    fuzz_targets=()
    for f in fuzz/fuzz_*.cpp; do fuzz_targets+=("$(basename "$f" .cpp)"); done
    cmake --build "$BUILD_DIR" -j "$JOBS" --target "${fuzz_targets[@]}"
    ;;
esac

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
  sanitize)
    cd "$BUILD_DIR"
    # Any sanitizer report fails the test that triggered it.
    export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1}"
    export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
    ctest --output-on-failure -j "$JOBS"
    ;;
  fuzz)
    shift 2
    bash fuzz/run.sh "$seconds" "$BUILD_DIR" "$@"
    ;;
  *)
    echo "usage: bash .ci/setup.sh demo|test|sanitize|fuzz SECONDS [TARGET...]" >&2
    exit 2
    ;;
esac
