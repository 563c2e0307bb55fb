#!/usr/bin/env bash
# The GUI tried as a new user would, with real X input (xdotool under Xvfb):
# open the bunny with two panes, switch to the wipe and drag it, change a
# parameter and see the pane restart, open a broken scene and see the error
# while the previous scene keeps rendering, orbit the camera. Each step is
# checked on the sidecar of an F12 screenshot (where the GUI drew its
# controls, the compare state, pane phases, messages, the camera).
#   walkthrough_test.sh LIGHTLAB OUT_DIR     (run under xvfb-run)
set -euo pipefail
LL=$1 OUT=$2
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
rm -rf "$OUT" && mkdir -p "$OUT" && cd "$OUT"

"$LL" gui --preset "$HERE/walkthrough.json" >gui.log 2>&1 &
gui=$!
trap 'kill $gui 2>/dev/null || true' EXIT
xdotool search --sync --name LightLab >/dev/null

q() { python3 -c "import json,sys; j=json.load(open('$1')); print($2)"; }  # q FILE EXPR
shot() {  # shot NAME: F12, wait for the PNG and its sidecar
  rm -f lightlab_*.png lightlab_*.json
  xdotool mousemove 5 5 key F12
  for _ in $(seq 100); do ls lightlab_*.json >/dev/null 2>&1 && break; sleep 0.1; done
  sleep 0.2
  mv lightlab_*.png "$1.png" && mv lightlab_*.json "$1.json"
}
until_shot() {  # until_shot NAME PYTHON-CONDITION: screenshots until the condition holds (60 s)
  for _ in $(seq 120); do
    shot "$1"
    [ "$(q "$1.json" "$2")" = True ] && return 0
    sleep 0.5
  done
  echo "FAIL: $1: never true: $2"; exit 1
}
centre() { q "$1.json" "' '.join(str(int(v)) for v in (j['widgets']['$2'][0] + j['widgets']['$2'][2] * ${3:-0.5}, j['widgets']['$2'][1] + j['widgets']['$2'][3] / 2))"; }
drag() {  # drag X0 Y0 X1 Y1 in small steps, as a hand would
  xdotool mousemove "$1" "$2" sleep 0.1 mousedown 1 sleep 0.1
  for i in 1 2 3 4 5; do
    xdotool mousemove $(( $1 + ($3 - $1) * i / 5 )) $(( $2 + ($4 - $2) * i / 5 )) sleep 0.05
  done
  xdotool sleep 0.1 mouseup 1
}
done_both="j['panes'][0]['phase'] == 'done' and j['panes'][1]['phase'] == 'done'"

# 1. The bunny opens in two panes; both finish; B names no missing task in the solution build.
until_shot s1 "$done_both"
echo "ok: the bunny rendered in both panes"

# 2. Wipe: click the radio button, then drag the split line from the middle to a quarter.
xdotool mousemove $(centre s1 compare.wipe 0.1) click 1
until_shot s2 "j['compare']['mode'] == 'wipe' and j['compare']['rect'][2] > 0"
read -r x y w h < <(q s2.json "' '.join(str(int(v)) for v in j['compare']['rect'])")
drag $((x + w / 2)) $((y + h / 2)) $((x + w / 4)) $((y + h / 2))
until_shot s3 "abs(j['compare']['wipe'] - 0.25) < 0.03"
echo "ok: the wipe line was dragged to $(q s3.json "round(j['compare']['wipe'], 3)")"

# 3. A parameter: click right of the middle of pane A's light_samples slider (the rect includes the label); A restarts and finishes.
xdotool mousemove $(centre s3 A.param.light_samples 0.6) click 1
until_shot s4 "int(j['panes'][0]['params']['light_samples']) > 16 and $done_both"
echo "ok: light_samples = $(q s4.json "j['panes'][0]['params']['light_samples']"), pane A re-rendered"

# 4. A broken scene: its error is shown, the bunny stays and still renders.
xdotool mousemove $(centre s4 scene.path) click 1 sleep 0.2 keydown ctrl keydown a sleep 0.2 keyup a keyup ctrl
xdotool sleep 0.2 type --delay 10 "$ROOT/data/scenes/tests/bad/unknown_key.json"
xdotool sleep 0.2 mousemove $(centre s4 scene.open) click 1
until_shot s5 "any('unknown_key.json:6:5: unknown key' in m['text'] for m in j['messages'])"
[ "$(q s5.json "j['scene'].endswith('bunny.json')")" = True ] || { echo "FAIL: the bunny was replaced"; exit 1; }
echo "ok: the broken scene was reported and the bunny kept"

# 5. Orbit: a drag over the image turns the camera around its target, at the same distance.
read -r x y w h < <(q s5.json "' '.join(str(int(v)) for v in j['compare']['rect'])")
drag $((x + w * 3 / 4)) $((y + h / 2)) $((x + w * 3 / 4 + 60)) $((y + h / 2 - 20))
until_shot s6 "j['camera']['eye'] != $(q s5.json "j['camera']['eye']") and $done_both"
dist="import math; d=lambda c: math.dist(c['eye'], c['target'])"
python3 -c "$dist; import json; a=json.load(open('s5.json'))['camera']; b=json.load(open('s6.json'))['camera']; assert abs(d(a)-d(b)) < 1e-3*d(a), (a, b)"
echo "ok: the camera orbited; both panes re-rendered"

kill -0 $gui || { echo "FAIL: the GUI died"; cat gui.log; exit 1; }
echo "GUI walkthrough OK: $OUT"
