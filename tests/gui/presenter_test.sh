#!/usr/bin/env bash
# Presenter mode with real key presses (xdotool under Xvfb): open a deck,
# step with Right, PageDown, space, PageUp and Home as a clicker would, and
# check on F12 screenshots and their sidecars that each arrival applied the
# slide's preset: the panes show what headless renders of the same settings
# show, and what the slide's figure in the HTML build shows.
#   presenter_test.sh LIGHTLAB CHECKER OUT_DIR     (run under xvfb-run)
set -euo pipefail
LL=$1 CHECK=$2 OUT=$3
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
DECK=$HERE/presenter_deck.md
rm -rf "$OUT" && mkdir -p "$OUT" && cd "$OUT"

# Headless references with the presets' settings, and the deck's HTML figures.
cd "$ROOT"
common=(--quiet render data/scenes/cornell_box.json -t raycast -a none --width 160 --height 160 --spp 2)
"$LL" "${common[@]}" --set light_samples=16 -o "$OUT/cornell16.pfm" >/dev/null
"$LL" --quiet render data/scenes/whitted_1980.json -t whitted -a bvh --width 160 --height 120 --spp 1 \
  -o "$OUT/whitted.pfm" >/dev/null
# (--max-width 160: the figure's panes at the GUI's size, not the page's 2x.)
"$LL" --quiet slides build "$DECK" --out "$OUT/html" --max-width 160 >/dev/null
python3 -c "import base64,re,sys; h=open('$OUT/html/presenter_deck.html').read(); \
m=re.search(r'id=\"fig-whitted\" alt=\"[^\"]*\" src=\"data:image/png;base64,([^\"]+)\"', h); \
open('$OUT/figure_whitted.png','wb').write(base64.b64decode(m.group(1)))"
cd "$OUT"

"$LL" gui --slides "$DECK" >gui.log 2>&1 &
gui=$!
trap 'kill $gui 2>/dev/null || true' EXIT
xdotool search --sync --name LightLab >/dev/null

source "$HERE/xdotool_helpers.sh"
slide_is() { echo "j['slides']['index'] == $1 and j['slides']['count'] == 3"; }

# 1. Slide 1 on opening: its preset, both panes finished; pane A is the 16-sample render.
until_shot s1 "$(slide_is 0) and j['slides']['applied'] == 0 and j['scene'].endswith('/cornell_box.json') and $done_both"
"$CHECK" s1.png pane 0 cornell16.pfm
[ "$(q s1.json "'slides.next' in j['widgets'] and j['panes'][1]['params']['light_samples'] == 1")" = True ] \
  || fail "slide 1: no next button or pane B is not the preset's"
echo "ok: slide 1 shows its preset"

# 2. Right arrow: slide 2's preset is applied (another scene, pane B whitted), as headless and as its figure.
key Right
until_shot s2 "$(slide_is 1) and j['slides']['applied'] == 1 and j['scene'].endswith('/whitted_1980.json') and \
[p['technique'] for p in j['panes'][:2]] == ['raycast', 'whitted'] and $done_both"
"$CHECK" s2.png pane 1 whitted.pfm
"$CHECK" s2.png pane 1 figure_whitted.png 0.50617 1   # right half of the figure: 164..324 of 324 columns
"$CHECK" s2.png differs s1.png
echo "ok: Right went to slide 2 and applied its preset"

# 3. PageDown: slide 3 has no preset, so slide 2's view stays. Space at the last slide stays there.
key Next
until_shot s3 "$(slide_is 2) and j['slides']['applied'] == 1 and j['scene'].endswith('/whitted_1980.json') and $done_both"
key space
sleep 0.5
until_shot s3b "$(slide_is 2)"
echo "ok: PageDown to slide 3 kept the view; space at the end stays"

# 4. PageUp back to slide 2, Home back to slide 1: the presets are applied again.
key Prior
until_shot s4 "$(slide_is 1) and j['slides']['applied'] == 1"
key Home
until_shot s5 "$(slide_is 0) and j['slides']['applied'] == 0 and j['scene'].endswith('/cornell_box.json') and $done_both"
"$CHECK" s5.png pane 0 cornell16.pfm
echo "ok: PageUp and Home went back, slide 1's preset applied again"

kill -0 $gui || fail "the GUI died"
echo "presenter mode OK: $OUT"
