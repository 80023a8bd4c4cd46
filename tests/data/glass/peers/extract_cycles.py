#!/usr/bin/python3
"""Write Blender Cycles' precomputed microfacet albedo tables as CSV, with their axes.

Input: Cycles' `shader.tables` (blender/blender intern/cycles/scene/shader.tables, or the
standalone mirror blender/cycles src/scene/shader.tables; Apache-2.0, Copyright 2011-2022
Blender Foundation). Output, beside this script (or --out): one CSV per table,
cycles_<name>.csv, in long form with the index of every texel and the axis values at which
Cycles' generator (intern/cycles/app/cycles_precompute.cpp) evaluated it:

  rough = clamp(ix / (nx - 1), 1e-4, 1)   Cycles' "roughness": alpha = rough^2
  mu    = clamp(iy / (ny - 1), 1e-4, 1)   cos(theta) of the incoming direction
  z     = clamp(iz / (nz - 1), 1e-4, 0.99), ior = ior_from_F0(z^4) = (1 + z^2) / (1 - z^2)
          (float32, as the generator computes it; the *_inv_* tables were baked at 1/ior)

and `value` exactly as printed in the file (std::to_string, 6 decimals). The numbers are
Blender Foundation's (Apache-2.0); this script and the CSV layout are lutbake's.

Usage: extract_cycles.py SHADER_TABLES [--out DIR] [--source 'repo@commit path']
"""
import argparse
import os
import re

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))

# name -> (nx, ny, nz, axes): nx = roughness, ny = mu (1: averaged over mu), nz = IOR (1: none)
TABLES = {
    "ggx_E": (32, 32, 1),
    "ggx_Eavg": (32, 1, 1),
    "ggx_glass_E": (16, 16, 16),
    "ggx_glass_Eavg": (16, 1, 16),
    "ggx_glass_inv_E": (16, 16, 16),
    "ggx_glass_inv_Eavg": (16, 1, 16),
    "ggx_gen_schlick_ior_s": (16, 16, 16),
}


def f32(v):
    return np.float32(v)


def ior_of_z(z):
    """ior_from_F0(sqr(sqr(z))) in float32 (bsdf_util.h: sqrt_f0 = sqrtf(clamp(f0, 0, 0.99)))."""
    z = f32(z)
    f0 = f32(f32(z * z) * f32(z * z))
    s = np.sqrt(np.clip(f0, f32(0.0), f32(0.99)), dtype=np.float32)
    return float(f32(f32(1.0) + s) / f32(f32(1.0) - s))


def axis(i, n, lo, hi):
    if n == 1:
        return None
    return float(np.clip(f32(f32(i) / f32(n - 1)), f32(lo), f32(hi)))


def parse(path):
    text = open(path).read()
    out = {}
    for m in re.finditer(r"static const float table_(\w+)\[(\d+)\]\s*=\s*\{(.*?)\};", text, re.S):
        vals = re.findall(r"(-?\d+\.\d+)f", m.group(3))
        line = text.count("\n", 0, m.start()) + 1
        out[m.group(1)] = (vals, line)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("shader_tables")
    ap.add_argument("--out", default=HERE)
    ap.add_argument("--source", default="blender/cycles@97dbe6f57cdf4ede2d2b75ebdda507c8712edb7a "
                    "src/scene/shader.tables (= blender/blender intern/cycles/scene/shader.tables)")
    a = ap.parse_args()
    tabs = parse(a.shader_tables)
    for name, (nx, ny, nz) in TABLES.items():
        if name not in tabs:
            print("missing", name)
            continue
        vals, line = tabs[name]
        assert len(vals) == nx * ny * nz, (name, len(vals))
        path = os.path.join(a.out, f"cycles_{name}.csv")
        with open(path, "w") as f:
            f.write(f"# Blender Cycles table_{name}[{len(vals)}], {a.source}, line {line}.\n")
            f.write("# Copyright 2011-2022 Blender Foundation, Apache-2.0 (the numbers); extracted by\n")
            f.write("# tests/data/glass/peers/extract_cycles.py; conventions in tests/data/glass/README.md.\n")
            f.write("# index = (iz * ny + iy) * nx + ix; rough, mu, z, ior: where the generator evaluated\n")
            f.write("# the texel (alpha = rough^2; ior = (1 + z^2)/(1 - z^2), float32; *_inv_* at 1/ior).\n")
            f.write("ix,iy,iz,rough,mu,z,ior,value\n")
            for iz in range(nz):
                z = axis(iz, nz, 1e-4, 0.99)
                ior = ior_of_z(z) if z is not None else ""
                for iy in range(ny):
                    mu = axis(iy, ny, 1e-4, 1.0)
                    for ix in range(nx):
                        r = axis(ix, nx, 1e-4, 1.0)
                        v = vals[(iz * ny + iy) * nx + ix]
                        fmt = lambda q: "" if q is None or q == "" else f"{q:.9g}"
                        f.write(f"{ix},{iy if ny > 1 else ''},{iz if nz > 1 else ''},{fmt(r)},"
                                f"{fmt(mu)},{fmt(z)},{fmt(ior)},{v}\n")
        print("wrote", path, len(vals))


if __name__ == "__main__":
    main()
