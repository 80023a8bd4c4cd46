#!/usr/bin/python3
"""Babylon.js's shipped BRDF textures, and the babylon preset's, read as Babylon reads them,
against exact values at Babylon's texels (docs/presets.md, "The engines' own tables, measured").

Usage:
    /usr/bin/python3 tools/measure_peer_babylon.py tests/data/presets/babylon build/lutbake [PRESET_DIR]

The first directory holds Babylon's three PNGs (decoded from @babylonjs/core 9.35.0
Misc/brdfTextureTools.js; README.md there) and Zeltner's table (zeltner_ltc_volume.csv).
PRESET_DIR, if given, is the output of `lutbake bake --preset babylon`; its PNGs are measured
the same way. Conventions (src/presets/babylon.cpp): x = NdotV, y = perceptualRoughness at texel
centres, PNG row 0 = y of 0.5 / N; fromRGBD: value = (byte / 255)^2.2 / (alpha / 255) (an RGB
PNG has alpha 255). BRDF: R = B, G = E, B = sheen E (Charlie D, Ashikhmin V, alpha = r^2);
OpenPBR: R = B, G = E, B = 16 C (f82); fuzz: x = Zeltner's alpha, y = NdotV, channels mapped
to a in [0.005, 0.88], b in [-0.18, 0.002], R in [0, 0.75], compared with Zeltner's table
bilinear at the coordinates the lookup samples. Exact values from `lutbake eval` (dfg, sheen_E,
f82). Needs numpy; about 10 s.
"""
import csv
import json
import os
import struct
import subprocess
import sys
import zlib

import numpy as np


