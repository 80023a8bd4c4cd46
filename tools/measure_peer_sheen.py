#!/usr/bin/python3
"""Measure the real error of other renderers' shipped sheen albedo tables E(mu, roughness).

Each peer table is read under its OWN conventions (axis mapping, alpha = r or r^2, texel
centres or edges, row order, sRGB/RGBD encoding, visibility term, clamping) and compared
with lutbake's exact values (`lutbake eval --table sheen_E ... --json`, each with a proven error
bound, at most ~1e-7 at the points used).

Usage:
    /usr/bin/python3 tools/measure_peer_sheen.py PEER_DIR LUTBAKE [--khronos-stride N] [--grid N]

PEER_DIR holds the peer files below, as saved by hand from the public repositories (nothing of
them is bundled with lutbake). LUTBAKE is the lutbake binary. The Markdown report goes to stdout,
progress to stderr. Needs numpy. With the defaults (every Khronos texel, 256^2 dense grids) it
evaluates about 1.3 million exact points: about 5 minutes on 2 cores.

Peer files (repository @ commit, path) and the conventions this script reads them with:

  lut_sheen_E_fixture.png  Khronos glTF-Sample-Renderer `assets/images/lut_sheen_E.png`, current
      version (Sample-Renderer d59d1d6 / bec106e; byte copy in MarlonJD/flutter_scene_viewer
      tools/reference_renderers/khronos_sample_viewer_fixture/assets/lut_sheen_E.png,
      sha256 7f21d775...). 1024^2 RGB, 16 bit, R=G=B. Stores sRGB-encoded E with the glTF
      "Charlie" visibility (fitted Lambda), alpha = r^2. x = NdotV = (col+0.5)/1024,
      y = sheenRoughness r = (row+0.5)/1024, PNG row 0 (top) = r ~ 0. The viewer uploads it
      as plain 8-bit RGBA (no sRGB decode), so the shader uses the encoded numbers as E.
  lut_sheen_E.png  the older glTF-Sample-Viewer copy of the same asset (Sample-Viewer
      assets/images/lut_sheen_E.png, index version 481083ec; byte copy from
      Suraj-Yadav/render-engine@a56454b images/lut_sheen_E.png). An exact vertical flip of the
      current file (checked below); only used for a supplementary line.
  babylon_brdf_lut.png  Babylon.js environment BRDF LUT: base64 PNG embedded in
      BabylonJS/Babylon.js@02e530f4 packages/dev/core/src/Misc/brdfTextureTools.ts; same bytes as
      BabylonJS/Babylon-Lite@dda4ecc1 packages/babylon-lite/assets/brdf-lut.png (sha256 f1081890...).
      256^2 RGBA8, RGBD-encoded: value = (c/255)^2.2 / (a/255). Blue = sheen E with the
      Ashikhmin/Neubelt visibility, alpha = r^2, texel centres, PNG row 0 = r ~ 0.
  epbr_pbrlut_pre2021-03.hpp  DassaultSystemes-Technology/EnterprisePBRShadingModel@90cf05f8
      res/pbrlut.hpp (the 2021x tables, the ones the glTF sheen spec cites).
      Sheen_E[16 rows: r_b][16 cols: cos]: glTF Charlie visibility, alpha = r_b^2, both axes at
      texel centres (i+0.5)/16. Rows 0-3 look clamped (alpha held near 0.07).
  epbr_pbrlut.hpp  the same file @929c6cae (2022x tables, since 3ee91319).
      Sheen_ash_E[16 rows: alpha][16 cols: cos]: Ashikhmin visibility, y = alpha directly,
      texel centres, values clamped to <= 1. (Its Sheen_E uses EPBR's refined Lambda fit,
      which lutbake does not implement: not measured.)
  materialx_mx_microfacet_sheen_2021-09-06_parent.glsl  AcademySoftwareFoundation/MaterialX
      @740f70cb libraries/pbrlib/genglsl/lib/mx_microfacet_sheen.glsl, u_sheenAlbedo[16*16]
      (in MaterialX 2019-05 .. 2021-09). Ashikhmin visibility, y = alpha (roughness passed
      straight to the NDF). Generated at texel centres (i+0.5)/16 but looked up by the shader
      with an edge mapping x = cos*15, y = roughness*15, bilinear, then clamped to [0, 1].
  castor3d_GlslSheenBRDF.cpp  DragonJoker/Castor3D@4a24e1c3
      source/Core/Castor3D/Shader/Shaders/GlslSheenBRDF.cpp, albedoSheenScalingLUT (256 ints).
      Only checked for provenance (= EPBR 2022x Sheen_E, sRGB-encoded to 8 bits); not comparable
      with lutbake (refined Lambda), so not measured against it.
  csv/khronos_runtime_charlie_lut_expectation.csv  NOT a peer file: the research pass's computed
      infinite-sample expectation of the Khronos runtime Charlie LUT estimator; compared with
      lutbake's exact values in the "expectations" section only.
Analytic fits (formulas re-typed from the peers' shaders, evaluated here; all clamped to [0,1]
as the shaders do):
  three.js IBLSheenBRDF (mrdoob/three.js, lights_physical_pars_fragment): the current fit
      (PR #32397) and the legacy piecewise fit (PR #23069). Argument = perceptual sheenRoughness
      r, alpha = r^2, Ashikhmin (Neubelt) visibility.
  MaterialX mx_imageworks_sheen_dir_albedo_analytic (MaterialX@4177b2cb, same .glsl file):
      rational fit, argument = alpha, Ashikhmin visibility.

Statistics: |error| = |E_peer - E_exact|. "max rel" is over points with E_exact >= 0.01 only.
"max where exact <= 1" leaves out the low-roughness grazing corner, where E_exact grows without
bound (to ~87 for Charlie at r ~ 0.0005, mu ~ 0.0005) but plain 8/16-bit images and clamped
tables cannot go above 1. A second table repeats the comparison over rows with alpha >= 1/16. mu = 0 is never evaluated (Charlie's E is infinite there and lutbake refuses
it): every table here is texel-centred in mu, and the dense grids start at mu = 1/N.
"""

