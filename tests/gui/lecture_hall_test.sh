#!/usr/bin/env bash
# The lecture hall, under Xvfb at 1920x1080 and UI scale 2, with real key
# presses and clicks (xdotool), checked on F12 screenshots and their sidecars:
#   1. presenter mode on the ray-tracing deck's recursion-depth slide: projector
#      labels on by default, one line per pane naming its depth, each covering
#      less than 6 % of its pane; I shows the stats, H hides the slide text;
#   2. the cost-of-accuracy plot (a preset with "plot": true): one falling
#      curve per pane against the reference pane; exported as SVG;
#   3. switching a pane from ray casting to radiosity: at once a neutral
#      placeholder with the phase's name and progress, never the ray-cast picture.
#   lecture_hall_test.sh LIGHTLAB OUT_DIR     (run under xvfb-run at 1920x1080)
set -euo pipefail
LL=$1 OUT=$2
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
rm -rf "$OUT" && mkdir -p "$OUT" && cd "$OUT"
source "$HERE/xdotool_helpers.sh"
gui=
start() { "$LL" gui --window 1920 --window-height 1080 --ui-scale 2 "$@" >gui.log 2>&1 & gui=$!; xdotool search --sync --name LightLab >/dev/null; }
stop() { kill "$gui" 2>/dev/null || true; wait "$gui" 2>/dev/null || true; }
trap stop EXIT
done_all="all(p['phase'] == 'done' and p['on_screen_version'] == p['image_version'] for p in j['panes'][:j['pane_count']])"

# 1. Presenter mode, the recursion-depth slide (the one whose panes differ in max_depth only).
slide=$(python3 - "$ROOT/slides/ray_tracing.md" <<'PY'
import re, sys
slides = re.split(r'\n---\n', open(sys.argv[1]).read())
print(next(i + 1 for i, s in enumerate(slides) if s.count('"max_depth"') == 4))
PY
)
start --slides "$ROOT/slides/ray_tracing.md" --slide "$slide"
labels="['A  depth 0', 'B  depth 1', 'C  depth 2', 'D  depth 5']"
until_shot depth "j['projector']['on'] and j['projector']['labels'] == $labels and $done_all" 300
python3 - depth.json <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j['width'] >= 1900, f"window {j['width']}x{j['height']}: not 1920x1080"
for i, (label, box) in enumerate(zip(j['projector']['labels'], j['projector']['label_rects'])):
    pane = j['panes'][i]['rect']
    share = box[2] * box[3] / (pane[2] * pane[3])
    # One line: the box is no taller than one line of the label font plus its padding (< 2 lines).
    assert box[3] < 0.2 * pane[3], f'{label}: label {box[3]:.0f} px high on a {pane[3]:.0f} px pane'
    assert share < 0.06, f'{label}: covers {100 * share:.1f} % of its pane'
    assert box[0] >= pane[0] - 1 and box[1] >= pane[1] - 1, f'{label}: not on its pane'
    print(f'ok: "{label}" covers {100 * share:.1f} % of its pane ({box[2]:.0f}x{box[3]:.0f} px)')
PY
# I: the stats under the labels; H: the slide text hidden, the panes take the window.
key i
until_shot depth_stats "j['projector']['stats'] and len(j['overlays']) >= 2 * len(j['projector']['labels'])"
key h
until_shot depth_hidden "j['projector']['panel_hidden'] and j['panes'][0]['rect'][0] < 0.1 * j['width']"
key p
until_shot depth_full "not j['projector']['on'] and not j['projector']['labels']"
echo "ok: projector labels at UI scale 2 name each pane's depth on one line; I, H and P work"
stop

# 2. The cost-of-accuracy plot.
start --preset "$HERE/accuracy_plot.json"
until_shot plot "j['plot']['shown'] and j['plot']['rect'][2] > 0 and $done_all" 600
python3 - plot.json <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
for p in j['panes'][:3]:
    h = p['error_history']
    assert len(h) >= 3, f"pane {p['index']}: {len(h)} points on its curve"
    first, last = h[0][1], h[-1][1]
    assert last < 0.7 * first, f"pane {p['index']}: relMSE {first:.3g} -> {last:.3g} does not fall"
    assert all(b[0] > a[0] for a, b in zip(h, h[1:])), f"pane {p['index']}: time does not grow"
    print(f"ok: pane {'ABC'[p['index']]}: {len(h)} points, relMSE {first:.3g} -> {last:.3g} in {h[-1][0]:.2f} s")
