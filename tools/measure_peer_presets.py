#!/usr/bin/python3
"""Each engine's own shipped table against lutbake's exact values in the engine's layout:
max and RMS difference, and where the max is (docs/presets.md).

Usage:
    /usr/bin/python3 tools/measure_peer_presets.py PEER_DIR LUTBAKE [CYCLES_DIR]

PEER_DIR holds the peers' tables as CSV (extracted from each project's source, conventions in
each file's comments; not bundled except the five under tests/data/presets/):
  cycles_table_ggx_E.csv          Blender Cycles table_ggx_E (tests/data/presets/)
  threejs_dfg_lut_16x16.csv       three.js DFGLUTData.js, current (tests/data/presets/)
  threejs_dfg_lut_32x32.csv       three.js DFGLUTData.js, r181 (tests/data/presets/)
  filament_dfg_64x64.csv          Filament v1.19.0 dfg.inc, mobile size (tests/data/presets/)
  ibl_brdf_lut_png_website_copy.csv  LearnOpenGL's website ibl_brdf_lut.png (8-bit, 256^2)
  lut_sheen_E_current_1024x1024.csv  glTF Sample Renderer assets/images/lut_sheen_E.png
  eevee_brdf_ggx_rows.csv         Blender EEVEE brdf_ggx, 13 of 64 rows (tests/data/presets/)
CYCLES_DIR, if given, is the output of `lutbake bake --preset cycles --out CYCLES_DIR`: its
four glass arrays are compared, value for value in Cycles' own memory order, with Cycles'
shipped ones in tests/data/glass/peers/ (slice 0, ior = 1, apart). A missing file is reported
and skipped. Exact values come from LUTBAKE: `eval` (dfg, sheen_E)
and `furnace` (Schlick-GGX, which eval has no table for) at the peer's own texel coordinates.
Needs numpy.
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

import numpy as np


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def run_json_lines(cmd):
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return [json.loads(line) for line in out.splitlines() if line.strip().startswith("{")]


def eval_points(lutbake, table, mus, rs, extra=()):
    """lutbake eval on the grid mus x rs: {(mu, r): value or [A, B]}."""
    out = {}
    for k in range(0, len(rs), 64):
        chunk = rs[k:k + 64]
        cmd = [lutbake, "eval", "--table", table, "--mu", ",".join(repr(m) for m in mus),
               "--roughness", ",".join(repr(r) for r in chunk), "--json", *extra]
        for p in run_json_lines(cmd):
            out[(round(p["mu"], 12), round(p["roughness"], 12))] = p["value"]
    return out


def report(name, diffs, where):
    d = np.abs(np.asarray(diffs))
    k = int(np.argmax(d))
    print(f"| {name} | {d.max():.2e} | {np.sqrt(np.mean(d * d)):.2e} | {where[k]} |")


def main():
    peer, lutbake = sys.argv[1], sys.argv[2]
    print("| peer table, in its own layout | max difference | RMS | where the max is |")
    print("|---|---|---|---|")
    path = os.path.join(peer, "cycles_table_ggx_E.csv")
    if os.path.exists(path):
        r = rows(path)
        mus = sorted({float(x["mu"]) for x in r})
        rs = sorted({float(x["roughness"]) for x in r})
        ev = eval_points(lutbake, "E", mus, rs)
        diffs, where = [], []
        for x in r:
            v = ev[(round(float(x["mu"]), 12), round(float(x["roughness"]), 12))]
            diffs.append(float(x["cycles_E"]) - (v if not isinstance(v, list) else v[0]))
            where.append(f"mu {float(x['mu']):.4g}, rough {float(x['roughness']):.4g}")
        report("Cycles table_ggx_E 32x32 (E)", diffs, where)
    for size, name in ((16, "threejs_dfg_lut_16x16.csv"), (32, "threejs_dfg_lut_32x32.csv")):
        path = os.path.join(peer, name)
        if not os.path.exists(path):
            print(f"| three.js {size}x{size}: {name} missing | | | |")
            continue
        r = rows(path)
        muk, rk = ("v_NdotV", "u_roughness") if size == 16 else ("NdotV", "roughness")
        ak, bk = ("R_A_scale", "G_B_bias") if size == 16 else ("three_scale_A", "three_bias_B")
        mus = sorted({float(x[muk]) for x in r})
        rs = sorted({float(x[rk]) for x in r})
        ev = eval_points(lutbake, "dfg", mus, rs)
        for c, key in enumerate((ak, bk)):
            diffs = [float(x[key]) - ev[(round(float(x[muk]), 12), round(float(x[rk]), 12))][c]
                     for x in r]
            where = [f"NdotV {float(x[muk]):.4g}, roughness {float(x[rk]):.4g}" for x in r]
            report(f"three.js {size}x{size} ({'AB'[c]})", diffs, where)
    path = os.path.join(peer, "filament_dfg_64x64.csv")
    if os.path.exists(path):
        r = rows(path)
        mus = sorted({float(x["u"]) for x in r})
        rs = sorted({float(x["v"]) for x in r})
        ev = eval_points(lutbake, "dfg", mus, rs)
        sh = eval_points(lutbake, "sheen_E", mus, rs,
                         ("--sheen-visibility", "ashikhmin", "--sheen-alpha", "squared"))
        for label, key, f in (("B", "R_B", lambda a: a[1]), ("E", "G_E", lambda a: a[0] + a[1])):
            diffs = [float(x[key]) - f(ev[(round(float(x["u"]), 12), round(float(x["v"]), 12))])
                     for x in r]
            where = [f"NoV {float(x['u']):.4g}, r {float(x['v']):.4g}" for x in r]
            report(f"Filament dfg.inc 64x64 v1.19.0 ({label}, rows as the shader samples them)",
                   diffs, where)
        diffs = [float(x["B_sheenE_ashikhmin"]) -
                 sh[(round(float(x["u"]), 12), round(float(x["v"]), 12))] for x in r]
        where = [f"NoV {float(x['u']):.4g}, r {float(x['v']):.4g}" for x in r]
        report("Filament dfg.inc 64x64 v1.19.0 (cloth)", diffs, where)
    path = os.path.join(peer, "ibl_brdf_lut_png_website_copy.csv")
    if os.path.exists(path):
        r = [x for x in rows(path) if int(x["i"]) % 8 == 3 and int(x["j"]) % 8 == 3]
        mus = sorted({float(x["NoV"]) for x in r})
        rs = sorted({float(x["roughness"]) for x in r})
        vals = {}
        for f0 in (0, 1):
            for p in json.loads(subprocess.run(
                    [lutbake, "furnace", "--model", "microfacet", "--smith", "schlick-ggx-ibl",
                     "--f0", str(f0), "--parameter", ",".join(repr(x) for x in rs),
                     "--mu", ",".join(repr(x) for x in mus), "--json"],
                    check=True, capture_output=True, text=True).stdout)["albedo"]:
                vals[(f0, round(p["mu"], 12), round(p["parameter"], 12))] = p["value"]
        for c, key in enumerate(("R_A", "G_B")):
            diffs, where = [], []
            for x in r:
                mu, rr = round(float(x["NoV"]), 12), round(float(x["roughness"]), 12)
                b, e = vals[(0, mu, rr)], vals[(1, mu, rr)]
                diffs.append(float(x[key]) - (e - b if c == 0 else b))
                where.append(f"NdotV {mu:.4g}, roughness {rr:.4g}")
            report(f"LearnOpenGL website ibl_brdf_lut.png 256x256 8-bit, every 8th texel "
                   f"({'AB'[c]})", diffs, where)
    path = os.path.join(peer, "lut_sheen_E_current_1024x1024.csv")
    if os.path.exists(path):
        r = [x for x in rows(path) if int(x["i"]) % 16 == 7 and int(x["j"]) % 16 == 7]
        mus = sorted({float(x["u_NdotV"]) for x in r})
        rs = sorted({float(x["v_sheenRoughness"]) for x in r})
        sh = eval_points(lutbake, "sheen_E", mus, rs, ("--sheen-alpha", "squared"))
        for label, key in (("as the shader reads it", "as_sampled_u8"),
                           ("sRGB-decoded", "linear_decoded")):
            diffs = [float(x[key]) - min(1.0, sh[(round(float(x["u_NdotV"]), 12),
                                                  round(float(x["v_sheenRoughness"]), 12))])
                     for x in r]
            where = [f"NdotV {float(x['u_NdotV']):.4g}, r {float(x['v_sheenRoughness']):.4g}"
                     for x in r]
            report(f"glTF Sample Renderer lut_sheen_E.png, every 16th texel ({label})", diffs,
                   where)


    path = os.path.join(peer, "eevee_brdf_ggx_rows.csv")
    if os.path.exists(path):
        eevee(path, lutbake)
    generated(peer, lutbake)

    if len(sys.argv) > 3:
        cycles_glass(sys.argv[3])


def dump_pixels(path):
    """{(x, y): [channel values]} of an image through oiiotool --dumpdata (unorm as 0..1)."""
    out = subprocess.run(["oiiotool", "--dumpdata", path], check=True, capture_output=True,
                         text=True).stdout
    pixels = {}
    for line in out.splitlines():
        line = line.strip()
        if not line.startswith("Pixel ("):
            continue
        where, values = line[len("Pixel ("):].split("):", 1)
        x, y = (int(v) for v in where.split(","))
        if "(" in values:  # integer codes, then the normalised values in parentheses
            values = values.split("(", 1)[1].rstrip(")")
        pixels[(x, y)] = [float(v) for v in values.split()]
    return pixels


def ktx2_half_pixels(path):
    """{(x, y): [channels]} of a 2D KTX2 file of R16G16_SFLOAT (level 0, no supercompression)."""
    with open(path, "rb") as f:
        data = f.read()
    width, height = np.frombuffer(data, "<u4", 2, 20)
    offset, length = np.frombuffer(data, "<u8", 2, 80)
    values = np.frombuffer(data, "<f2", int(length) // 2, int(offset)).astype(float)
    values = values.reshape(int(height), int(width), -1)
    return {(x, y): list(values[y, x]) for y in range(int(height)) for x in range(int(width))}


def bake_preset(lutbake, name, out):
    subprocess.run([lutbake, "bake", "--preset", name, "--out", os.path.join(out, name)],
                   check=True, capture_output=True)
    return os.path.join(out, name)


def generated(peer, lutbake):
    """The engines that build their table at run time (Unreal, Godot, HDRP), against their
    generators re-implemented by tests/presets/engine_generators.py (CSV in PEER_DIR), each texel
    compared in the engine's own layout and storage."""
    names = ("unreal_preintegrated_gf.csv", "godot_dfg.csv", "hdrp_fgd_ggx_disney.csv",
             "hdrp_fgd_charlie.csv", "gltf_lut_ggx.csv", "gltf_lut_charlie.csv")
    if not any(os.path.exists(os.path.join(peer, n)) for n in names):
        print("| run-time generators: none in PEER_DIR (tests/presets/engine_generators.py PEER_DIR) "
              "| | | |")
        return
    with tempfile.TemporaryDirectory() as out:
        path = os.path.join(peer, names[0])
        if os.path.exists(path):
            ours = dump_pixels(os.path.join(bake_preset(lutbake, "unreal", out),
                                            "PreIntegratedGF.png"))
            r = rows(path)
            for c, key in enumerate(("A", "B")):
                diffs = [float(x[key]) - ours[(int(x["i"]), int(x["j"]))][c] for x in r]
                where = [f"NoV {float(x['NoV']):.4g}, Roughness {float(x['roughness']):.4g}"
                         for x in r]
                report(f"Unreal PreIntegratedGF 128x32 unorm16, its generator run here ({key})",
                       diffs, where)
        path = os.path.join(peer, names[1])
        if os.path.exists(path):
            ours = ktx2_half_pixels(os.path.join(bake_preset(lutbake, "godot", out), "dfg.ktx2"))
            r = rows(path)
            for shift, label in ((0, "rows as the shader reads them"),
                                 (1, "row j against the preset's row j - 1, the roughness it "
                                     "integrated")):
                for c, key in enumerate(("R_B", "G_E")):
                    diffs, where = [], []
                    for x in r:
                        i, j = int(x["i"]), int(x["j"])
                        if j - shift < 0:
                            continue
                        diffs.append(float(x[key]) - ours[(i, j - shift)][c])
                        where.append(f"NoV {float(x['NdotV']):.4g}, roughness read "
                                     f"{float(x['roughness_read']):.4g}")
                    report(f"Godot dfg 128x128 RG16F, its generator run here ({key[0]}; {label})",
                           diffs, where)
        for k, (preset, file, keys) in enumerate((
                ("unity-hdrp", "PreIntegratedFGD_GGXDisneyDiffuse.exr", ("R_x", "G_y", "B_z")),
                ("unity-hdrp", "PreIntegratedFGD_CharlieFabricLambert.exr",
                 ("R_x", "G_y", "B_z")))):
            path = os.path.join(peer, names[2 + k])
            if not os.path.exists(path):
                continue
            directory = os.path.join(out, preset)
            if not os.path.exists(directory):
                bake_preset(lutbake, preset, out)
            ours = dump_pixels(os.path.join(directory, file))
            r = rows(path)
            label = ""
            if k == 0:
                # HDRP integrates the column sqrt(NdotV) = 0 at NdotV = FLT_EPS, the preset
                # at 0 (where the shader reads it); that column apart.
                r = [x for x in r if int(x["i"]) > 0]
                label = ", the column NdotV = 0 apart"
            for c, key in enumerate(keys):
                # The engine's texture is 10-bit unorm: the preset's exact value clamped to
                # [0, 1] is what that storage can hold.
                diffs = [float(x[key]) - min(1.0, max(0.0, ours[(int(x["i"]), int(x["j"]))][c]))
                         for x in r]
                where = [f"NdotV {float(x['NdotV']):.4g}, perceptualRoughness "
                         f"{float(x['perceptual_roughness']):.4g}" for x in r]
                report(f"HDRP {file[:-4]} 64x64 10-bit, its generator run here ({key}{label})",
                       diffs, where)
        # The glTF Sample Renderer's lut_ggx and lut_charlie (1024^2, RGBA16F, 512 samples),
        # every 16th texel; the preset's PNGs hold row j at roughness (j + 0.5) / 1024 as the
        # pass does (PNG row 0 uploaded as texture row 0).
        for k, (file, keys) in enumerate((("lut_ggx.png", (("R_A", 0), ("G_B", 1))),
                                          ("lut_charlie.png", (("B_sheen_E", 2),)))):
            path = os.path.join(peer, names[4 + k])
            if not os.path.exists(path):
                continue
            if k == 1:
                # The preset's lut_charlie.png is 256^2 (the shader's normalised coordinates
                # take any size): the exact values of its model (Charlie D at alpha = r^2,
                # Ashikhmin V) at the generator's points instead.
                r = rows(path)
                mus = sorted({float(x["NdotV"]) for x in r})
                rs = sorted({float(x["roughness"]) for x in r})
                sh = eval_points(lutbake, "sheen_E", mus, rs,
                                 ("--sheen-visibility", "ashikhmin", "--sheen-alpha", "squared"))
                diffs = [float(x["B_sheen_E"]) -
                         sh[(round(float(x["NdotV"]), 12), round(float(x["roughness"]), 12))]
                         for x in r]
                where = [f"NdotV {float(x['NdotV']):.4g}, roughness {float(x['roughness']):.4g}"
                         for x in r]
                report("glTF Sample Renderer lut_charlie 1024x1024 RGBA16F, its generator run "
                       "here, every 16th texel (B, against the preset's model)", diffs, where)
                continue
            directory = os.path.join(out, "gltf-sample-renderer")
            if not os.path.exists(directory):
                bake_preset(lutbake, "gltf-sample-renderer", out)
            ours = dump_pixels(os.path.join(directory, file))
            r = rows(path)
            for key, c in keys:
                diffs = [float(x[key]) - ours[(int(x["i"]), int(x["j"]))][c] for x in r]
                where = [f"NdotV {float(x['NdotV']):.4g}, roughness {float(x['roughness']):.4g}"
                         for x in r]
                report(f"glTF Sample Renderer {file[:-4]} 1024x1024 RGBA16F, its generator run "
                       f"here, every 16th texel ({key})", diffs, where)