import argparse
import csv
import json
import os
import re
import struct
import subprocess
import sys
import zlib

import numpy as np

REL_FLOOR = 0.01          # relative errors only where the exact E is at least this
MAX_POINTS_PER_CALL = 200000


def log(msg):
    print(msg, file=sys.stderr, flush=True)


# ----------------------------------------------------------------------------------------------
# PNG reading (8 or 16 bit, non-interlaced), written for this script.

def read_png(path):
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise ValueError(path + ': not a PNG')
    pos, idat, header = 8, [], None
    while pos < len(data):
        length, = struct.unpack('>I', data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b'IHDR':
            header = struct.unpack('>IIBBBBB', body)
        elif kind == b'IDAT':
            idat.append(body)
    width, height, depth, colour, _, _, interlace = header
    if interlace != 0 or depth not in (8, 16):
        raise ValueError(path + ': unsupported PNG layout')
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
    bpp = channels * depth // 8                      # bytes per pixel (filter distance)
    stride = width * bpp
    raw = zlib.decompress(b''.join(idat))
    rows = np.zeros((height, stride), np.uint8)
    prev = np.zeros(stride, np.int64)
    for y in range(height):
        start = y * (stride + 1)
        filt = raw[start]
        cur = np.frombuffer(raw, np.uint8, stride, start + 1).astype(np.int64)
        if filt == 1:                                # Sub: running sum per byte lane
            for lane in range(bpp):
                cur[lane::bpp] = np.cumsum(cur[lane::bpp]) & 255
        elif filt == 2:                              # Up
            cur = (cur + prev) & 255
        elif filt in (3, 4):                         # Average / Paeth: sequential
            out, up = cur.tolist(), prev.tolist()
            for i in range(stride):
                left = out[i - bpp] if i >= bpp else 0
                upleft = up[i - bpp] if i >= bpp else 0
                if filt == 3:
                    pred = (left + up[i]) >> 1
                else:
                    p = left + up[i] - upleft
                    da, db, dc = abs(p - left), abs(p - up[i]), abs(p - upleft)
                    pred = left if da <= db and da <= dc else (up[i] if db <= dc else upleft)
                out[i] = (out[i] + pred) & 255
            cur = np.array(out, np.int64)
        rows[y] = cur
        prev = cur
    if depth == 16:
        pix = (rows[:, 0::2].astype(np.int64) << 8) | rows[:, 1::2]
    else:
        pix = rows.astype(np.int64)
    return pix.reshape(height, width, channels), depth


def srgb_to_linear(c):
    c = np.asarray(c, float)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def linear_to_srgb(x):
    x = np.asarray(x, float)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(np.maximum(x, 0), 1 / 2.4) - 0.055)


# ----------------------------------------------------------------------------------------------
# C / GLSL array parsing

