#!/usr/bin/env bash
# Sets up the autograder once, in the student tree (Gradescope runs it as the
# image's setup.sh; CI and a course server run it by hand, as root): installs
# the packages, builds the framework and the stub task modules from the
# student tree alone (no submission is ever linked into them), creates the
# unprivileged user student code runs as, and closes the reference images to
# that user. Grading a submission afterwards only compiles its files
# (run_autograder).
#
# Usage: assignments/autograder/setup_autograder.sh [BUILD_DIR]   (default: build/)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
[ -f "$root/assignments/reference/lib/liblightlab_private.a" ] ||
  { echo "setup_autograder: $root is not a student tree (assignments/make_student_tree.sh makes one)" >&2; exit 2; }
bash "$root/.ci/setup.sh" install
if [ ! -f "$build/CMakeCache.txt" ]; then  # an existing build (the student's own) keeps its settings
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" -DLIGHTLAB_WITH_GUI=OFF \
    -DLIGHTLAB_BUILD_BENCHMARKS=OFF >/dev/null
fi
cmake --build "$build" --target lightlab lightlab_task_tests lightlab_task_modules lightlab_big_meshes -j "$(nproc)"
user=${LIGHTLAB_SANDBOX_USER:-lightlab-sandbox}
if [ "$(id -u)" -eq 0 ]; then
  id -u "$user" >/dev/null 2>&1 ||
    useradd --system --no-create-home --home-dir /nonexistent --shell /usr/sbin/nologin "$user"
  chmod -R o-rwx "$root/data/references"
fi
echo "autograder ready: $build (grade with assignments/autograder/run_autograder ASSIGNMENT SUBMISSION RESULTS)"
