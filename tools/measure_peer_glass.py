#!/usr/bin/python3
"""Measure the error of Blender Cycles' shipped rough-glass albedo tables (both sides) and of its
dielectric-reflection factor table, each read under its OWN conventions, against exact values.

Usage:
    /usr/bin/python3 tools/measure_peer_glass.py PEER LUTBAKE [--reference-csv CSV]
        [--python] [--stride N] [--cache FILE]

PEER is a directory holding the cycles_*.csv files of tests/data/glass/peers/ (written by
tests/data/glass/peers/extract_cycles.py from Cycles' shader.tables), one of those CSV files,
or a shader.tables file itself. LUTBAKE is the lutbake binary, or '-' for none. Exact values:

  * with LUTBAKE: `LUTBAKE eval --table glass_E --mu LIST --roughness LIST --eta LIST --ndf ggx
    --smith correlated --json` (one JSON object per line, keys mu, roughness, eta, value, error),
    at every texel of every table (and glass_Eavg at every texel of the Eavg tables);
  * with --python (or no LUTBAKE): tests/data/glass/generate_reference.py's integrator (the
    lighter rule, about 1e-8) at a subset of texels (every --stride-th roughness and mu index
    plus the last, every IOR slice), cached in --cache;
  * with --reference-csv (tests/data/glass/glass_E.csv or glass_Eavg.csv): the table as the
    kernel reads it (Cycles' lookup_table_read_3D/2D, linear in each axis between texels) at
    the reference points, i.e. with interpolation error.

Cycles' conventions (blender/cycles@97dbe6f5 = blender/blender intern/cycles/...; README.md in
tests/data/glass has the line numbers): GGX, alpha = rough^2 (Cycles' "roughness" is r, alpha is
its square), height-correlated Smith G2 for reflection and transmission, exact dielectric
Fresnel, value = mean of eval/pdf of the VNDF sampler = E_h[F G2/G1 + (1-F) G2/G1] (energy form:
no eta^2 radiance factor), clamped to [0, 1] and printed to 6 decimals. Texels on the edges:
rough = x/15, mu = y/15 (both clamped to >= 1e-4), z = clamp(k/15, 1e-4, 0.99) with
ior = (1 + z^2)/(1 - z^2), i.e. z = sqrt((ior - 1)/(ior + 1)); the *_inv_* tables at eta = 1/ior,
looked up with ior -> 1/ior. Slice k = 0 is ior = 1 exactly, where Cycles' sampler treats
refraction as specular (|eta - 1| < 1e-4) and returns 1: not the microfacet model's
(1 + Lambda)/(1 + 2 Lambda), so it is reported apart. The tables were baked in 2023-06
(34125e1d) by a sampler that did not reject refracted directions ending above the surface
(possible only for eta < 1); today's sampler (since 20d38758, 2023-09) rejects them, so the inv
tables are also compared with 'exact + that wrong-side transmission' (python only).

The Markdown report goes to stdout, progress to stderr. Needs numpy.
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "data", "glass"))

SHAPES = {"ggx_glass_E": (16, 16, 16), "ggx_glass_inv_E": (16, 16, 16),
          "ggx_glass_Eavg": (16, 1, 16), "ggx_glass_inv_Eavg": (16, 1, 16),
          "ggx_gen_schlick_ior_s": (16, 16, 16), "ggx_E": (32, 32, 1), "ggx_Eavg": (32, 1, 1)}


def log(m):
    print(m, file=sys.stderr, flush=True)


# ----------------------------------------------------------------------------------------------
# Reading the peer tables

def f32(v):
    return np.float32(v)


def axis(i, n, lo, hi):
    return float(np.clip(f32(f32(i) / f32(n - 1)), f32(lo), f32(hi)))


def ior_of_z(z):
    z = f32(z)
    f0 = f32(f32(z * z) * f32(z * z))
    s = np.sqrt(np.clip(f0, f32(0.0), f32(0.99)), dtype=np.float32)
    return float(f32(f32(1.0) + s) / f32(f32(1.0) - s))


def read_peers(path):
    """{name: array (nz, ny, nx)} from a directory of cycles_*.csv, one such CSV, or shader.tables."""
    out = {}
    files = []
    if os.path.isdir(path):
        files = [os.path.join(path, f) for f in sorted(os.listdir(path))
                 if f.startswith("cycles_") and f.endswith(".csv")]
    elif path.endswith(".csv"):
        files = [path]
    else:
        text = open(path).read()
        for m in re.finditer(r"static const float table_(\w+)\[(\d+)\]\s*=\s*\{(.*?)\};", text, re.S):
            if m.group(1) in SHAPES:
                nx, ny, nz = SHAPES[m.group(1)]
                v = np.array([float(q) for q in re.findall(r"(-?\d+\.\d+)f", m.group(3))])
                out[m.group(1)] = v.reshape(nz, ny, nx)
        return out
    for fn in files:
        name = os.path.basename(fn)[len("cycles_"):-len(".csv")]
        if name not in SHAPES:
            continue
        nx, ny, nz = SHAPES[name]
        arr = np.full((nz, ny, nx), np.nan)
        with open(fn) as f:
            rows = csv.DictReader(line for line in f if not line.startswith("#"))
            for r in rows:
                ix = int(r["ix"])
                iy = int(r["iy"]) if r["iy"] else 0
                iz = int(r["iz"]) if r["iz"] else 0
                arr[iz, iy, ix] = float(r["value"])
        out[name] = arr
    return out


def texel_point(name, ix, iy, iz):
    nx, ny, nz = SHAPES[name]
    rough = axis(ix, nx, 1e-4, 1.0)
    mu = axis(iy, ny, 1e-4, 1.0) if ny > 1 else None
    ior = ior_of_z(axis(iz, nz, 1e-4, 0.99)) if nz > 1 else 1.0
    eta = float(f32(1.0) / f32(ior)) if "_inv_" in name else ior
    return rough, mu, eta


def lookup(arr, rough, mu, z):
    """Cycles' lookup_table_read_3D / _2D (util/lookup_table.h): edge-placed, linear per axis."""
    nz, ny, nx = arr.shape

    def split(v, n):
        v = min(max(v, 0.0), 1.0) * (n - 1)
        i = min(int(v), n - 1)
        return i, min(i + 1, n - 1), v - i

    def row(iz, iy):
        i0, i1, t = split(rough, nx)
        return (1 - t) * arr[iz, iy, i0] + t * arr[iz, iy, i1]

    def plane(iz):
        if ny == 1:
            return row(iz, 0)
        j0, j1, t = split(mu, ny)
        return (1 - t) * row(iz, j0) + t * row(iz, j1)

    if nz == 1:
        return plane(0)
    k0, k1, t = split(z, nz)
    return (1 - t) * plane(k0) + t * plane(k1)


