#!/usr/bin/env bash
# LightLab set-up: installs what is missing (Debian packages, as root), builds,
# and then either runs the main job or the whole test suite.
#
#   bash .ci/setup.sh run    # the GUI on the Cornell box when a display exists,
#                            # else a headless render whose path is printed
#   bash .ci/setup.sh test   # the whole test suite (ctest, in parallel)
#   bash .ci/setup.sh build  # install + build only
#   bash .ci/setup.sh install  # install the packages only
set -euo pipefail
mode=${1:-run}
root=$(cd "$(dirname "$0")/.." && pwd)
build=${LIGHTLAB_BUILD_DIR:-$root/build}
jobs=$(nproc 2>/dev/null || echo 2)

packages=(
  build-essential cmake ninja-build ccache pkg-config git patch python3 python3-jsonschema
  libglfw3-dev libimgui-dev libglm-dev libstb-dev libopenmesh-dev libtinyobjloader-dev libeigen3-dev
  nlohmann-json3-dev libcli11-dev libtbb-dev libgtest-dev libbenchmark-dev libembree-dev
  libmd4c-dev libmd4c-html0-dev libjs-katex chromium  # chromium: the slides' browser test
  unifdef xvfb xauth xdotool libgl1-mesa-dri fonts-dejavu-core
  clang-14 libclang-rt-14-dev llvm-14  # the sanitizer build and libFuzzer (runtimes; llvm-symbolizer for reports)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

[ "$mode" = install ] && exit 0

# Copies of the tree that the tests build (student tree, planted bugs) sit at
# <copy>/build like this one at <root>/build: relative paths make ccache reuse objects.
export CCACHE_BASEDIR=$root
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
  -DLIGHTLAB_WARNINGS_AS_ERRORS=$werror >/dev/null
cmake --build "$build" -j "$jobs"

case "$mode" in
  build) ;;
  test)
    cd "$build"
    ctest --output-on-failure -j "$jobs" --timeout 1500
    ;;
  run)
    scene="$root/data/scenes/cornell_box.json"
    if [ -n "${DISPLAY:-}" ] && "$build/lightlab" --help 2>/dev/null | grep -q '^\s*gui'; then
      cd "$root"  # the GUI lists the scenes under data/scenes
      exec "$build/lightlab" gui "$scene"
    fi
    out="$root/out/cornell_box.png"
    mkdir -p "$(dirname "$out")"
    "$build/lightlab" render "$scene" -t raycast -o "$out" --spp 4
    echo "Cornell box rendered to $out"
    ;;
  *) echo "usage: bash .ci/setup.sh [run|test|build]" >&2; exit 2 ;;
esac
