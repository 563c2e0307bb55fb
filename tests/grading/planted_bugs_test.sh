#!/usr/bin/env bash
# The grader catches wrong solutions: every planted_bugs/<task>-<name>.patch
# is a realistic mistake in one task's solution. For each, a copy of the
# tree with that patch applied is rebuilt and graded (that task only), and
# the task must lose points with a message naming it. Usage:
#   planted_bugs_test.sh WORKDIR [PATCH...]   (default: every patch)
set -euo pipefail
work=${1:?usage: planted_bugs_test.sh WORKDIR [PATCH...]}
shift
root=$(cd "$(dirname "$0")/../.." && pwd)
patches=("$@")
[ ${#patches[@]} -gt 0 ] || patches=("$root"/tests/grading/planted_bugs/*.patch)
src="$work/src"  # the build sits in src/build, as the main one does in the root: ccache (CCACHE_BASEDIR) reuses its objects
rm -rf "$work"
mkdir -p "$src"
(cd "$root" && git ls-files -z --cached --others --exclude-standard | xargs -0 cp --parents -t "$src")
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root}
cmake -S "$src" -B "$src/build" -G Ninja "${launcher[@]}" -DLIGHTLAB_WITH_GUI=OFF -DLIGHTLAB_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$src/build" --target lightlab lightlab_task_tests lightlab_big_meshes -j 2 >/dev/null
caught=0
for p in "${patches[@]}"; do
  name=$(basename "$p" .patch)
  task=${name%%-*}
  assignment=${task%%.*}
  (cd "$src" && patch -s -p1 < "$p")
  if ! cmake --build "$src/build" --target lightlab lightlab_task_tests lightlab_big_meshes -j 2 > "$work/$name.build.txt" 2>&1; then
    echo "FAIL: $name does not build"; cat "$work/$name.build.txt"; exit 1
  fi
  "$src/build/lightlab" --quiet grade "$assignment" --task "$task" --format gradescope --report "$work/$name" \
    > "$work/$name.out.txt" 2>&1 || { echo "FAIL: grading $name exited with $?"; cat "$work/$name.out.txt"; exit 1; }
  python3 - "$work/$name/results.json" "$task" "$name" <<'PY'
import json, sys
results, task, name = sys.argv[1], sys.argv[2], sys.argv[3]
d = json.load(open(results))
tests = [t for t in d["tests"] if t["number"] == task]
lost = [t for t in tests if t["score"] < t["max_score"]]
if not lost:
    sys.exit(f"FAIL: {name}: the grader gave {task} full marks")
if not any(task in t["output"] for t in lost):
    sys.exit(f"FAIL: {name}: no failed test's message names {task}")
score = sum(t["score"] for t in tests); best = sum(t["max_score"] for t in tests)
print(f"caught {name}: {task} {score:.4g}/{best:.4g}, {len(lost)} of {len(tests)} tests failed; e.g. {lost[0]['output'].splitlines()[0][:160]}")
PY
  (cd "$src" && patch -s -R -p1 < "$p")
  caught=$((caught + 1))
done
echo "planted bugs: all $caught caught and named"
