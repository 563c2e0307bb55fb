#!/usr/bin/env bash
# Edit, save, see -- in the built student tree, as a student would, under Xvfb
# with real X input (xdotool):
#   1. `lightlab gui --assignment A2` opens on A2's preset: pane A ray casts with
#      the student's own intersection (its caption names A2.2 and A2.3 as theirs),
#      the stubs' banner is one line under the picture (never over it), and a
#      click unfolds it;
#   2. with every other A2 task by its reference, the stub's magenta stripes show;
#      saving the solution of blinn_phong.cpp rebuilds and reloads it in the
#      running window: the stripes are gone and the picture is lit;
#   3. saving a syntax error shows the compiler's first error (file:line) in the
#      window while the last good picture stays;
#   4. a segfault in the student's function stops pane A with a message naming
#      A2.4, and the window stays up;
#   5. fixing it shows the picture again;
#   6. `lightlab grade A2` grades the files as saved (a compile error as such, then the
#      solution with full marks), with the default, relative report folder.
# The stub is restored (and rebuilt) at the end.
# Usage: hot_reload_test.sh STUDENT_TREE WORKDIR SCREENSHOT_CHECK    (run under xvfb-run)
set -euo pipefail
tree=${1:?usage: hot_reload_test.sh STUDENT_TREE WORKDIR SCREENSHOT_CHECK}
work=${2:?}
check=${3:?}
root=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"
file=$tree/assignments/a2_raycasting/blinn_phong.cpp
cp "$file" stub.cpp
unifdef -x 2 -DLIGHTLAB_SOLUTION=1 -o solution.cpp "$root/assignments/a2_raycasting/blinn_phong.cpp" || true
grep -q LIGHTLAB_TODO solution.cpp && { echo "FAIL: the solution of blinn_phong.cpp still holds its stub"; exit 1; }

gui=
source "$root/tests/gui/xdotool_helpers.sh"
restore() {
  [ -n "$gui" ] && kill "$gui" 2>/dev/null || true
  cp stub.cpp "$file"
  (cd "$tree" && cmake --build build --target lightlab_task_A2_4 > restore.log 2>&1) || true
}
trap restore EXIT
start_gui() {  # ARGS...: the GUI from the tree's build, screenshots (F12) written here
  "$tree/build/lightlab" "$@" > gui.log 2>&1 &
  gui=$!
  xdotool search --sync --name LightLab > /dev/null
}
magenta() { "$check" "$1.png" magenta 0; }
save() {  # SOURCE: the student saves blinn_phong.cpp (a new modification time, as an editor gives)
  cp "$1" "$file"
  touch "$file"
}
pane_a_done="j['panes'][0]['phase'] == 'done' and j['panes'][0]['passes'] == j['panes'][0]['total_passes'] and j['panes'][0]['on_screen_version'] == j['panes'][0]['image_version']"

# 1. The A2 defaults run the student's intersection, and say so; the banner is one line, under the picture.
start_gui gui --assignment A2 --ui-scale 2 --window 1600 --window-height 1000
until_shot s1 "j['assignment'] == 'A2' and j['reload']['phase'] == 'watching' and $done_both" 240
python3 - s1.json <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
a = j["panes"][0]
ran = a["tasks_ran"]
assert a["technique"] == "raycast" and a["accelerator"] == "none", f"pane A is {a['technique']} / {a['accelerator']}"
# The Cornell box is all triangles: the student's A2.3 runs (A2.2 would for spheres); none is the reference.
assert ran.get("A2.3") is False, f"pane A does not run the student's A2.3: tasks_ran = {ran}"
assert not any(ran.values()), f"pane A runs a task by its reference: {ran}"
banner = j["widgets"].get("pane.A.banner")
assert banner, "pane A has no task banner although every A2 task is a stub"
r = a["rect"]
assert banner[1] >= r[1] + r[3] - 0.5, f"the banner {banner} covers the picture {r}"
assert banner[3] < 2.2 * 15 * 2, f"the banner is {banner[3]:.0f} px high: more than one line at UI scale 2"
assert all(t.startswith("A2.") for t in a["missing_tasks"]), a["missing_tasks"]
print("ok: pane A ray casts with the student's A2.2/A2.3 (caption), the banner is one line under the picture")
PY
folded=$(q s1.json "j['widgets']['pane.A.banner'][3]")
unfolded="j['widgets'].get('pane.A.banner', [0, 0, 0, 0])[3] > 1.5 * $folded"
for attempt in 1 2 3; do  # a click no frame took up (a loaded machine) is made again, as a user would
  press $(q s1.json "' '.join(str(int(v)) for v in (j['widgets']['pane.A.banner'][0] + 20, j['widgets']['pane.A.banner'][1] + j['widgets']['pane.A.banner'][3] / 2))")
  for _ in $(seq 20); do shot s1b; [ "$(q s1b.json "$unfolded")" = True ] && break 2; sleep 0.3; done
done
[ "$(q s1b.json "$unfolded")" = True ] || fail "s1b: three clicks did not unfold the banner"
echo "ok: a click unfolds the banner (one line per task)"
kill "$gui"; wait "$gui" 2>/dev/null || true