def read_png(path):
    """8-bit grey/RGB/RGBA PNG -> uint8 array (rows, columns, channels); all five filters."""
    data = open(path, 'rb').read()
    at, idat = 8, b''
    while at < len(data):
        n, kind = struct.unpack('>I4s', data[at:at + 8])
        body = data[at + 8:at + 8 + n]
        if kind == b'IHDR':
            width, height, bits, colour = struct.unpack('>IIBB', body[:10])
        elif kind == b'IDAT':
            idat += body
        at += 12 + n
    assert bits == 8, path
    channels = {0: 1, 2: 3, 6: 4}[colour]
    raw = zlib.decompress(idat)
    stride = width * channels
    out = np.zeros((height, stride), np.int32)
    previous = np.zeros(stride, np.int32)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = np.frombuffer(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)], np.uint8).astype(np.int32)
        row = np.zeros(stride, np.int32)
        for i in range(stride):
            a = row[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 0:
                p = 0
            elif kind == 1:
                p = a
            elif kind == 2:
                p = b
            elif kind == 3:
                p = (a + b) // 2
            else:
                q = a + b - c
                p = a if abs(q - a) <= abs(q - b) and abs(q - a) <= abs(q - c) else (b if abs(q - b) <= abs(q - c) else c)
            row[i] = (line[i] + p) & 255
        out[y] = row
        previous = row
    return out.reshape(height, width, channels)


def from_rgbd(img):
    rgb = img[..., :3] / 255.0
    alpha = img[..., 3:4] / 255.0 if img.shape[2] == 4 else 1.0
    return rgb ** 2.2 / alpha


def evaluate(lutbake, table, n, extra=()):
    """lutbake eval at the n x n texel centres: array [y = roughness][x = mu][value(s)]."""
    centres = [(i + 0.5) / n for i in range(n)]
    out = np.zeros((n, n, 2))
    for k in range(0, n, 64):
        cmd = [lutbake, 'eval', '--table', table, '--mu', ','.join(repr(m) for m in centres),
               '--roughness', ','.join(repr(r) for r in centres[k:k + 64]), '--json', *extra]
        text = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
        for line in text.splitlines():
            p = json.loads(line)
            i, j = round(p['mu'] * n - 0.5), round(p['roughness'] * n - 0.5)
            v = p['value']
            out[j, i] = v if isinstance(v, list) else [v, 0.0]
    return out


def report(name, diff, where):
    d = np.abs(diff)
    j, i = np.unravel_index(np.argmax(d), d.shape)
    print(f'| {name} | {d.max():.2e} | {np.sqrt(np.mean(d * d)):.2e} | {where(i, j)} |')


def zeltner_at_centres(path):
    t = np.zeros((32, 32, 3))
    with open(path) as f:
        for row in csv.DictReader(line for line in f if not line.startswith('#')):
            t[int(row['i']), int(row['j'])] = [float(row['a']), float(row['b']), float(row['R'])]
    c = (np.arange(32) + 0.5) / 32 * 31
    i0 = np.minimum(np.floor(c).astype(int), 30)
    f = c - i0
    # out[y = cos index][x = alpha index]
    out = np.zeros((32, 32, 3))
    for y in range(32):
        for x in range(32):
            a, b, fa, fb = i0[x], i0[y], f[x], f[y]
            out[y, x] = ((1 - fa) * ((1 - fb) * t[a, b] + fb * t[a, b + 1])
                         + fa * ((1 - fb) * t[a + 1, b] + fb * t[a + 1, b + 1]))
    return t, out


def main():
    data, lutbake = sys.argv[1], sys.argv[2]
    preset = sys.argv[3] if len(sys.argv) > 3 else None
    dfg256 = evaluate(lutbake, 'dfg', 256)
    sheen = evaluate(lutbake, 'sheen_E', 256, ('--sheen-visibility', 'ashikhmin', '--sheen-alpha', 'squared'))
    dfg128 = evaluate(lutbake, 'dfg', 128)
    f82 = evaluate(lutbake, 'f82', 128)
    brdf = np.stack([dfg256[..., 1], dfg256[..., 0] + dfg256[..., 1], sheen[..., 0]], -1)
    openpbr = np.stack([dfg128[..., 1], dfg128[..., 0] + dfg128[..., 1], 16 * f82[..., 0]], -1)
    table, fuzz = zeltner_at_centres(os.path.join(data, 'zeltner_ltc_volume.csv'))
    low, high = np.array([0.005, -0.18, 0.0]), np.array([0.88, 0.002, 0.75])

    def at(n):
        return lambda i, j: f'NdotV {(i + 0.5) / n:.4g}, r {(j + 0.5) / n:.4g}'

    def fuzz_at(i, j):
        return f'alpha {(i + 0.5) / 32:.4g}, NdotV {(j + 0.5) / 32:.4g}'

    print('| texture, as Babylon decodes it | max difference | RMS | where the max is |')
    print('|---|---|---|---|')
    sources = [('Babylon.js 9.35.0', {'brdf': 'environmentBRDF.png', 'openpbr': 'openPBREnvironmentBRDF.png',
                                      'fuzz': 'environmentFuzzBRDF.png'}, data)]
    if preset:
        sources.append(('lutbake --preset babylon', {'brdf': 'environmentBRDFTexture.png',
                                                     'openpbr': 'openPBREnvironmentBRDFTexture.png',
                                                     'fuzz': 'environmentFuzzBRDFTexture.png'}, preset))
    for who, files, where in sources:
        got = from_rgbd(read_png(os.path.join(where, files['brdf'])))
        sheen_ok = brdf[..., 2] <= 1.0
        for c, name in enumerate(['B', 'E']):
            report(f'{who} environmentBRDF 256² RGBD ({name})', got[..., c] - brdf[..., c], at(256))
        report(f'{who} environmentBRDF 256² RGBD (sheen E, where exact <= 1)',
               np.where(sheen_ok, got[..., 2] - brdf[..., 2], 0.0), at(256))
        report(f'{who} environmentBRDF 256² RGBD (sheen E, where exact > 1)',
               np.where(sheen_ok, 0.0, got[..., 2] - brdf[..., 2]), at(256))
        got = from_rgbd(read_png(os.path.join(where, files['openpbr'])))
        for c, name in enumerate(['B', 'E', 'z = 16 C']):
            report(f'{who} openPBREnvironmentBRDF 128² RGBD ({name})', got[..., c] - openpbr[..., c], at(128))
        img = read_png(os.path.join(where, files['fuzz']))
        got = low + (high - low) * from_rgbd(img)
        for c, name in enumerate(['a', 'b', 'R']):
            report(f'{who} environmentFuzzBRDF 32² ({name}; Zeltner at the sampled alpha, NdotV)',
                   got[..., c] - fuzz[..., c], fuzz_at)
        if img.shape[2] == 3:
            linear = low + (high - low) * img / 255.0
            for c, name in enumerate(['a', 'b', 'R']):
                report(f'{who} environmentFuzzBRDF 32² ({name}; bytes read linearly, against the entry '
                       f'at alpha = i/31, cos = j/31)', linear[..., c] - table.transpose(1, 0, 2)[..., c],
                       lambda i, j: f'entry alpha {i}/31, cos {j}/31')


if __name__ == '__main__':
    main()
