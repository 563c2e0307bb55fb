#!/usr/bin/env bash
# The built pages in a real browser (headless Chromium, no network): the
# page's own inlined KaTeX typesets every equation (each <x-equation> holds a
# KaTeX span, none a katex-error), and every figure is still an inline PNG.
#   browser_check.sh CHROMIUM PAGE.html...
set -euo pipefail
BROWSER=$1; shift
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for page in "$@"; do
  # --virtual-time-budget lets the load handler run before the DOM is dumped.
  timeout 120 "$BROWSER" --headless --no-sandbox --disable-gpu --no-first-run --user-data-dir="$tmp/profile" \
    --virtual-time-budget=10000 --dump-dom "file://$(realpath "$page")" 2>/dev/null >"$tmp/dom.html"
  python3 - "$page" "$tmp/dom.html" <<'PY'
import re, sys
page, dom = sys.argv[1], open(sys.argv[2]).read()
body = dom[dom.find('<body'):]
eqs = re.findall(r'<x-equation[^>]*>(?=(.{0,40}))', body, re.S)
assert eqs, f'{page}: no equations in the browser DOM'
raw = [e for e in eqs if not e.startswith('<span class="katex')]
assert not raw, f'{page}: {len(raw)} of {len(eqs)} equations were not typeset by the browser: {raw[:3]}'
errors = body.count('<span class="katex-error"')
assert errors == 0, f'{page}: {errors} equations show a KaTeX error'
imgs = re.findall(r'<img [^>]*src="([^"]{0,30})', body)
assert all(s.startswith('data:image/png;base64,') for s in imgs), f'{page}: a figure is not an inline PNG'
print(f'ok: {page}: {len(eqs)} equations typeset in the browser, {len(imgs)} inline figures')
PY
done
