# Shared helpers of the xdotool GUI tests (sourced, not run). The caller sets
# $gui (the GUI's pid) and works in the folder the GUI writes screenshots to.
#   fail MESSAGE            print, show the GUI's log if it died, exit 1
#   q FILE EXPR             a Python expression over the JSON file as j
#   shot NAME               F12 (again after 30 s), wait for the PNG and its sidecar, keep them as NAME.*
#   until_shot NAME COND [S]  screenshots until COND holds on the sidecar (S seconds, 120)
#   key KEYSYM              one key press, the mouse parked in the corner
#   reveal NAME WIDGET [BOX]  scroll the side panel (or BOX) until WIDGET is wholly in view
#   press X Y               the left button held 0.15 s (a click that no frame can miss)
#   click NAME WIDGET [FRACTION-ACROSS] [BOX]  reveal, then press the widget
#   open_combo NAME WIDGET  click a combo until its list shows (three tries)
#   click_until NAME WIDGET FRACTION COND  click the widget until COND holds (three clicks, 30 s each)
#   pick_until NAME COMBO ITEM COND  click ITEM in COMBO's open list until COND holds (three clicks, 40 s each)
#   state NAME              the panes' techniques, starts and phases and the open lists, from NAME.json
#   $done_both              both panes finished all passes of their last submit, and the pixels
#                           on screen are their last image (display bytes are encoded in the
#                           background, so the sidecar's phase can run ahead of the texture; a
#                           scene loads in the background too, so a pane can be 'done' with the
#                           previous scene until the worker takes the new submit up)

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
# state NAME: what a failure message needs from NAME.json -- each pane's technique, render starts
# and phase, and the lists open -- so that a failure on a loaded CI machine can be read afterwards.
state() { q "$1.json" "'panes ' + str([(p['technique'], p['starts'], p['phase']) for p in j['panes']]) + ', open lists ' + str([k for k in j['widgets'] if k.endswith('.list')])"; }
key() { xdotool mousemove 5 5 key "$1"; }
done_both="all(p['request_current'] and p['phase'] == 'done' and p['passes'] == p['total_passes'] and p['on_screen_version'] == p['image_version'] for p in j['panes'][:2])"
# reveal NAME WIDGET [BOX]: screenshots until WIDGET lies wholly inside BOX (a
# recorded window: the side panel, or an open combo's list), turning the mouse
# wheel over BOX to scroll it there, as a user would.
reveal() {
  local where
  for _ in $(seq 40); do
    shot "$1"
    where=$(q "$1.json" "(lambda r, b: 'missing' if r is None else 'up' if r[1] < b[1] else 'down' if r[1] + r[3] > b[1] + b[3] else 'ok')(j['widgets'].get('$2'), j['widgets']['${3:-panel}'])")
    case $where in
      ok) return 0 ;;
      up) xdotool mousemove $(centre "$1" "${3:-panel}") click 4 ;;
      down) xdotool mousemove $(centre "$1" "${3:-panel}") click 5 ;;
      *) fail "$1: the GUI drew no widget '$2'" ;;
    esac
    sleep 0.2
  done
  fail "$1: could not scroll '$2' into view"
}
centre() { q "$1.json" "' '.join(str(int(v)) for v in (j['widgets']['$2'][0] + j['widgets']['$2'][2] * ${3:-0.5}, j['widgets']['$2'][1] + j['widgets']['$2'][3] / 2))"; }
# press X Y: the left button down, held 0.15 s, then up. A press and release sent at once (xdotool
# click) can fall within one GUI frame on a loaded machine, and the frame sees no click at all.
press() { xdotool mousemove "$1" "$2" sleep 0.2 mousedown 1 sleep 0.15 mouseup 1; }
click() {  # click NAME WIDGET [FRACTION-ACROSS] [BOX]: reveal the widget, then press it
  reveal "$1" "$2" "${4:-panel}"
  press $(centre "$1" "$2" "${3:-0.5}")
}
# open_combo NAME WIDGET: click the combo until its list shows (kept as NAME.*): under a loaded
# CI machine a click on a combo was once not taken up; a user would click again too.
open_combo() {
  local attempt k
  for attempt in 1 2 3; do
    click "$1_click" "$2"
    for k in $(seq 10); do
      shot "$1"
      [ "$(q "$1.json" "'$2.list' in j['widgets']")" = True ] && return 0
      sleep 0.3
    done
  done
  fail "$1: the list of '$2' never opened (three clicks)"
}
# click_until NAME WIDGET FRACTION COND: click the widget (FRACTION across it), then screenshots
# until COND holds on the sidecar (kept as NAME.*); a click that no frame took up on a loaded
# machine is made again, as a user would, three tries of 30 s.
click_until() {
  local attempt end
  for attempt in 1 2 3; do
    click "$1_click" "$2" "$3"
    end=$((SECONDS + 30))
    while [ $SECONDS -lt $end ]; do
      shot "$1"
      [ "$(q "$1.json" "$4")" = True ] && return 0
      sleep 0.3
    done
  done
  fail "$1: never true after three clicks on '$2': $4 (then: $(state "$1"))"
}
# pick_until NAME COMBO ITEM COND: click ITEM in COMBO's open list, then screenshots until COND holds (kept
# as NAME.*); a click that no frame took up on a loaded machine is made again, the list reopened if it
# closed, as a user would: three tries of 40 s.
pick_until() {
  local attempt end
  for attempt in 1 2 3; do
    if [ "$attempt" -gt 1 ]; then
      shot "$1_reopen"
      [ "$(q "$1_reopen.json" "'$2.list' in j['widgets']")" = True ] || open_combo "$1_list" "$2"
    fi
    click "$1_click" "$3" 0.5 "$2.list"
    end=$((SECONDS + 40))
    while [ $SECONDS -lt $end ]; do
      shot "$1"
      [ "$(q "$1.json" "$4")" = True ] && return 0
      sleep 0.3
    done
  done
  fail "$1: never true after three clicks on '$3': $4 (then: $(state "$1"))"
}