def c_table(path, name, rows_label):
    """float NAME[16/*rows_label*/][16/*cos_theta*/] = {{...},...}; -> 16x16 array (rows, cos)."""
    text = open(path).read()
    m = re.search(r'float\s+' + name + r'\s*\[16/\*' + rows_label + r'\*/\]\[16/\*cos_theta\*/\]\s*=\s*\{(.*?)\n\};',
                  text, re.S)
    if not m:
        raise ValueError('%s: table %s not found' % (path, name))
    rows = re.findall(r'\{([^{}]*)\}', m.group(1))
    table = np.array([[float(v.strip().rstrip('f')) for v in r.split(',') if v.strip()] for r in rows])
    if table.shape != (16, 16):
        raise ValueError('%s: %s has shape %s' % (path, name, table.shape))
    return table


def materialx_table(path):
    text = open(path).read()
    m = re.search(r'u_sheenAlbedo\[[^\]]*\]\s*=\s*float\[\]\((.*?)\);', text, re.S)
    vals = [float(v) for v in m.group(1).replace('\n', ' ').split(',') if v.strip()]
    if len(vals) != 256:
        raise ValueError(path + ': expected 256 values')
    return np.array(vals).reshape(16, 16)          # [roughness index][cos index]


def castor_table(path):
    ints = [int(h, 16) for h in re.findall(r'0x([0-9a-fA-F]+)_h', open(path).read())]
    if len(ints) != 256:
        raise ValueError(path + ': expected 256 entries')
    return np.array(ints).reshape(16, 16)          # index = cos index + 16 * roughness index


# ----------------------------------------------------------------------------------------------
# Exact values from lutbake

