#!/usr/bin/env bash
# `lightlab slides build` of every deck under slides/, at CI size (figures 96
# pixels wide per pane, at most 2 passes), then checks each page on its own
# terms: every ```preset block of the deck's Markdown (counted here, not by
# the builder) has its figure embedded as a decodable PNG under its slide's
# anchor, no figure failed, every slide is a section, the equations are
# KaTeX elements with KaTeX and its fonts inlined, and nothing is loaded from
# the network; and the handouts link to slides that exist.
#   slides_build_test.sh LIGHTLAB OUT_DIR
set -euo pipefail
LL=$1 OUT=$2
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$OUT" && mkdir -p "$OUT"
cd "$ROOT"
"$LL" --quiet slides build --out "$OUT" --max-width 96 --max-spp 2
python3 - "$ROOT/slides" "$OUT" <<'PY'
import base64, glob, json, os, re, sys
slides, out = sys.argv[1], sys.argv[2]
manifest = json.load(open(os.path.join(out, 'figures.json')))
bad = [f for f in manifest if f['error'] or f['png_bytes'] == 0]
assert not bad, 'figures failed: %s' % bad
decks = sorted(p for p in glob.glob(os.path.join(slides, '*.md')) if not p.endswith('README.md'))
assert len(decks) >= 6, decks
total = 0
for deck in decks:
    text = open(deck).read()
    # Independent count: fenced blocks whose info string is "preset", and slides (--- lines outside fences).
    presets, rules, fence = 0, 0, None
    for line in text.splitlines():
        m = re.match(r' {0,3}(`{3,}|~{3,})\s*(\S*)', line)
        if fence is None and m:
            fence = m.group(1)
            presets += m.group(2) == 'preset'
        elif fence is not None and line.strip().startswith(fence) and line.strip() == line.strip()[0] * len(line.strip()):
            fence = None
        elif fence is None and line.strip() == '---':
            rules += 1
    page = os.path.join(out, os.path.basename(deck)[:-3] + '.html')
    html = open(page, encoding='utf-8').read()
    sections = re.findall(r'<section class="slide" id="([^"]+)"', html)
    assert len(sections) == rules + 1, '%s: %d sections for %d slides' % (page, len(sections), rules + 1)
    figures = re.findall(r'<img id="fig-([^"]+)" alt="[^"]*" src="data:image/png;base64,([^"]+)"', html)
    assert len(figures) == presets, '%s: %d figures embedded, the deck has %d preset blocks' % (page, len(figures), presets)
    assert 'figure-failed' not in html, page + ': a figure failed'
    for anchor, data in figures:
        assert anchor in sections, anchor
        png = base64.b64decode(data)
        assert png.startswith(b'\x89PNG\r\n\x1a\n') and len(png) > 200, anchor + ': not a PNG'
    entries = [f for f in manifest if os.path.samefile(f['deck'], deck)]
    assert len(entries) == presets and all(f['width'] > 0 for f in entries), deck
    # Offline: KaTeX and its fonts inlined, nothing fetched.
    assert 'katex.render' in html and 'data:font/woff2;base64,' in html, page + ': KaTeX not inlined'
    assert not re.search(r'(src|href)\s*=\s*["\']?(https?:)?//', html), page + ': loads from the network'
    assert not re.search(r'url\((["\']?)(https?:|//|fonts/)', html), page + ': a font or image outside the page'
    if '$' in text:
        assert '<x-equation' in html, page + ': no equations found'
    total += presets
    print('ok %s: %d slides, %d figures' % (os.path.basename(page), len(sections), presets))
# The handouts' links into the decks name slides that exist.
root = os.path.dirname(slides)
for readme in glob.glob(os.path.join(root, 'assignments', '*', 'README.md')) + [os.path.join(root, 'README.md')]:
    for deck, anchor in re.findall(r'slides/([a-z_]+)\.md(?:#([a-z0-9-]+))?\)', open(readme, encoding='utf-8').read()):
        page = open(os.path.join(out, deck + '.html'), encoding='utf-8').read()
        assert not anchor or 'id="%s"' % anchor in page, '%s links to a missing slide %s#%s' % (readme, deck, anchor)
print('slides build OK: %d figures in %d decks' % (total, len(decks)))
PY
