# Shared helpers of the xdotool GUI tests (sourced, not run). The caller sets
# $gui (the GUI's pid) and works in the folder the GUI writes screenshots to.
#   fail MESSAGE            print, show the GUI's log if it died, exit 1
#   q FILE EXPR             a Python expression over the JSON file as j
#   shot NAME               F12 (again after 30 s), wait for the PNG and its sidecar, keep them as NAME.*
#   until_shot NAME COND [S]  screenshots until COND holds on the sidecar (S seconds, 120)
#   key KEYSYM              one key press, the mouse parked in the corner
#   $done_both              both panes finished all passes, and the pixels on screen are
#                           their last image (display bytes are encoded in the background,
#                           so the sidecar's phase can run ahead of the texture)

fail() { echo "FAIL: $*"; kill -0 "$gui" 2>/dev/null || { echo "the GUI died:"; cat gui.log; }; exit 1; }
q() { python3 -c "import json,sys; j=json.load(open('$1')); print($2)"; }
shot() {
  rm -f lightlab_*.png lightlab_*.json
  kill -0 "$gui" 2>/dev/null || fail "the GUI died before $1"
  # F12, pressed again after 30 s: a GUI still starting on a loaded machine may miss the first.
  for _ in 1 2; do
    xdotool mousemove 5 5 key F12
    for _ in $(seq 300); do ls lightlab_*.json >/dev/null 2>&1 && break; sleep 0.1; done
    ls lightlab_*.json >/dev/null 2>&1 && break
  done
  ls lightlab_*.json >/dev/null 2>&1 || fail "$1: no screenshot after F12 (twice, 60 s)"
  sleep 0.2
  mv lightlab_*.png "$1.png" && mv lightlab_*.json "$1.json"
}
until_shot() {
  local end=$((SECONDS + ${3:-120}))
  while :; do
    shot "$1"
    [ "$(q "$1.json" "$2")" = True ] && return 0
    [ $SECONDS -lt $end ] || fail "$1: never true: $2 (slides: $(q "$1.json" "j.get('slides')"))"
    sleep 0.3
  done
}
key() { xdotool mousemove 5 5 key "$1"; }
done_both="all(p['phase'] == 'done' and p['passes'] == p['total_passes'] and p['on_screen_version'] == p['image_version'] for p in j['panes'][:2])"
