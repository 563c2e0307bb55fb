#!/usr/bin/env bash
# Dishonest and broken A2 submissions through the autograder (run_autograder) of
# a built student tree: each scores what it deserves -- the stubs 0 -- and none
# can forge a result, outlive the grading or take it down.
#   cheats/<name>/  the submitted files (@RESULTS@ becomes the results folder)
# Usage: autograder_cheats_test.sh STUDENT_TREE WORKDIR   (the tree set up: setup_autograder.sh)
set -euo pipefail
tree=${1:?usage: autograder_cheats_test.sh STUDENT_TREE WORKDIR}
work=${2:?}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
rm -rf "$work"
mkdir -p "$work"
export LIGHTLAB_AUTOGRADER_CCACHE=$work/ccache  # many gradings of the same files: compile each once
sandboxed=0
[ "$(id -u)" -eq 0 ] && sandboxed=1
export LIGHTLAB_SANDBOX_USER=${LIGHTLAB_SANDBOX_USER:-lightlab-sb-cheats}  # its own user: no other grading's processes are killed

submit() {  # NAME: run the autograder on cheats/NAME (or on $work/sub_NAME if it exists)
  local name=$1 sub="$work/sub_$1" res="$work/res_$1"
  if [ ! -d "$sub" ]; then
    mkdir -p "$sub"
    cp -r "$here/cheats/$name/." "$sub/"
  fi
  sed -i "s|@RESULTS@|$res|g" "$sub"/* 2>/dev/null || true
  local start=$SECONDS
  LIGHTLAB_TEST_SECONDS=${LIGHTLAB_TEST_SECONDS:-30} bash "$tree/assignments/autograder/run_autograder" A2 "$sub" "$res" \
    > "$work/$name.log" 2>&1 || { cat "$work/$name.log"; echo "FAIL: $name: run_autograder exited with $?"; exit 1; }
  echo $((SECONDS - start)) > "$work/$name.seconds"
}

expect() {  # NAME PYTHON-CONDITIONS...: check results.json (d), the tests by task (task[id]) and the log
  local name=$1
  shift
  python3 - "$work/res_$name/results.json" "$work/$name.log" "$name" "$@" <<'PY' || { cat "$work/$name.log"; exit 1; }
import json, os, sys
path, log, name, checks = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
if not os.path.exists(path):
    sys.exit(f"FAIL: {name}: no results.json")
d = json.load(open(path))
size = os.path.getsize(path)
task = {}
for t in d["tests"]:
    task.setdefault(t.get("number", "?"), []).append(t)
score = lambda i: sum(t["score"] for t in task.get(i, []))
output = lambda i: "\n".join(t["output"] for t in task.get(i, []))
for c in checks:
    if not eval(c):
        sys.exit(f"FAIL: {name}: {c} does not hold (score {d['score']}; {size} bytes)\n" +
                 "\n".join(f"  {t['number']} {t['name']}: {t['output'][:200]}" for t in d["tests"] if t["status"] != "passed"))
print(f"{name}: {d['score']} points, as it deserves")
PY
}

no_sandbox_process_left() {
  [ "$sandboxed" -eq 1 ] || return 0
  # Zombies (already dead, waiting for a parent that is gone) do not count.
  if ps -o stat= -u "$LIGHTLAB_SANDBOX_USER" 2>/dev/null | grep -qv '^Z'; then
    ps -o pid,stat,etimes,cmd -u "$LIGHTLAB_SANDBOX_USER" | head
    echo "FAIL: $1: processes of the sandbox user outlive the grading"
    exit 1
  fi
}

# 1. Defining the grader's entry point in a student file: the module is rejected at link time.
submit grade_override
expect grade_override 'd["score"] == 0' '"defines and exports ll::grading::grade" in output("A2.1")'

# 2. A results.json forged from an atexit handler: the results folder is not the student's to write.
submit atexit_results
expect atexit_results 'd["score"] == 0' 'len(d["tests"]) > 30'

# 3. A grading.json in the submission: only task files are taken from a submission.
mkdir -p "$work/sub_edited_spec"
cp "$here/cheats/edited_spec/grading.json" "$work/sub_edited_spec/"
unifdef -x 2 -DLIGHTLAB_SOLUTION=0 -o "$work/sub_edited_spec/camera_ray.cpp" "$root/assignments/a2_raycasting/camera_ray.cpp" || true
submit edited_spec
expect edited_spec 'd["score"] == 0' 'len(d["tests"]) > 30'

# 4. A daemon that rewrites results.json after the grading: every process of the sandbox user ends with it.
submit daemon
sleep 12
no_sandbox_process_left daemon
expect daemon 'd["score"] == 0' 'len(d["tests"]) > 30'

# 5. A daemon that rewrites the renders' statistics while they run: no process outlives its render.
submit tamper_outputs
no_sandbox_process_left tamper_outputs
expect tamper_outputs 'd["score"] == 0' '"A2.4 not implemented" in output("A2.4")'

# 6. A2.3 handed in as the framework's own watertight triangle test: 0 on A2.3, saying why.
submit framework_triangle
expect framework_triangle 'score("A2.3") == 0' '"the framework\x27s own answer to A2.3" in output("A2.3")'

# 7. A correct A2.1 that calls exit(0) in one case: that test fails alone, the rest still count.
mkdir -p "$work/sub_exit_early"
unifdef -x 2 -DLIGHTLAB_SOLUTION=1 "$root/assignments/a2_raycasting/camera_ray.cpp" |
  sed 's|^  Ray ray;$|  if (px == 40.0f \&\& py == 30.0f) std::exit(0);  // the test of the centre ray\n  Ray ray;|' |
  sed 's|^#include "a2_tasks.h"$|#include <cstdlib>\n#include "a2_tasks.h"|' > "$work/sub_exit_early/camera_ray.cpp" || true
grep -q 'std::exit(0)' "$work/sub_exit_early/camera_ray.cpp" || { echo "FAIL: could not plant the exit"; exit 1; }
submit exit_early
expect exit_early 'abs(score("A2.1") - 12) < 1e-3' '"a call to exit()" in output("A2.1")' 'd["score"] == 12'

# 8. Fifty forked sleepers: none is left when the autograder returns.
submit forks
no_sandbox_process_left forks
expect forks 'd["score"] == 0'

# 9. An endless, sleeping loop: each test stops at its limit, the grading within its budget.
LIGHTLAB_TEST_SECONDS=4 submit sleep_loop
no_sandbox_process_left sleep_loop
expect sleep_loop 'd["score"] == 0' '"did not finish within 4 s" in output("A2.1")'
[ "$(cat "$work/sleep_loop.seconds")" -lt 120 ] || { echo "FAIL: sleep_loop: grading took $(cat "$work/sleep_loop.seconds") s"; exit 1; }

# 10. 64 MiB on stderr: logs are capped, results.json stays small.
submit stderr_flood
expect stderr_flood 'd["score"] == 0' 'size < 1_000_000'

# 11. A2.2 as a lookup table of the inputs the student's own tests use (seed 1), used only when graded:
# against the seed the student tree shows it would earn points; against the autograder's own, none.
mkdir -p "$work/sub_lookup_table_seen"
cp "$here/cheats/lookup_table/ray_sphere.cpp" "$work/sub_lookup_table_seen/"
LIGHTLAB_GRADING_SEED=1 submit lookup_table_seen
expect lookup_table_seen 'score("A2.2") > 10'
LIGHTLAB_GRADING_SEED=987654 submit lookup_table
expect lookup_table 'd["score"] == 0'

echo "autograder: 11 dishonest or broken submissions score what they deserve; none outlives the grading"