class Exact:
    def __init__(self, binary):
        self.binary = binary
        self.cache = {}
        self.points = 0
        self.max_bound = 0.0

    def grid(self, visibility, alpha_mode, mus, rs):
        """E[j, i] at roughness rs[j], mu mus[i] (lutbake's --roughness; alpha = r or r^2)."""
        mus = [float(m) for m in mus]
        rs = [float(r) for r in rs]
        key = (visibility, alpha_mode, tuple(mus), tuple(rs))
        if key in self.cache:
            return self.cache[key]
        if min(mus) <= 0.0:
            raise ValueError('mu = 0 is not evaluated (Charlie E is infinite there)')
        out = np.empty((len(rs), len(mus)))
        mu_arg = ','.join(repr(m) for m in mus)
        per_call = max(1, MAX_POINTS_PER_CALL // len(mus))
        for first in range(0, len(rs), per_call):
            chunk = rs[first:first + per_call]
            cmd = [self.binary, 'eval', '--table', 'sheen_E', '--mu', mu_arg,
                   '--roughness', ','.join(repr(r) for r in chunk),
                   '--sheen-visibility', visibility, '--sheen-alpha', alpha_mode, '--json']
            res = subprocess.run(cmd, capture_output=True, text=True)
            if res.returncode != 0:
                raise RuntimeError('lutbake eval failed: ' + res.stderr.strip()[:500])
            lines = res.stdout.splitlines()
            if len(lines) != len(chunk) * len(mus):
                raise RuntimeError('lutbake returned %d lines, expected %d' % (len(lines), len(chunk) * len(mus)))
            for k, line in enumerate(lines):
                rec = json.loads(line)
                j, i = divmod(k, len(mus))           # roughness outer, mu inner
                if abs(rec['mu'] - mus[i]) > 1e-12 or abs(rec['roughness'] - chunk[j]) > 1e-12:
                    raise RuntimeError('lutbake point order differs from the request: %s' % line)
                out[first + j, i] = rec['value']
                self.max_bound = max(self.max_bound, rec['error'])
            self.points += len(lines)
        self.cache[key] = out
        return out


# ----------------------------------------------------------------------------------------------
# Statistics and report rows

def fmt(x, digits=4):
    return '%.*g' % (digits, x)


def pct(x):
    return '%.3g%%' % (100 * x)


def stats(peer, exact, mus, ys, yname, alphas):
    """Error statistics of peer[j, i] against exact[j, i]: ys (named yname, alpha = alphas[j]) on rows,
    mus on columns."""
    err = np.abs(peer - exact)

    def at(k):
        j, i = k
        s = 'mu=%s, %s=%s' % (fmt(mus[i]), yname, fmt(ys[j]))
        if yname != 'alpha':
            s += ', alpha=%s' % fmt(alphas[j])
        return s + '; peer %s, exact %s' % (fmt(peer[k]), fmt(exact[k]))

    out = {'n': err.size, 'mean': float(err.mean())}
    k = np.unravel_index(np.argmax(err), err.shape)
    out['max'], out['max_at'] = float(err[k]), at(k)
    le1 = np.where(exact <= 1.0, err, -1.0)
    k = np.unravel_index(np.argmax(le1), err.shape)
    out['max_le1'], out['max_le1_at'] = (float(err[k]), at(k)) if le1[k] >= 0 else (float('nan'), '-')
    rel = np.where(exact >= REL_FLOOR, err / np.maximum(exact, REL_FLOOR), -1.0)
    k = np.unravel_index(np.argmax(rel), err.shape)
    out['rel'], out['rel_at'] = (float(rel[k]), at(k)) if rel[k] >= 0 else (float('nan'), '-')
    return out


ROWS = []       # (peer, file, convention, points, full-domain stats, stats over alpha >= ALPHA_MIN)
NOTES = []      # supplementary lines
ALPHA_MIN = 1.0 / 16


def measure(peer, exact, mus, ys, yname, alphas):
    """Full-domain statistics, and the same over the rows with alpha >= ALPHA_MIN (None if none)."""
    alphas = np.asarray(alphas, float)
    full = stats(peer, exact, mus, ys, yname, alphas)
    keep = alphas >= ALPHA_MIN - 1e-12
    part = stats(peer[keep], exact[keep], mus, np.asarray(ys)[keep], yname, alphas[keep]) if keep.any() else None
    return full, part


def add_row(peer, file, convention, points, measured):
    ROWS.append((peer, file, convention, points) + measured)


# ----------------------------------------------------------------------------------------------
# Peers

def centres(n):
    return (np.arange(n) + 0.5) / n


def line(st, with_le1=True):
    s = 'max |err| %s (%s); mean %s' % (fmt(st['max']), st['max_at'], fmt(st['mean']))
    if with_le1:
        s += '; where exact <= 1: max %s (%s)' % (fmt(st['max_le1']), st['max_le1_at'])
    return s + '; max rel %s' % pct(st['rel'])


def khronos(peer_dir, ex, stride):
    img, depth = read_png(os.path.join(peer_dir, 'lut_sheen_E_fixture.png'))
    if img.shape != (1024, 1024, 3) or depth != 16:
        raise ValueError('lut_sheen_E_fixture.png: expected 1024x1024 16-bit RGB')
    if not ((img[..., 0] == img[..., 1]).all() and (img[..., 0] == img[..., 2]).all()):
        raise ValueError('lut_sheen_E_fixture.png: R, G, B differ')
    raw = img[..., 0]
    sel = np.arange(0, 1024, stride)
    if sel[-1] != 1023:
        sel = np.append(sel, 1023)
    mus = (sel + 0.5) / 1024
    rs = (sel + 0.5) / 1024
    log('khronos: %d x %d texels, exact Charlie alpha=r^2 ...' % (len(rs), len(mus)))
    exact = ex.grid('charlie', 'squared', mus, rs)
    sub = raw[np.ix_(sel, sel)]                      # [row = r index][column = mu index]
    conv = 'charlie, alpha=r^2, x=NdotV, y=r, texel centres, PNG row 0 = r~0'
    pts = 'all %d texels' % sub.size if stride == 1 else 'every %dth row/column (%d)' % (stride, sub.size)
    u8 = np.floor(sub / 257.0 + 0.5) / 255.0         # the browser's 16 -> 8 bit reduction (rounding)
    add_row('Khronos glTF Sample Viewer/Renderer, as the viewer uses it', 'assets/images/lut_sheen_E.png (current)',
            conv + '; uploaded as 8-bit RGBA, no sRGB decode', pts,
            measure(u8, exact, mus, rs, 'r', rs ** 2))
    add_row('Khronos, sRGB-decoded (what the file stores)', 'assets/images/lut_sheen_E.png (current)',
            conv + '; sRGB EOTF of raw/65535', pts,
            measure(srgb_to_linear(sub / 65535.0), exact, mus, rs, 'r', rs ** 2))
    full, _ = measure(sub / 65535.0, exact, mus, rs, 'r', rs ** 2)
    NOTES.append('Khronos, the 16-bit values read as linear without the 8-bit reduction: ' + line(full) + '.')
    full, _ = measure((sub >> 8) / 255.0, exact, mus, rs, 'r', rs ** 2)
    NOTES.append('Khronos, 8-bit reduction by truncation (high byte) instead of rounding: ' + line(full) + '.')
    # rows at low roughness are nearly identical: how far does each row differ from row 0?
    diff = np.abs(raw.astype(np.int64) - raw[0][None, :]).max(axis=1) / 65535.0
    last = int(np.nonzero(diff <= 0.01)[0].max())
    NOTES.append('Khronos: every PNG row up to row %d (r=%s) differs from row 0 (r=%s) by at most 0.01 in the '
                 'stored (sRGB-encoded) value, so below r~%s the table is essentially one clamped row.'
                 % (last, fmt((last + 0.5) / 1024), fmt(0.5 / 1024), fmt((last + 0.5) / 1024, 2)))
    old_path = os.path.join(peer_dir, 'lut_sheen_E.png')
    if os.path.exists(old_path):
        old, _ = read_png(old_path)
        flipped = bool((old[::-1] == img).all())
        NOTES.append('The older Sample-Viewer lut_sheen_E.png is an exact vertical flip of the current file: %s.' % flipped)
        if flipped:
            used = np.floor(old[..., 0][np.ix_(sel, sel)] / 257.0 + 0.5) / 255.0
            full, part = measure(used, exact, mus, rs, 'r', rs ** 2)
            NOTES.append('That older file read the same way (PNG row 0 at r~0, 8-bit, no decode), i.e. with its '
                         'roughness axis upside down: ' + line(full) + '; over alpha >= 1/16: ' + line(part, False) + '.')


def babylon(peer_dir, ex):
    img, depth = read_png(os.path.join(peer_dir, 'babylon_brdf_lut.png'))
    if img.shape != (256, 256, 4) or depth != 8:
        raise ValueError('babylon_brdf_lut.png: expected 256x256 RGBA8')
    b, a = img[..., 2], img[..., 3]
    if a.min() == 0:
        raise ValueError('babylon_brdf_lut.png: RGBD alpha of 0')
    e = (b / 255.0) ** 2.2 / (a / 255.0)            # Babylon's fromRGBD: pow(rgb, 2.2) / D
    mus = centres(256)
    rs = centres(256)
    log('babylon: 256 x 256 texels, exact Ashikhmin alpha=r^2 ...')
    exact = ex.grid('ashikhmin', 'squared', mus, rs)
    add_row('Babylon.js environment BRDF LUT, blue channel', 'brdfTextureTools.ts (embedded PNG)',
            'ashikhmin, alpha=r^2, x=NdotV, y=r, texel centres, PNG row 0 = r~0; RGBD: (b/255)^2.2/(a/255)',
            'all %d texels' % e.size, measure(e, exact, mus, rs, 'r', rs ** 2))
    full, part = measure(e.astype(np.float16).astype(float), exact, mus, rs, 'r', rs ** 2)
    NOTES.append('Babylon, decoded values rounded to half float (Babylon expands RGBD textures to RGBA16F where it can): '
                 + line(full) + '; over alpha >= 1/16: ' + line(part, False) + '.')


def epbr(peer_dir, ex):
    c = centres(16)
    # 2021x Sheen_E: y = r_b, alpha = r_b^2, glTF Charlie visibility
    t21 = c_table(os.path.join(peer_dir, 'epbr_pbrlut_pre2021-03.hpp'), 'Sheen_E', 'roughness')
    log('epbr: 2021x Sheen_E, 2022x Sheen_ash_E ...')
    exact = ex.grid('charlie', 'squared', c, c)
    add_row('Enterprise PBR 2021x Sheen_E', 'res/pbrlut.hpp @90cf05f8',
            'charlie (glTF Lambda), alpha=r_b^2, y=r_b, 16^2 texel centres', 'all 256',
            measure(t21, exact, c, c, 'r_b', c ** 2))
    # The suspected clamp of rows 0-3: which single alpha explains each of them best?
    cands = np.round(np.arange(0.030, 0.1201, 0.001), 6)
    ecand = ex.grid('charlie', 'linear', c, cands)      # rows = candidate alpha
    for j in range(4):
        worst = np.abs(ecand - t21[j][None, :]).max(axis=1)
        k = int(np.argmin(worst))
        NOTES.append('EPBR 2021x Sheen_E row %d (r_b=%s, alpha=%s): max |err| %s against its own alpha; the best '
                     'single alpha in [0.03, 0.12] is %s, leaving max |err| %s.'
                     % (j, fmt(c[j]), fmt(c[j] ** 2), fmt(np.abs(t21[j] - exact[j]).max()), fmt(cands[k]), fmt(worst[k])))
    # 2022x Sheen_ash_E: y = alpha, Ashikhmin visibility, clamped to 1
    ash = c_table(os.path.join(peer_dir, 'epbr_pbrlut.hpp'), 'Sheen_ash_E', 'alpha')
    exact_a = ex.grid('ashikhmin', 'linear', c, c)
    add_row('Enterprise PBR 2022x Sheen_ash_E', 'res/pbrlut.hpp @929c6cae',
            'ashikhmin, y=alpha, 16^2 texel centres, values clamped to <= 1', 'all 256',
            measure(ash, exact_a, c, c, 'alpha', c))
    return c_table(os.path.join(peer_dir, 'epbr_pbrlut.hpp'), 'Sheen_E', 'alpha')


def bilinear(table, x, y):
    """Bilinear lookup in a 16x16 table at continuous indices x (cos) and y (roughness), as MaterialX does."""
    ix = np.floor(x).astype(int)
    iy = np.floor(y).astype(int)
    ix2 = np.minimum(ix + 1, 15)
    iy2 = np.minimum(iy + 1, 15)
    fx, fy = x - ix, y - iy
    v1 = table[iy, ix] * (1 - fx) + table[iy, ix2] * fx
    v2 = table[iy2, ix] * (1 - fx) + table[iy2, ix2] * fx
    return v1 * (1 - fy) + v2 * fy


def materialx(peer_dir, ex, n):
    t = materialx_table(os.path.join(peer_dir, 'materialx_mx_microfacet_sheen_2021-09-06_parent.glsl'))
    c = centres(16)
    exact_c = ex.grid('ashikhmin', 'linear', c, c)
    add_row('MaterialX u_sheenAlbedo (2019-05..2021-09), at its generation points', 'mx_microfacet_sheen.glsl @740f70cb',
            'ashikhmin, y=alpha, 16^2 texel centres', 'all 256', measure(t, exact_c, c, c, 'alpha', c))
    g = np.arange(1, n + 1) / n
    log('materialx: dense %d x %d grid, exact Ashikhmin alpha linear ...' % (n, n))
    exact = ex.grid('ashikhmin', 'linear', g, g)
    mu, al = np.meshgrid(g, g)                      # [alpha index][mu index]
    edge = np.clip(bilinear(t, mu * 15, al * 15), 0, 1)
    add_row('MaterialX u_sheenAlbedo, through its shader lookup', 'mx_microfacet_sheen.glsl @740f70cb',
            'x=mu*15, y=alpha*15 (edge mapping), bilinear, clamp [0,1]',
            '%dx%d grid, mu and alpha in {1/%d..1}' % (n, n, n), measure(edge, exact, g, g, 'alpha', g))
    centre = np.clip(bilinear(t, np.clip(mu * 16 - 0.5, 0, 15), np.clip(al * 16 - 0.5, 0, 15)), 0, 1)
    add_row('MaterialX u_sheenAlbedo, centre-consistent lookup (hypothetical, not shipped)',
            'mx_microfacet_sheen.glsl @740f70cb',
            'x=mu*16-0.5, y=alpha*16-0.5 (clamped to the table), bilinear, clamp [0,1]',
            'same grid', measure(centre, exact, g, g, 'alpha', g))
    return exact, g


def castor(peer_dir, epbr22_sheen_e):
    path = os.path.join(peer_dir, 'castor3d_GlslSheenBRDF.cpp')
    if not os.path.exists(path):
        return
    ints = castor_table(path)
    enc = np.floor(linear_to_srgb(epbr22_sheen_e) * 255 + 0.5)
    d = np.abs(ints - enc)
    NOTES.append('Castor3D albedoSheenScalingLUT against EPBR 2022x Sheen_E sRGB-encoded to 8 bits: %d of 256 equal, '
                 'max difference %d LSB (a provenance check, not a lutbake comparison). As Castor3D uses it (no /255) '
                 'its values run from %d to %d.' % (int((d == 0).sum()), int(d.max()), ints.min(), ints.max()))


def three_current(mu, r):
    r2 = r * r
    rinv = 1.0 / (r + 0.1)
    a = -1.9362 + 1.0678 * r + 0.4573 * r2 - 0.8469 * rinv
    b = -0.6014 + 0.5538 * r - 0.4670 * r2 - 0.1255 * rinv
    return np.clip(np.exp(a * mu + b), 0, 1)


def three_legacy(mu, r):
    r2 = r * r
    low = r < 0.25
    a = np.where(low, -339.2 * r2 + 161.4 * r - 25.9, -8.48 * r2 + 14.3 * r - 9.95)
    b = np.where(low, 44.0 * r2 - 23.7 * r + 3.26, 1.97 * r2 - 3.27 * r + 0.72)
    dg = np.exp(a * mu + b) + np.where(low, 0.0, 0.1 * (r - 0.25))
    return np.clip(dg / np.pi, 0, 1)


def materialx_rational(mu, alpha):
    num = (13.67300 - 68.78018 * mu + 799.08825 * alpha - 905.00061 * mu * alpha
           + 60.28956 * mu * mu + 1086.96473 * alpha * alpha)
    den = (1.0 + 61.57746 * mu + 442.78211 * alpha + 2597.49308 * mu * alpha
           + 121.81241 * mu * mu + 3045.55075 * alpha * alpha)
    return np.clip(num / den, 0, 1)


def fits(ex, n, mx_exact, g):
    log('analytic fits: dense %d x %d grid, exact Ashikhmin alpha=r^2 ...' % (n, n))
    exact = ex.grid('ashikhmin', 'squared', g, g)
    mu, r = np.meshgrid(g, g)
    pts = '%dx%d grid, mu and r in {1/%d..1}' % (n, n, n)
    add_row('three.js IBLSheenBRDF, current fit (PR #32397)', 'analytic (shader formula)',
            'ashikhmin, argument r, alpha=r^2, saturate', pts, measure(three_current(mu, r), exact, g, g, 'r', g ** 2))
    add_row('three.js IBLSheenBRDF, legacy fit (PR #23069)', 'analytic (shader formula)',
            'ashikhmin, argument r, alpha=r^2, saturate', pts, measure(three_legacy(mu, r), exact, g, g, 'r', g ** 2))
    add_row('MaterialX mx_imageworks_sheen_dir_albedo_analytic (current)', 'analytic (shader formula)',
            'ashikhmin, argument alpha, clamp [0,1]', pts.replace('mu and r', 'mu and alpha'),
            measure(materialx_rational(mu, r), mx_exact, g, g, 'alpha', g))


def expectations(peer_dir, ex):
    lines = []
    path = os.path.join(peer_dir, 'csv', 'khronos_runtime_charlie_lut_expectation.csv')
    if os.path.exists(path):
        recs = list(csv.DictReader(open(path)))
        worst_ref, biases = 0.0, []
        for rec in recs:
            r, mu = float(rec['sheenRoughness']), float(rec['NoV'])
            neub = ex.grid('ashikhmin', 'squared', [mu], [r])[0, 0]
            charl = ex.grid('charlie', 'squared', [mu], [r])[0, 0]
            worst_ref = max(worst_ref, abs(neub - float(rec['E_neubelt_alpha_r2'])),
                            abs(charl - float(rec['E_charlieLambda_alpha_r2'])))
            expect = float(rec['runtime_LUT_expectation'])
            biases.append((expect / neub - 1, r, mu, expect, neub))
        lo, hi = min(biases), max(biases)
        lines.append('Khronos runtime Charlie LUT (ibl_filtering.frag `LUT()`, u_CharlieLUT blue; made on the GPU, no '
                     'file): it weights Charlie-importance-sampled half vectors (alpha=r^2) with Filament\'s uniform-'
                     'sampling factor 8*pi and evaluates D with alpha=r. The research pass\'s infinite-sample '
                     'expectation of that estimator lies %.0f%% to %.0f%% above lutbake\'s exact Ashikhmin E at '
                     'alpha=r^2 over its %d points (largest: %s vs %s at r=%s, mu=%s), before 512-sample noise and '
                     'storage. (The exact-E columns of that file agree with lutbake to %s.)'
                     % (100 * lo[0], 100 * hi[0], len(recs), fmt(hi[3]), fmt(hi[4]), fmt(hi[1]), fmt(hi[2]),
                        fmt(worst_ref, 2)))
    for h in (128, 64):
        look = centres(h)                                  # where the shader looks up r (texel centres)
        stored = np.minimum((np.arange(h) + 1.5) / h, 1.0)  # the coordinate cmgen stored there, read from the code
        mus = centres(h)
        e_look = ex.grid('ashikhmin', 'squared', mus, look)
        e_stored = ex.grid('ashikhmin', 'squared', mus, stored)
        full, part = measure(e_stored, e_look, mus, look, 'r', look ** 2)
        lines.append('Filament cmgen cloth DFG (blue channel), DFG_LUT_SIZE=%d (built, never committed): uniform '
                     'half-vector sampling, 4096 Hammersley points, Ashikhmin V, alpha=r^2, RGB16F; if GL row j holds '
                     'coordinate (j+1.5)/%d as the code reads, the one-texel roughness offset alone (exact values on '
                     'both sides, no sampling noise or half-float rounding; "peer" = what the lookup returns) gives '
                     '%s; over alpha >= 1/16: %s.'
                     % (h, h, line(full, False), line(part, False)))
    lines.append('Unity HDRP Charlie FGD (made at runtime, 64^2 A2B10G10R10 UNorm storing E/(2 pi)): a consistent '
                 '4096-point golden-spiral estimator with the Charlie visibility, alpha=p^2, texel centres; its '
                 'storage step alone is 2 pi/1023 = %s in E (arithmetic, not a measurement).' % fmt(2 * np.pi / 1023, 3))
    return lines


# ----------------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description='Measure peers\' shipped sheen albedo tables against lutbake.')
    ap.add_argument('peer_dir', help='folder holding the peer files (see the header of this script)')
    ap.add_argument('lutbake', help='the lutbake binary')
    ap.add_argument('--khronos-stride', type=int, default=1, help='use every Nth row/column of the 1024^2 Khronos LUT')
    ap.add_argument('--grid', type=int, default=256, help='dense grid size for the lookups and analytic fits')
    args = ap.parse_args()

    ex = Exact(args.lutbake)
    for vis, want in (('charlie', 0.35629), ('ashikhmin', 0.28729)):   # sanity: alpha=1, mu=0.5
        got = ex.grid(vis, 'linear', [0.5], [1.0])[0, 0]
        if abs(got - want) > 1e-5:
            sys.exit('lutbake sanity check failed: %s E(0.5, alpha=1) = %r' % (vis, got))

    khronos(args.peer_dir, ex, args.khronos_stride)
    babylon(args.peer_dir, ex)
    epbr22_sheen_e = epbr(args.peer_dir, ex)
    mx_exact, g = materialx(args.peer_dir, ex, args.grid)
    castor(args.peer_dir, epbr22_sheen_e)
    fits(ex, args.grid, mx_exact, g)
    exp_lines = expectations(args.peer_dir, ex)

    print('**Whole table** (every point the peer covers):')
    print()
    print('| Peer | File | Convention as read | Points compared | max \\|E − exact\\| (where) | mean \\|error\\| '
          '| max \\|error\\| where exact ≤ 1 (where) | max rel. error where exact ≥ %s (where) |' % REL_FLOOR)
    print('|---|---|---|---|---|---|---|---|')
    for peer, file, conv, pts, full, _ in ROWS:
        print('| %s | %s | %s | %s | %s (%s) | %s | %s (%s) | %s (%s) |' % (
            peer, file, conv, pts, fmt(full['max']), full['max_at'], fmt(full['mean']),
            fmt(full['max_le1']), full['max_le1_at'], pct(full['rel']), full['rel_at']))
    print()
    print('**Same comparison, rows with alpha ≥ 1/16 only** (r ≥ 0.25 where alpha = r²):')
    print()
    print('| Peer | Points compared | max \\|E − exact\\| (where) | mean \\|error\\| '
          '| max \\|error\\| where exact ≤ 1 (where) | max rel. error where exact ≥ %s (where) |' % REL_FLOOR)
    print('|---|---|---|---|---|---|')
    for peer, _, _, _, _, part in ROWS:
        print('| %s | %d | %s (%s) | %s | %s (%s) | %s (%s) |' % (
            peer, part['n'], fmt(part['max']), part['max_at'], fmt(part['mean']),
            fmt(part['max_le1']), part['max_le1_at'], pct(part['rel']), part['rel_at']))
    print()
    print('Not measured: Enterprise PBR 2022x `Sheen_E`, and Castor3D\'s table (that table sRGB-encoded to 8 bits), '
          'use EPBR\'s refined Lambda fit, which lutbake does not implement: a comparison with the glTF Charlie E '
          'would measure the model difference, not the table\'s error.')
    print()
    print('Supplementary measurements:')
    print()
    for note in NOTES:
        print('- ' + note)
    print()
    print('Computed expectations (no shipped file exists; NOT measurements of a peer\'s table):')
    print()
    for note in exp_lines:
        print('- ' + note)
    print()
    print('lutbake: %d exact points evaluated; largest proven error bound %s. |error| = |E_peer − E_exact|; '
          'relative errors only where E_exact ≥ %s; mu = 0 is never evaluated.' % (ex.points, fmt(ex.max_bound, 3), REL_FLOOR))


if __name__ == '__main__':
    main()