def cycles_read(tables, kind, rough, mu, eta):
    """What the kernel returns for (rough, mu, eta): kind 'E' or 'Eavg'."""
    ior = eta
    inv = ior < 1.0
    if inv:
        ior = 1.0 / ior
    name = "ggx_glass_" + ("inv_" if inv else "") + kind
    z = math.sqrt(abs((ior - 1.0) / (ior + 1.0)))
    if name not in tables:
        return None, name
    return lookup(tables[name], rough, mu if mu is not None else 0.0, z), name


# ----------------------------------------------------------------------------------------------
# Exact values

def lutbake_eval(exe, table, mus, roughs, etas):
    cmd = [exe, "eval", "--table", table, "--roughness", ",".join(f"{r:.9g}" for r in roughs),
           "--eta", ",".join(f"{e:.9g}" for e in etas), "--ndf", "ggx", "--smith", "correlated",
           "--json"]
    if mus is not None:
        cmd[4:4] = ["--mu", ",".join(f"{m:.9g}" for m in mus)]
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode != 0:
        raise RuntimeError(" ".join(cmd[:4]) + " ...: " + res.stderr.strip()[:400])
    out = {}
    for line in res.stdout.splitlines():
        line = line.strip()
        if not line.startswith("{"):
            continue
        o = json.loads(line)
        key = (round(float(o["roughness"]), 6), round(float(o["mu"]), 6) if "mu" in o else None,
               round(float(o["eta"]), 6))
        out[key] = (float(o["value"]), float(o.get("error", 0.0)))
    return out


def key_of(rough, mu, eta):
    return (round(rough, 6), round(mu, 6) if mu is not None else None, round(eta, 6))


class PythonExact:
    """generate_reference.py's integrator (lighter rule), cached on disk."""

    def __init__(self, cache):
        import generate_reference as G
        self.G = G
        self.cache_path = cache
        self.cache = {}
        if cache and os.path.exists(cache):
            with open(cache) as f:
                for r in csv.DictReader(f):
                    self.cache[(float(r["rough"]), float(r["mu"]), float(r["eta"]))] = tuple(
                        float(r[k]) for k in ("glass", "spec", "wrong", "vndf_s"))
        self.fresh = []

    def get(self, rough, mu, eta):
        k = (float(f"{rough:.9g}"), float(f"{mu:.9g}"), float(f"{eta:.9g}"))
        if k not in self.cache:
            v = self.G.albedo("ggx", "correlated", rough * rough, mu, eta, 12, in_levels=10,
                              out_levels=8, extra=True)
            self.cache[k] = v
            self.fresh.append((k, v))
            if len(self.fresh) % 25 == 0:
                self.flush()
        return self.cache[k]

    def flush(self):
        if not self.cache_path:
            return
        new = not os.path.exists(self.cache_path)
        with open(self.cache_path, "a") as f:
            if new:
                f.write("rough,mu,eta,glass,spec,wrong,vndf_s\n")
            for (r, m, e), v in self.fresh:
                f.write(f"{r!r},{m!r},{e!r}," + ",".join(f"{q:.17g}" for q in v) + "\n")
        self.fresh = []


