#!/usr/bin/env python3
"""Radiosity against path-traced ground truth, region by region (a measurement, not a CI test).

  python3 tests/bench/radiosity_regions.py data/scenes/cornell_box.json --out out/regions \
      [--spp 2048] [--width 128] [--set name=value ...]

Renders the scene with `path` (the ground truth, cached in OUT by its settings), with `radiosity`
(the given --set; timed), and an object-id mask (every object an emitter of its own id, seen by
`raycast` at pixel centres). For every object that covers at least 30 pixels away from its outline
(the 3x3 neighbourhood all the same object) it prints the mean luminance of both images and their
relative difference, and writes OUT/regions.json.
"""
import argparse, json, os, struct, subprocess, sys, time

def read_pfm(path):
    with open(path, 'rb') as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        channels = 3 if kind == b'PF' else 1
        data = f.read()
    endian = '<' if scale < 0 else '>'
    values = struct.unpack(endian + 'f' * (w * h * channels), data[:4 * w * h * channels])
    return w, h, [values[i * channels:(i + 1) * channels] for i in range(w * h)]

def luminance(c):
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('scene')
    ap.add_argument('--out', required=True)
    ap.add_argument('--spp', type=int, default=2048)
    ap.add_argument('--width', type=int, default=128)
    ap.add_argument('--set', action='append', default=[])
    ap.add_argument('--lightlab', default='build/lightlab')
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    scene = json.load(open(a.scene))
    size = ['--width', str(a.width), '--height', str(a.width)]
    truth = os.path.join(a.out, f'path_{a.width}_{a.spp}.pfm')
    if not os.path.exists(truth):
        subprocess.run([a.lightlab, '--quiet', 'render', a.scene, '-t', 'path', '--spp', str(a.spp), '-o', truth] + size,
                       check=True)
    # The mask: object k emits (k + 1, 0, 0) and reflects nothing.
    mask_scene = dict(scene)
    mask_scene['materials'] = {f'id{k}': {'kd': [0, 0, 0], 'emission': [k + 1, 0, 0]} for k in range(len(scene['objects']))}
    mask_scene['objects'] = [dict(o, material=f'id{k}') for k, o in enumerate(scene['objects'])]
    mask_scene['lights'] = []
    mask_scene['ambient'] = [0, 0, 0]
    mask_json = os.path.join(a.out, 'mask_scene.json')
    json.dump(mask_scene, open(mask_json, 'w'))
    mask = os.path.join(a.out, f'mask_{a.width}.pfm')
    subprocess.run([a.lightlab, '--quiet', 'render', mask_json, '-t', 'raycast', '-o', mask] + size, check=True)
    rad = os.path.join(a.out, 'radiosity.pfm')
    sets = sum((['--set', s] for s in a.set), [])
    t = time.time()
    subprocess.run([a.lightlab, '--quiet', 'render', a.scene, '-t', 'radiosity', '-o', rad] + size + sets, check=True)
    seconds = time.time() - t
    w, h, m = read_pfm(mask)
    _, _, gt = read_pfm(truth)
    _, _, rb = read_pfm(rad)
    ids = [round(c[0]) - 1 for c in m]
    sums = {}
    for y in range(1, h - 1):
        for x in range(1, w - 1):
            k = ids[y * w + x]
            if k < 0 or any(ids[(y + dy) * w + x + dx] != k for dy in (-1, 0, 1) for dx in (-1, 0, 1)):
                continue
            s = sums.setdefault(k, [0, 0.0, 0.0])
            s[0] += 1
            s[1] += luminance(gt[y * w + x])
            s[2] += luminance(rb[y * w + x])
    rows = []
    print(f'radiosity {" ".join(a.set)}: {seconds:.2f} s (render, meshing, form factors and solve)')
    print(f'{"region":24s} {"pixels":>7s} {"path":>9s} {"radiosity":>9s} {"difference":>10s}')
    for k in sorted(sums):
        n, p, r = sums[k]
        if n < 30:
            continue
        name = scene['objects'][k].get('name', f'object {k}')
        d = (r - p) / p if p > 0 else 0.0
        rows.append({'region': name, 'pixels': n, 'path': p / n, 'radiosity': r / n, 'relative_difference': d})
        print(f'{name:24s} {n:7d} {p / n:9.4f} {r / n:9.4f} {100 * d:+9.2f} %')
    json.dump({'scene': a.scene, 'set': a.set, 'seconds': seconds, 'spp': a.spp, 'width': a.width, 'regions': rows},
              open(os.path.join(a.out, 'regions.json'), 'w'), indent=1)

if __name__ == '__main__':
    main()
