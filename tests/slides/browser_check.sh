#!/usr/bin/env bash
# The built pages in a real browser (headless Chromium, no network), at a
# 1920x1080 and a 1280x720 window:
# - the page's own inlined KaTeX typesets every equation (each <x-equation>
#   holds a KaTeX span, none a katex-error), and every figure is an inline PNG;
# - on every slide, no text box (heading, paragraph, list item, equation,
#   typeset formula, code block, table) overlaps a figure's box (its image
#   or caption). Every slide of a page is laid out at once (the page
#   scrolls), so each is measured where it stands: a copy of the page gets a
#   script that, after load, KaTeX and the fonts, compares the
#   getBoundingClientRect boxes (each element's own and its content's, which
#   may overflow it; clipped by any scrolling box around them)
#   and writes the result into the DOM, which --dump-dom prints.
#   browser_check.sh CHROMIUM PAGE.html...
set -euo pipefail
BROWSER=$1; shift
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/measure.html" <<'JS'
<script>
(function () {
  var TEXT = 'h1, h2, h3, h4, h5, h6, p, li, x-equation, .katex .base, pre, table, blockquote';
  var FIGURE = 'figure img, figure figcaption, figure .failed';
  function clip(box, from, stop) {  // box cut by every element from `from` up to `stop` that clips its overflow
    for (var p = from; p && p !== stop; p = p.parentElement) {
      var cs = getComputedStyle(p), pr = p.getBoundingClientRect();
      if (cs.overflowX !== 'visible') { box.l = Math.max(box.l, pr.left); box.r = Math.min(box.r, pr.right); }
      if (cs.overflowY !== 'visible') { box.t = Math.max(box.t, pr.top); box.b = Math.min(box.b, pr.bottom); }
    }
    return box;
  }
  // el's box joined with the boxes of the text inside it (which may overflow it), each cut by what clips it.
  function clipped(el, stop) {
    var r = el.getBoundingClientRect();
    var box = clip({l: r.left, t: r.top, r: r.right, b: r.bottom}, el.parentElement, stop);
    var walk = document.createTreeWalker(el, NodeFilter.SHOW_TEXT), node;
    while ((node = walk.nextNode())) {
      if (!node.textContent.trim()) continue;
      var range = document.createRange(); range.selectNodeContents(node);
      var c = range.getBoundingClientRect();
      if (c.width <= 0 || c.height <= 0) continue;
      var t = clip({l: c.left, t: c.top, r: c.right, b: c.bottom}, node.parentElement, stop);
      if (t.r - t.l <= 0 || t.b - t.t <= 0) continue;
      box = {l: Math.min(box.l, t.l), t: Math.min(box.t, t.t), r: Math.max(box.r, t.r), b: Math.max(box.b, t.b)};
    }
    return box;
  }
  function area(b) { return Math.max(0, b.r - b.l) * Math.max(0, b.b - b.t); }
  function name(el) {
    var s = el.tagName.toLowerCase() + (el.className && typeof el.className === 'string' ? '.' + el.className.split(' ')[0] : '');
    return s + ' "' + (el.textContent || el.getAttribute('alt') || '').replace(/\s+/g, ' ').slice(0, 50) + '"';
  }
  function measure() {
    var out = {window: [window.innerWidth, window.innerHeight], slides: []};
    document.querySelectorAll('section.slide').forEach(function (s) {
      var texts = [], figures = [], overlaps = [];
      s.querySelectorAll(FIGURE).forEach(function (e) { var b = clipped(e, s); if (area(b) > 0) figures.push([e, b]); });
      s.querySelectorAll(TEXT).forEach(function (e) {
        if (e.closest('figure') || e.closest('aside.notes')) return;
        var b = clipped(e, s); if (area(b) > 0) texts.push([e, b]);
      });
      texts.forEach(function (t) {
        figures.forEach(function (f) {
          var i = {l: Math.max(t[1].l, f[1].l), t: Math.max(t[1].t, f[1].t), r: Math.min(t[1].r, f[1].r), b: Math.min(t[1].b, f[1].b)};
          if (i.r - i.l > 0.5 && i.b - i.t > 0.5)
            overlaps.push({text: name(t[0]), figure: name(f[0]), area: Math.round(area(i))});
        });
      });
      out.slides.push({id: s.id, texts: texts.length, figures: figures.length,
                       images: s.querySelectorAll('figure img').length, overlaps: overlaps});
    });
    var r = document.createElement('script');
    r.type = 'application/json'; r.id = 'layout-report'; r.textContent = JSON.stringify(out);
    document.body.appendChild(r);
  }
  window.addEventListener('load', function () {
    var ready = document.fonts && document.fonts.ready ? document.fonts.ready : Promise.resolve();
    ready.then(function () { setTimeout(measure, 300); });
  });
})();
</script>
JS
for page in "$@"; do
  for size in 1920,1080 1280,720; do
    copy="$tmp/$(basename "$page" .html)_${size/,/x}.html"
    cat "$page" "$tmp/measure.html" >"$copy"
    # --virtual-time-budget lets the load handlers and timers run before the DOM is dumped.
    timeout 120 "$BROWSER" --headless --no-sandbox --disable-gpu --no-first-run --user-data-dir="$tmp/profile" \
      --hide-scrollbars --window-size="$size" --virtual-time-budget=15000 --dump-dom "file://$copy" \
      2>/dev/null >"$tmp/dom.html"
    python3 - "$page" "$size" "$tmp/dom.html" <<'PY'
import json, re, sys
page, size, dom = sys.argv[1], sys.argv[2], open(sys.argv[3]).read()
body = dom[dom.find('<body'):]
eqs = re.findall(r'<x-equation[^>]*>(?=(.{0,40}))', body, re.S)
assert eqs, f'{page}: no equations in the browser DOM'
raw = [e for e in eqs if not e.startswith('<span class="katex')]
assert not raw, f'{page}: {len(raw)} of {len(eqs)} equations were not typeset by the browser: {raw[:3]}'
errors = body.count('<span class="katex-error"')
assert errors == 0, f'{page}: {errors} equations show a KaTeX error'
imgs = re.findall(r'<img [^>]*src="([^"]{0,30})', body)
assert all(s.startswith('data:image/png;base64,') for s in imgs), f'{page}: a figure is not an inline PNG'
m = re.search(r'<script type="application/json" id="layout-report">(.*?)</script>', body, re.S)
assert m, f'{page} at {size}: the layout was not measured (no report in the DOM)'
report = json.loads(m.group(1))
slides = report['slides']
assert slides and all(s['texts'] > 0 for s in slides), f'{page} at {size}: a slide shows no text: {slides}'
hidden = [s['id'] for s in slides if s['images'] and not s['figures']]
assert not hidden, f'{page} at {size}: figures not displayed on {hidden}'
bad = [(s['id'], o) for s in slides for o in s['overlaps']]
for sid, o in bad[:12]:
    print(f'OVERLAP {page} at {size} (window {report["window"]}): slide #{sid}: {o["text"]} overlaps {o["figure"]} ({o["area"]} px²)')
assert not bad, f'{page} at {size}: {len(bad)} text boxes overlap a figure on slides {sorted({s for s, _ in bad})}'
print(f'ok: {page} at {size}: {len(eqs)} equations typeset, {len(imgs)} inline figures, '
      f'{sum(s["texts"] for s in slides)} text boxes on {len(slides)} slides clear of every figure')
PY
  done
done