assert not j['panes'][3]['error_history'], 'the reference pane has no curve'
PY
stop
echo "ok: the plot shows one falling curve per pane"

# 3. Ray casting -> radiosity: the placeholder with phase and progress at once, never the old picture.
start --preset "$HERE/radiosity_switch.json"
until_shot rc "$done_all and j['panes'][0]['image_shows'] == 'raycast'"
# Every screenshot from the switch on (the pane's technique is radiosity): never the ray-cast picture;
# the first one reporting on the new request (the worker took it up) names its phase. A click on the
# list item that no frame took up (the pane still ray casting and the list closed) is made again, as a
# user would: three tries.
old="j['panes'][0]['technique'] == 'radiosity' and j['panes'][0]['image_on_screen'] and j['panes'][0]['image_shows'] != 'radiosity'"
taken=
for attempt in 1 2 3; do
  open_combo sw2 A.technique
  reveal sw3 A.technique:radiosity A.technique.list
  press $(centre sw3 A.technique:radiosity)
  switched=$SECONDS
  for k in $(seq 100); do
    shot "sw4_$k"
    [ "$(q "sw4_$k.json" "$old")" = False ] || fail "sw4_$k: the ray-cast picture is on screen under radiosity"
    if [ "$(q "sw4_$k.json" "j['panes'][0]['technique'] == 'radiosity'")" = True ]; then
      taken=yes
      [ "$(q "sw4_$k.json" "j['panes'][0]['request_current']")" = True ] && break
    elif [ $k -ge 10 ] || { [ $k -ge 3 ] && [ "$(q "sw4_$k.json" "'A.technique.list' in j['widgets']")" = False ]; }; then
      break  # the click was not taken up: the pane still ray casting, the list closed (or open for 10 shots)
    fi
  done
  [ -n "$taken" ] && break
done
[ -n "$taken" ] || fail "the pane never switched to radiosity (three clicks on the list item)"
n=0
python3 - "sw4_$k.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))['panes'][0]
print(f"first screenshot on the new request: phase '{p['phase_name']}' {p['phase_fraction']:.2f}, {p['elapsed']:.2f} s into it, "
      f"picture on screen: {p['image_on_screen']} ({p['image_shows'] or 'none'})")
assert p['request_current'], 'the worker never took the switch up'
assert p['phase_name'], 'no phase named'
PY
# (the first screenshot on the new request counts: on this machine the default solve takes ~2 s)
phases="|$(q "sw4_$k.json" "j['panes'][0]['phase_name'] + ' ' + format(j['panes'][0]['phase_fraction'], '.2f')")"
while :; do
  n=$((n + 1))
  shot "sw_$n"
  [ "$(q "sw_$n.json" "j['panes'][0]['image_on_screen'] and j['panes'][0]['image_shows'] != 'radiosity'")" = False ] \
    || fail "sw_$n: the previous technique's picture is on screen under radiosity"
  phases="$phases|$(q "sw_$n.json" "j['panes'][0]['phase_name'] + ' ' + format(j['panes'][0]['phase_fraction'], '.2f')")"
  [ "$(q "sw_$n.json" "$done_all")" = True ] && break
  [ $((SECONDS - switched)) -lt 300 ] || fail "radiosity did not finish in 300 s; phases seen: $phases"
done
echo "phases seen: $phases"
# A loaded machine may take longer for one screenshot than the whole solve: the phases the GUI's frames
# drew for this request (phases_drawn in the screenshot's JSON) count too.
drawn="|$(q "sw_$n.json" "'|'.join(j['panes'][0]['phases_drawn'])")"
echo "phases drawn: $drawn"
echo "$phases$drawn" | grep -Eq "form factors[^|]* 0\.[0-9]+|radiosity \(" || fail "no form-factor or solve progress was shown"
echo "ok: the switch to radiosity showed its phases with progress and never the ray-cast picture"
echo "lecture hall OK: $OUT"