def eevee(path, lutbake):
    """Blender's brdf_ggx[j][i][c] rows against the eevee preset's brdf_ggx.inc, same order."""
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([lutbake, "bake", "--preset", "eevee", "--out", os.path.join(out, "e")],
                       check=True, capture_output=True)
        with open(os.path.join(out, "e", "brdf_ggx.inc")) as f:
            body = " ".join(line for line in f if not line.startswith("//"))
    ours = [float(v.strip().rstrip("f")) for v in body.split(",") if v.strip()]
    assert len(ours) == 64 * 64 * 3, len(ours)
    # The last row apart: Blender integrated it at NV = 1e-4 (its generator's clamp), the preset
    # at NV = 0, where the shader samples it.
    for label, keep in (("rows 0 to 62", lambda j: j < 63), ("row 63, NV 1e-4 vs 0", lambda j: j == 63)):
        r = [x for x in rows(path) if keep(int(x["j"]))]
        for c, key in enumerate(("blender_A", "blender_B")):
            diffs, where = [], []
            for x in r:
                i, j = int(x["i"]), int(x["j"])
                diffs.append(float(x[key]) - ours[(j * 64 + i) * 3 + c])
                where.append(f"sqrt(1 - NV) {j}/63, roughness {i}/63")
            report(f"EEVEE brdf_ggx 64x64 ({'AB'[c]}; {len(r) // 64} of its rows: {label})",
                   diffs, where)