# ----------------------------------------------------------------------------------------------
# Statistics and report

class Stat:
    def __init__(self):
        self.n = 0
        self.sum = 0.0
        self.max = -1.0
        self.where = ""
        self.sgn = 0.0

    def add(self, err, where):
        self.n += 1
        self.sum += abs(err)
        if abs(err) > self.max:
            self.max, self.where, self.sgn = abs(err), where, err

    def cells(self):
        if self.n == 0:
            return "0 | - | -"
        return f"{self.n} | {self.sgn:+.2e} ({self.where}) | {self.sum / self.n:.2e}"


def where_str(rough, mu, eta):
    s = f"r={rough:.4g}"
    if mu is not None:
        s += f", mu={mu:.4g}"
    return s + f", eta={eta:.5g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("peer")
    ap.add_argument("lutbake", nargs="?", default="-")
    ap.add_argument("--averages", action="store_true",
                    help="also the Eavg tables against lutbake's glass_Eavg (slow: minutes)")
    ap.add_argument("--reference-csv", action="append", default=[])
    ap.add_argument("--python", action="store_true")
    ap.add_argument("--stride", type=int, default=3)
    ap.add_argument("--cache", default="")
    ap.add_argument("--python-avg", default="7:8,7:15,9:8,9:15",
                    help="python mode: Eavg texels 'iz:ix,...' to integrate (each ~1 min); '' for none")
    a = ap.parse_args()

    tables = read_peers(a.peer)
    log("peer tables: " + ", ".join(f"{k}{tuple(v.shape)}" for k, v in tables.items()))
    use_py = a.python or a.lutbake == "-"
    py = PythonExact(a.cache) if use_py else None

    conv = {"ggx_glass_E": "GGX, alpha=r^2, correlated G2, E=R+T energy form, edge texels r=x/15, "
                           "mu=y/15, z=k/15 (ior=(1+z^2)/(1-z^2)), 6 decimals, clamped <= 1",
            "ggx_glass_inv_E": "same, baked at eta = 1/ior (lookup: ior<1 -> 1/ior)",
            "ggx_glass_Eavg": "2 int E mu dmu (MC over mu), axes r, z",
            "ggx_glass_inv_Eavg": "same at eta = 1/ior",
            "ggx_gen_schlick_ior_s": "E_vndf[(F-F0)/(1-F0) 1{i_r.z>0}], eta = ior > 1"}
    print("# Cycles glass tables against exact values\n")
    print(f"Peer: `{a.peer}`; exact values: "
          + ("generate_reference.py integrator (python, stride %d)" % a.stride if use_py
             else f"`{a.lutbake} eval`") + ".\n")

    # -------- texels
    rows = []
    for name in ("ggx_glass_E", "ggx_glass_inv_E", "ggx_gen_schlick_ior_s"):
        if name not in tables:
            continue
        arr = tables[name]
        nz, ny, nx = arr.shape
        if use_py:
            xs = sorted(set(range(0, nx, a.stride)) | {nx - 1})
            ys = sorted(set(range(1, ny, a.stride)) | {ny - 1})
        else:
            xs, ys = list(range(nx)), list(range(ny))
        st_main, st_one, st_def23, st_spec = Stat(), Stat(), Stat(), Stat()
        for iz in range(nz):
            roughs = [texel_point(name, ix, 0, iz)[0] for ix in xs]
            mus = [texel_point(name, 0, iy, iz)[1] for iy in ys]
            eta = texel_point(name, 0, 0, iz)[2]
            if name == "ggx_gen_schlick_ior_s" and (iz == 0 or not use_py):
                continue    # exact definition only in python mode; eta = 1: s undefined (0/0)
            exact = None
            if not use_py:
                if not (1.0 / 16.0 <= eta <= 16.0):
                    log(f"{name} slice {iz} eta={eta:.6g}: outside lutbake's [1/16, 16], skipped")
                    continue
                exact = lutbake_eval(a.lutbake, "glass_E", mus, roughs, [eta])
            log(f"{name} slice {iz} eta={eta:.6g}")
            for ix, rough in zip(xs, roughs):
                for iy, mu in zip(ys, mus):
                    peer = arr[iz, iy, ix]
                    w = where_str(rough, mu, eta)
                    if use_py:
                        g, s, wrong, vs = py.get(rough, mu, eta)
                    else:
                        g, _ = exact[key_of(rough, mu, eta)]
                        wrong = vs = None
                    if name == "ggx_gen_schlick_ior_s":
                        st_main.add(peer - vs, w)
                        continue
                    if iz == 0:
                        st_one.add(peer - g, w)
                        continue
                    st_main.add(peer - g, w)
                    if wrong is not None and "_inv_" in name:
                        st_def23.add(peer - min(1.0, g + wrong), w)
        if name == "ggx_gen_schlick_ior_s":
            if st_main.n:   # python mode only: lutbake has no table of this definition
                rows.append((name, conv[name], "texels k>=1 vs its exact definition", st_main))
        else:
            side = "eta < 1" if "_inv_" in name else "eta > 1"
            rows.append((name, conv[name], f"{side}: texels k>=1 vs glass_E", st_main))
            if st_def23.n:
                rows.append((name, "as baked in 2023 (34125e1d): refracted rays above the surface "
                             "kept", f"{side}: texels k>=1 vs glass_E + wrong-side T", st_def23))
            rows.append((name, "slice k=0: ior = 1.0f exactly, Cycles' specular special case (=1)",
                         f"{side}: eta = 1 vs (1+L)/(1+2L)", st_one))
    if py:
        py.flush()

    # -------- Eavg texels (lutbake only; --averages: each eta < 1 average takes seconds)
    if not use_py and a.averages:
        for name in ("ggx_glass_Eavg", "ggx_glass_inv_Eavg"):
            if name not in tables:
                continue
            arr = tables[name]
            nz, _, nx = arr.shape
            st, st_one = Stat(), Stat()
            for iz in range(nz):
                roughs = [texel_point(name, ix, 0, iz)[0] for ix in range(nx)]
                eta = texel_point(name, 0, 0, iz)[2]
                if not (1.0 / 16.0 <= eta <= 16.0):
                    continue
                ex = lutbake_eval(a.lutbake, "glass_Eavg", None, roughs, [eta])
                for ix, rough in enumerate(roughs):
                    g, _ = ex[key_of(rough, None, eta)]
                    (st_one if iz == 0 else st).add(arr[iz, 0, ix] - g, where_str(rough, None, eta))
            side = "eta < 1" if "_inv_" in name else "eta > 1"
            rows.append((name, conv[name], f"{side}: texels k>=1 vs glass_Eavg", st))
            rows.append((name, "slice k=0 (ior = 1 special case)", f"{side}: eta = 1", st_one))

    if use_py and a.python_avg:
        G = py.G
        for name in ("ggx_glass_Eavg", "ggx_glass_inv_Eavg"):
            if name not in tables:
                continue
            st = Stat()
            for item in a.python_avg.split(","):
                iz, ix = (int(q) for q in item.split(":"))
                rough, _, eta = texel_point(name, ix, 0, iz)
                log(f"{name} texel iz={iz} ix={ix}: averaging")
                g = G.average("ggx", "correlated", rough * rough, eta)[0]
                st.add(tables[name][iz, 0, ix] - g, where_str(rough, None, eta))
            side = "eta < 1" if "_inv_" in name else "eta > 1"
            rows.append((name, conv[name], f"{side}: texels {a.python_avg} vs glass_Eavg", st))

    print("## At the tables' own texels (no interpolation)\n")
    print("| peer table | convention as read | compared | points | max err (peer - exact, where) "
          "| mean abs err |")
    print("|---|---|---|---|---|---|")
    for name, c, what, st in rows:
        print(f"| {name} | {c} | {what} | {st.cells()} |")

    # -------- lookups at reference points
    for ref in a.reference_csv:
        print(f"\n## As the kernel reads them, at the points of `{os.path.basename(ref)}`\n")
        print("Cycles' own lookup (linear between edge texels in r, mu and z = sqrt(|ior-1|/(ior+1))), "
              "GGX correlated rows only; eta = 1 rows apart (Cycles returns 1 there).\n")
        print("| table | side | points | max err (peer - exact, where) | mean abs err |")
        print("|---|---|---|---|---|")
        stats = {}
        with open(ref) as f:
            for r in csv.DictReader(line for line in f if not line.startswith("#")):
                if r["ndf"] != "ggx" or r["smith"] != "correlated" or \
                        r["table"] not in ("glass_E", "glass_Eavg"):
                    continue
                kind = "E" if r["table"] == "glass_E" else "Eavg"
                eta, rough = float(r["eta"]), float(r["roughness"])
                mu = float(r["mu"]) if kind == "E" else None
                v, name = cycles_read(tables, kind, rough, mu, eta)
                if v is None:
                    continue
                side = "eta = 1" if eta == 1.0 else ("eta < 1" if eta < 1 else "eta > 1")
                stats.setdefault((name, side), Stat()).add(v - float(r["value"]),
                                                          where_str(rough, mu, eta))
        for (name, side), st in sorted(stats.items()):
            print(f"| {name} | {side} | {st.cells()} |")


if __name__ == "__main__":
    main()