# 2. Only A2.4 the student's: stub (magenta), then the solution, saved while the window runs.
start_gui --reference A2.1,A2.2,A2.3,A2.5 gui --assignment A2 --ui-scale 2 --window 1600 --window-height 1000
until_shot s2 "j['reload']['phase'] == 'watching' and $pane_a_done and 'A2.4' in j['panes'][0]['missing_tasks']" 240
m=$(magenta s2)
python3 -c "import sys; sys.exit(0 if $m > 0.05 else 1)" || fail "the stub's picture is not striped magenta ($m)"
echo "ok: the stub's picture is striped magenta ($m of pane A)"
save solution.cpp
until_shot s3 "j['reload']['reloads'] >= 1 and j['reload']['latency_seconds'] > 0 and $pane_a_done and not j['panes'][0]['missing_tasks']" 300
m=$(magenta s3)
python3 -c "import sys; sys.exit(0 if $m < 0.01 else 1)" || fail "after the reload pane A still shows magenta ($m)"
"$check" s3.png differs s2.png
echo "ok: saved, rebuilt and reloaded in $(q s3.json "round(j['reload']['latency_seconds'], 1)") s: lit, no stripes"

# 3. A syntax error: the error in the window, the last good picture stays.
awk '{print} /blinnPhong\(/ && !done {print "  this is not C++;"; done=1}' solution.cpp > broken.cpp
line=$(grep -n "this is not C++" broken.cpp | cut -d: -f1)
[ -n "$line" ] || fail "could not plant the syntax error"
starts=$(q s3.json "j['panes'][0]['starts']")
save broken.cpp
until_shot s4 "j['reload']['phase'] == 'failed'" 300
q s4.json "j['reload']['error']" | grep -q "blinn_phong.cpp:$line:" || fail "the window shows '$(q s4.json "j['reload']['error']")', not blinn_phong.cpp:$line"
[ "$(q s4.json "'reload.error' in j['widgets'] and j['panes'][0]['starts'] == $starts and j['panes'][0]['phase'] == 'done'")" = True ] ||
  fail "after the failed build pane A restarted or the error is not drawn"
m=$(magenta s4)
python3 -c "import sys; sys.exit(0 if $m < 0.01 else 1)" || fail "the last good picture is gone ($m magenta)"
echo "ok: the build error is shown ($(q s4.json "j['reload']['error']")) and the last picture stays"

# 4. A crash in the student's code stops the pane, not the window.
awk '{print} /blinnPhong\(/ && !done {print "  volatile int* volatile nowhere = nullptr;  // volatile: the store cannot be optimised away"; print "  *nowhere = 1;"; done=1}' solution.cpp > crash.cpp
save crash.cpp
until_shot s5 "j['reload']['reloads'] >= 2 and j['panes'][0]['phase'] == 'failed'" 300
q s5.json "j['panes'][0]['error']" | grep -q "A2.4.*crashed" || fail "pane A's error does not name A2.4's crash: $(q s5.json "j['panes'][0]['error']")"
# The side panel still knows the pane ran A2.4 (it said "not run by these panes" after a crash).
[ "$(q s5.json "'A2.4' in j['panes'][0]['tasks_ran']")" = True ] ||
  fail "after the crash pane A's tasks_ran lost A2.4: $(q s5.json "j['panes'][0]['tasks_ran']")"
echo "ok: a segfault in blinnPhong stopped pane A only: $(q s5.json "j['panes'][0]['error']")"

# 5. Fixed again: the picture is back.
save solution.cpp
until_shot s6 "j['reload']['reloads'] >= 3 and $pane_a_done" 300
m=$(magenta s6)
python3 -c "import sys; sys.exit(0 if $m < 0.01 else 1)" || fail "after the fix pane A shows magenta ($m)"
echo "ok: fixed and saved: the picture is back"

# 6. Grading, the handout's way (from the tree's root, the default report folder out/grade/A2): the code
#    as saved, not its last build. A syntax error saved with no window open is graded as not compiling;
#    the solution saved then scores full marks, its reference images included.
kill "$gui"; wait "$gui" 2>/dev/null || true
gui=
graded() {  # NAME: grade A2.4 as a student would, the text report kept as NAME.txt
  (cd "$tree" && build/lightlab --quiet grade A2 --task A2.4) > "$1.txt" 2>&1 ||
    { cat "$1.txt"; echo "FAIL: grading exited with $?"; exit 1; }
}
save broken.cpp
graded grade_broken
grep -q "does not compile: .*blinn_phong.cpp:$line:" grade_broken.txt ||
  { cat grade_broken.txt; echo "FAIL: the grade does not say that blinn_phong.cpp:$line does not compile"; exit 1; }
echo "ok: grade rebuilt the saved file first and reports its compile error"
save solution.cpp
graded grade_solution
python3 - "$tree/out/grade/A2/results.json" grade_solution.txt <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
tests = [t for t in d["tests"] if t["number"] == "A2.4"]
lost = [t["name"] + ": " + (t["output"].splitlines() or [""])[0] for t in tests if t["score"] < t["max_score"]]
if not tests or lost or not any(" image " in t["name"] for t in tests):
    sys.exit(open(sys.argv[2]).read() + f"\nFAIL: the saved solution of A2.4 does not score full marks with its images: {lost}")
print(f"ok: the saved solution graded in the default report folder: A2.4 full marks over {len(tests)} checks, images included")
PY
