#!/usr/bin/env bash
# The student tree, made and built once for every student_tree.* test: the
# instructor's make_student_tree.sh from this (solution) tree and its build,
# then what a student runs first (bash .ci/setup.sh build), then the
# autograder's set-up on top (setup_autograder.sh keeps that build).
# Usage: setup.sh SOLUTION_BUILD_DIR WORKDIR    (the tree goes to WORKDIR/tree)
set -euo pipefail
solution_build=${1:?usage: setup.sh SOLUTION_BUILD_DIR WORKDIR}
work=${2:?}
root=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work"
mkdir -p "$work"
bash "$root/assignments/make_student_tree.sh" "$work/tree" "$solution_build"
# ccache (CCACHE_BASEDIR) reuses objects of an earlier student tree at the same place.
export CCACHE_BASEDIR=$work/tree
(cd "$work/tree" && bash .ci/setup.sh build > "$work/build.log" 2>&1) || { tail -60 "$work/build.log"; echo "FAIL: the student tree does not build"; exit 1; }
bash "$work/tree/assignments/autograder/setup_autograder.sh" > "$work/autograder_setup.log" 2>&1 ||
  { tail -30 "$work/autograder_setup.log"; echo "FAIL: the autograder set-up fails in the student tree"; exit 1; }
echo "student tree made and built: $work/tree"
