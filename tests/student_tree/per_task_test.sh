#!/usr/bin/env bash
# Every task graded on its own, through the autograder of a built student tree
# (run_autograder), for one assignment:
#   - the solution's files score full marks;
#   - each task's solution alone scores full marks on that task and 0 on the others;
#   - each planted bug (tests/grading/planted_bugs/<task>-<name>.patch, in an otherwise
#     complete solution) costs points in its own task only, with a message naming it;
#   - the stubs with their LIGHTLAB_TODO line deleted score 0 (no stub holds an answer);
#   - other correct solutions (tests/grading/alternative_solutions/<task>-<name>.cpp) score
#     full marks on their task.
# Usage: per_task_test.sh STUDENT_TREE WORKDIR ASSIGNMENT   (the tree set up: setup_autograder.sh)
set -euo pipefail
tree=${1:?usage: per_task_test.sh STUDENT_TREE WORKDIR ASSIGNMENT}
work=${2:?}
assignment=${3:?}
root=$(cd "$(dirname "$0")/../.." && pwd)
export LIGHTLAB_SANDBOX_USER=${LIGHTLAB_SANDBOX_USER:-lightlab-sb-${assignment,,}}  # its own: gradings run side by side
rm -rf "$work"
mkdir -p "$work"
export LIGHTLAB_AUTOGRADER_CCACHE=$work/ccache  # many gradings of the same files: compile each once
spec=$(grep -l "\"assignment\": \"$assignment\"" "$root"/assignments/*/grading.json | head -1)
folder=$(basename "$(dirname "$spec")")
mapfile -t tasks < <(python3 -c 'import json,sys; [print(t["id"], t["file"], t["points"]) for t in json.load(open(sys.argv[1]))["tasks"]]' "$spec")

solution() {  # FILE DEST: the solution's version of a task file, as a student would hand it in
  unifdef -x 2 -DLIGHTLAB_SOLUTION=1 -o "$2" "$1" || true
}

grade() {  # NAME SUBMISSION_DIR: run the autograder
  bash "$tree/assignments/autograder/run_autograder" "$assignment" "$2" "$work/res_$1" > "$work/$1.log" 2>&1 ||
    { cat "$work/$1.log"; echo "FAIL: $1: run_autograder exited with $?"; exit 1; }
}

# check NAME EXPECTATION...: each "ID=full", "ID=0", "ID<full" (and its messages name ID), "ID=any".
check() {
  local name=$1
  shift
  python3 - "$work/res_$name/results.json" "$name" "$@" <<'PY' || { cat "$work/$name.log"; exit 1; }
import json, sys
d = json.load(open(sys.argv[1]))
name, rules = sys.argv[2], sys.argv[3:]
by = {}
for t in d["tests"]:
    by.setdefault(t["number"], []).append(t)
problems = []
for rule in rules:
    op = "<" if "<" in rule else "="
    task, want = rule.split(op)
    tests = by.get(task, [])
    score, best = sum(t["score"] for t in tests), sum(t["max_score"] for t in tests)
    lost = [t for t in tests if t["score"] < t["max_score"]]
    if want == "any":
        continue
    if op == "=" and want == "full" and (best == 0 or abs(score - best) > 1e-3):
        problems.append(f"{task} scores {score:.4g} of {best:.4g}, not full marks: " +
                        "; ".join(t["name"] + ": " + t["output"].splitlines()[0][:160] for t in lost if t["output"])[:900])
    elif op == "=" and want == "0" and score > 1e-9:
        problems.append(f"{task} scores {score:.4g}, not 0")
    elif op == "<":
        if not lost:
            problems.append(f"{task} keeps full marks")
        elif not any(task in t["output"] for t in lost):
            problems.append(f"no failed test of {task} names {task}")
if problems:
    sys.exit(f"FAIL: {name}:\n  " + "\n  ".join(problems))
print(f"{name}: {d['score']:.4g} points, " + ", ".join(rules))
PY
}

all_full=()
for line in "${tasks[@]}"; do read -r id file points <<< "$line"; all_full+=("$id=full"); done

# The solution's files: full marks.
mkdir -p "$work/sub_solution"
for line in "${tasks[@]}"; do
  read -r id file points <<< "$line"
  solution "$root/assignments/$folder/$file" "$work/sub_solution/$file"
done
grade solution "$work/sub_solution"
check solution "${all_full[@]}"

# Each task's solution alone: full marks there, 0 elsewhere.
for line in "${tasks[@]}"; do
  read -r id file points <<< "$line"
  sub="$work/sub_only_$id"
  mkdir -p "$sub"
  cp "$work/sub_solution/$file" "$sub/"
  rules=()
  for other in "${tasks[@]}"; do
    read -r oid ofile opoints <<< "$other"
    [ "$oid" = "$id" ] && rules+=("$oid=full") || rules+=("$oid=0")
  done
  grade "only_$id" "$sub"
  check "only_$id" "${rules[@]}"
done

# Each planted bug in an otherwise complete solution: points lost in its own task only.
shopt -s nullglob
for p in "$root"/tests/grading/planted_bugs/"$assignment".*.patch; do
  name=$(basename "$p" .patch)
  id=${name%%-*}
  src="$work/patched_$name"
  mkdir -p "$src"
  (cd "$root" && cp --parents "assignments/$folder"/*.cpp "$src/")
  (cd "$src" && patch -s -p1 < "$p")
  sub="$work/sub_$name"
  mkdir -p "$sub"
  rules=()
  for line in "${tasks[@]}"; do
    read -r tid file points <<< "$line"
    solution "$src/assignments/$folder/$file" "$sub/$file"
    [ "$tid" = "$id" ] && rules+=("$tid<full") || rules+=("$tid=full")
  done
  grade "$name" "$sub"
  check "$name" "${rules[@]}"
done

# The stubs without their LIGHTLAB_TODO lines: no stub holds a working answer.
sub="$work/sub_no_todo"
mkdir -p "$sub"
zero=()
for line in "${tasks[@]}"; do
  read -r id file points <<< "$line"
  grep -v 'LIGHTLAB_TODO' "$tree/assignments/$folder/$file" > "$sub/$file"
  zero+=("$id=0")
done
grade no_todo "$sub"
check no_todo "${zero[@]}"

# Other correct solutions: full marks on their task.
for alt in "$root"/tests/grading/alternative_solutions/"$assignment".*.cpp; do
  name=$(basename "$alt" .cpp)
  id=${name%%-*}
  file=$(python3 -c 'import json,sys; print(next(t["file"] for t in json.load(open(sys.argv[1]))["tasks"] if t["id"] == sys.argv[2]))' "$spec" "$id")
  sub="$work/sub_$name"
  mkdir -p "$sub"
  cp "$alt" "$sub/$file"
  grade "$name" "$sub"
  check "$name" "$id=full"
done
echo "$assignment: every task graded on its own; planted bugs cost their own task; stubs hold no answer"
