#!/usr/bin/env bash
# Benchmark (not a test): save-to-new-image latency of the GUI's hot reload,
# the student's loop. In a built student tree, under Xvfb: the GUI on
# --assignment A2 (the other A2 tasks by their reference, so pane A's picture is
# the student's Blinn-Phong), then ROUNDS saves of blinn_phong.cpp, each a
# one-line change never compiled before (a new constant each round, so the
# compiler really runs; ccache is warm for everything else). Per save:
#   - outside: from the file's write to the GUI's line "new image ..." on stdout
#     (polled every 20 ms), which is printed when every pane has finished its first
#     full pass with the new code;
#   - inside: the GUI's own numbers (build time; latency from seeing the save).
# Prints each round and the median.
#   hot_reload_latency.sh STUDENT_TREE [ROUNDS=6]
set -euo pipefail
tree=$(cd "${1:?usage: hot_reload_latency.sh STUDENT_TREE [ROUNDS]}" && pwd)
rounds=${2:-6}
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
file=$tree/assignments/a2_raycasting/blinn_phong.cpp
cp "$file" "$work/original.cpp"
unifdef -x 2 -DLIGHTLAB_SOLUTION=1 -o "$work/a.cpp" "$root/assignments/a2_raycasting/blinn_phong.cpp" || true
# The one-line change: the same file with one more statement at the top of blinnPhong.
variant() {  # N: the solution plus the line "const float changed = N.<random>f;"
  awk -v n="$1.$RANDOM$RANDOM" '{print} /blinnPhong\(/ && !done {print "  [[maybe_unused]] const float changed = " n "f;"; done=1}' "$work/a.cpp"
}
cleanup() {
  kill "$gui" 2>/dev/null || true
  [ -n "${xvfb:-}" ] && kill "$xvfb" 2>/dev/null || true
  cp "$work/original.cpp" "$file"
  (cd "$tree" && cmake --build build --target lightlab_task_A2_4 > /dev/null 2>&1) || true
  rm -rf "$work"
}
gui=
trap cleanup EXIT
display=:$((90 + RANDOM % 100))
Xvfb "$display" -noreset -screen 0 1600x1000x24 > /dev/null 2>&1 &
xvfb=$!
sleep 1
cp "$work/a.cpp" "$file"
(cd "$tree" && cmake --build build --target lightlab_task_A2_4 > /dev/null)
DISPLAY=$display "$tree/build/lightlab" --reference A2.1,A2.2,A2.3,A2.5 gui --assignment A2 > "$work/gui.log" 2>&1 &
gui=$!
sleep 20  # the window, the scene and the first renders
printf "%-6s %-12s %-12s %-14s\n" round "outside (s)" "build (s)" "GUI: save-to-image (s)"
outside=()
for i in $(seq "$rounds"); do
  before=$(grep -c "new image" "$work/gui.log" || true)
  variant "$i" > "$work/next.cpp"
  t0=$(date +%s.%N)
  cp "$work/next.cpp" "$file"
  for _ in $(seq 3000); do
    [ "$(grep -c "new image" "$work/gui.log" || true)" -gt "$before" ] && break
    sleep 0.02
  done
  t1=$(date +%s.%N)
  line=$(grep "new image" "$work/gui.log" | tail -1)
  gui_latency=$(sed -E 's/.*new image ([0-9.]+) s.*/\1/' <<< "$line")
  build=$(sed -E 's/.*build ([0-9.]+) s.*/\1/' <<< "$line")
  o=$(python3 -c "print(f'{$t1 - $t0:.2f}')")
  outside+=("$o")
  printf "%-6s %-12s %-12s %-14s\n" "$i" "$o" "$build" "$gui_latency"
  sleep 1
done
python3 -c "import statistics,sys; v=[float(x) for x in sys.argv[1:]]; print(f'save-to-new-image: median {statistics.median(v):.2f} s, worst {max(v):.2f} s over {len(v)} saves')" "${outside[@]}"
