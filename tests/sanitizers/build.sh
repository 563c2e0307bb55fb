#!/usr/bin/env bash
# Usage: build.sh BUILD_DIR [WERROR=ON|OFF]
# The sanitizer build: BUILD_DIR configured with Clang, every library under
# AddressSanitizer + UndefinedBehaviorSanitizer with libFuzzer's coverage
# instrumentation (LIGHTLAB_SANITIZE, LIGHTLAB_FUZZ), assertions on, GUI and
# benchmarks off; builds only the two test programs and the fuzz targets.
set -euo pipefail
build=$1; werror=${2:-OFF}
root=$(cd "$(dirname "$0")/../.." && pwd)
export CCACHE_BASEDIR=$root
# -g1: ccache would hash the working directory into every object (for the debug info's compile directory), so
# no other clone's objects would ever be reused: 450-530 s of compiling on every clean-clone run.
export CCACHE_NOHASHDIR=1
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cxx=$(command -v clang++ || command -v clang++-14)
# -O1: ASan's recommended trade between build time, run time and exact reports; no -DNDEBUG: asserts stay on.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" "${launcher[@]}" \
  -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_FLAGS_SANITIZE="-O1" \
  -DLIGHTLAB_SANITIZE=ON -DLIGHTLAB_FUZZ=ON -DLIGHTLAB_WITH_GUI=OFF -DLIGHTLAB_BUILD_BENCHMARKS=OFF \
  -DLIGHTLAB_WARNINGS_AS_ERRORS="$werror" >/dev/null
cmake --build "$build" -j "$(nproc 2>/dev/null || echo 2)" \
  --target lightlab_tests lightlab_task_tests fuzz_scene_json fuzz_obj_scene fuzz_command_line