def c_array_values(path):
    """The literals between a lutbake C array's value markers."""
    with open(path) as f:
        text = f.read()
    block = text.split("// lutbake-values-begin")[1].split("// lutbake-values-end")[0]
    return [float(v.strip().rstrip("f")) for v in block.replace("\n", " ").split(",") if v.strip()]


def cycles_glass(baked):
    peers = os.path.join(os.path.dirname(__file__), "..", "tests", "data", "glass", "peers")
    for name in ("glass_E", "glass_inv_E", "glass_Eavg", "glass_inv_Eavg"):
        ours = c_array_values(os.path.join(baked, f"table_ggx_{name}.h"))
        r = rows(os.path.join(peers, f"cycles_ggx_{name}.csv"))
        assert len(ours) == len(r), (name, len(ours), len(r))
        diffs, where = [], []
        for k, x in enumerate(r):  # the CSV is in Cycles' memory order
            if int(x["iz"]) == 0:
                continue
            diffs.append(float(x["value"]) - ours[k])
            mu = f", mu {float(x['mu']):.3g}" if x["mu"] else ""
            where.append(f"rough {float(x['rough']):.3g}{mu}, ior {float(x['ior']):.4g}")
        report(f"Cycles table_ggx_{name} ({len(diffs)} texels, the slice ior = 1 apart)", diffs, where)


if __name__ == "__main__":
    main()
