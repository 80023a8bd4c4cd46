#!/usr/bin/python3
"""Four engines' own split-sum / DFG table generators, re-implemented (not copied) in numpy with
float32 arithmetic where the engine computes in float, so that lutbake can be compared with "the
engine's own table". Each table is written in the engine's own memory layout, after the engine's
storage quantisation (unorm16, half float, 10-bit unorm), as a CSV with '#' header lines.

Usage:
    /usr/bin/python3 tests/presets/engine_generators.py OUT_DIR [--stride N] [engine ...]

engines (default: unreal godot hdrp_ggx hdrp_charlie gltf_ggx gltf_charlie):
  unreal         -> unreal_preintegrated_gf.csv
      Unreal Engine 4 FSystemTextures PreintegratedGF (128 x 32, G16R16)
      windystrife/UnrealEngine_NVIDIAGameWorks@0f9675ae7119323ea973b2adde381b6f71eaead9
      Engine/Source/Runtime/Renderer/Private/SystemTextures.cpp
  godot          -> godot_dfg.csv
      Godot 4.5+ Forward+ DFG LUT (128 x 128, RG16F), the merged form of godotengine/godot PR #103934:
      servers/rendering/renderer_rd/shaders/forward_clustered/integrate_dfg.glsl (rg16f, no cloth
      channel, row y integrated at roughness (128 - y + 0.5) / 128), dispatched in
      servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.cpp and read in
      .../shaders/forward_clustered/scene_forward_clustered_inc.glsl (both godotengine/godot@00618982)
  godot_e8387d   -> godot_dfg_e8387d.csv (not in the default set)
      the same integrand with the row mapping of godotengine/godot@e8387d695efee663e2f427bd427792a6f0c633f0
      (invocation y integrates roughness (y + 0.5) / 128 and is stored in row 127 - y)
  hdrp_ggx       -> hdrp_fgd_ggx_disney.csv
  hdrp_charlie   -> hdrp_fgd_charlie.csv
  hdrp           -> both HDRP tables
      Unity HDRP PreIntegratedFGD (64 x 64, A2B10G10R10_UNormPack32), Unity-Technologies/Graphics:
      com.unity.render-pipelines.high-definition/Runtime/Material/PreIntegratedFGD/
        preIntegratedFGD_GGXDisneyDiffuse.shader (@2650bc9c300af36ecd22611f19625ae04dd787e9),
        preIntegratedFGD_CharlieFabricLambert.shader (@0b31872d981ed083e13891aabbd258e2e0cee94e),
        PreIntegratedFGD.cs / .hlsl (GraphicsFormat.A2B10G10R10_UNormPack32; reads),
      com.unity.render-pipelines.core/ShaderLibrary/ImageBasedLighting.hlsl
        (IntegrateGGXAndDisneyDiffuseFGD, @7dae456904eedb01a451a0e8dc52217d5cbe7471),
      .../ShaderLibrary/BSDF.hlsl, Sampling/Sampling.hlsl, Sampling/Hammersley.hlsl, CommonLighting.hlsl,
      Common.hlsl (helpers).
  gltf_ggx       -> gltf_lut_ggx.csv
  gltf_charlie   -> gltf_lut_charlie.csv
  ospray_ggx, ospray_glass, ospray_reflection, ospray_sheen -> ospray_ggx.csv, ospray_dielectric.csv,
                    ospray_dielectric_reflection.csv, ospray_sheen.csv (not in the default set)
      OSPRay MicrofacetAlbedoTables.ispc: GGX E 32 x 32 and its averages, the dielectric (eta in
      [1/3, 1]) and its reflection alone 16^3, the sheen albedo 16^2 (OSPRay's softened light
      Lambda), 1024 stratified samples, float
  materialx      -> materialx_albedo_table.csv (not in the default set)
      MaterialX mx_generate_dir_albedo_table: 128 x 128, 64 spherical Fibonacci samples, float
  gltf           -> both glTF tables
      KhronosGroup glTF Sample Renderer lut_ggx (R = A, G = B) and lut_charlie (B = sheen albedo), 1024 x 1024, 512 samples,
      RGBA16F, rendered at start-up: source/shaders/ibl_filtering.frag (@d3d2f605306756e76396073d3aef81b71012c16d, LUT()),
      source/ibl_sampler.js (@d0a1feac0c3cf41af6b05757f11f358bb5b3ebeb, sampleLut(), createLutTexture()), read in
      source/Renderer/shaders/ibl.glsl (@79f90e28d7951352833398695eb16de606a4fa63) at vec2(NdotV, perceptual roughness).
      A full table is 1024^2 x 512 samples; --stride N (default 16) lists only texels with i % N == j % N == (N - 1) // 2
      (64 x 64 texels by default, about a second each; --stride 1 is the full table: 256 times the work).

After each table a few sanity figures are printed (limits at roughness -> 0, A + B <= 1, smoothness).
numpy only; each table takes a few seconds (the glTF ones at the default stride). GPU transcendental functions (sin, cos, pow, exp) are
emulated with numpy's float32 ones, which are close to but not bit-identical with any GPU's.
"""
import math
import os
import sys
import time

import numpy as np

F = np.float32


def f32(x):
    return np.asarray(x, dtype=np.float32)


def reverse_bits32(i):
    return int("{:032b}".format(i)[::-1], 2)


def sin_cos_f32(angle):
    """sin and cos of a float32 angle, rounded to float32 (what a good libm sinf/cosf returns)."""
    a = float(F(angle))
    return F(math.sin(a)), F(math.cos(a))


def normalize3(x, y, z):
    inv = F(1.0) / np.sqrt(x * x + y * y + z * z)
    return x * inv, y * inv, z * inv


# ---------------------------------------------------------------------------------------------
# Unreal Engine 4: FSystemTextures::InitializeFeatureLevelDependentTextures, PreintegratedGF block
# (Engine/Source/Runtime/Renderer/Private/SystemTextures.cpp). Computed on the CPU in float.
# ---------------------------------------------------------------------------------------------
UNREAL_SRC = ("windystrife/UnrealEngine_NVIDIAGameWorks@0f9675ae7119323ea973b2adde381b6f71eaead9 "
              "Engine/Source/Runtime/Renderer/Private/SystemTextures.cpp (PreintegratedGF)")


def unreal_table():
    width, height, nsamp = 128, 32, 128
    pi = F(3.1415926535897932)
    rough = (f32(np.arange(height)) + F(0.5)) / F(height)          # row y
    nov = (f32(np.arange(width)) + F(0.5)) / F(width)              # column x
    R = rough[:, None] * np.ones((1, width), F)
    NoV = np.ones((height, 1), F) * nov[None, :]
    m = R * R
    m2 = m * m
    Vx = np.sqrt(F(1.0) - NoV * NoV)
    Vz = NoV
    A = np.zeros_like(R)
    B = np.zeros_like(R)
    for i in range(nsamp):
        e1 = F(i) / F(nsamp)
        e2 = F(reverse_bits32(i) / 4294967296.0)                   # double division, then float
        phi = F(2.0) * pi * e1
        sphi, cphi = sin_cos_f32(phi)
        cos_t = np.sqrt((F(1.0) - e2) / (F(1.0) + (m2 - F(1.0)) * e2))
        sin_t = np.sqrt(F(1.0) - cos_t * cos_t)
        Hx, Hy, Hz = sin_t * cphi, sin_t * sphi, cos_t
        vdh = Vx * Hx + F(0.0) * Hy + Vz * Hz
        s = F(2.0) * vdh
        Lz = s * Hz - Vz
        NoL = np.maximum(Lz, F(0.0))
        NoH = np.maximum(Hz, F(0.0))
        VoH = np.maximum(vdh, F(0.0))
        ok = NoL > F(0.0)
        vis_v = NoL * (NoV * (F(1.0) - m) + m)
        vis_l = NoV * (NoL * (F(1.0) - m) + m)
        with np.errstate(divide="ignore", invalid="ignore"):
            vis = F(0.5) / (vis_v + vis_l)
            w = NoL * vis * (F(4.0) * VoH / NoH)
        fc = F(1.0) - VoH
        fc = fc * np.square(fc * fc)
        A = np.where(ok, A + w * (F(1.0) - fc), A)
        B = np.where(ok, B + w * fc, B)
    A = A / F(nsamp)
    B = B / F(nsamp)
    qa = (np.clip(A, F(0), F(1)) * F(65535.0) + F(0.5)).astype(np.int32)   # (int32) truncation
    qb = (np.clip(B, F(0), F(1)) * F(65535.0) + F(0.5)).astype(np.int32)
    header = [
        "Unreal Engine 4 PreintegratedGF (the environment BRDF texture), generated at run time on the CPU",
        "source: " + UNREAL_SRC,
        "layout: 128 x 32 texels, PF_G16R16 (PF_R8G8 only where G16R16 is unsupported); memory row y = j, column x = i,",
        "  row 0 first; i: NoV = (i + 0.5) / 128, j: Roughness = (j + 0.5) / 32 (perceptual), alpha m = Roughness^2",
        "samples: 128 per texel, Hammersley (phi = 2 pi i / 128, E2 = reversebits32(i) / 2^32 drives cos theta),",
        "  GGX half-vector sampling with m^2, Vis = 0.5 / (NoL (NoV (1 - m) + m) + NoV (NoL (1 - m) + m)), weight NoL Vis 4 VoH / NoH",
        "channels: R = A = sum w (1 - Fc) / 128 (scale), G = B = sum w Fc / 128 (bias), Fc = (1 - VoH)^5; stored",
        "  (int)(clamp(v, 0, 1) * 65535 + 0.5); A, B below = code / 65535 as the sampler returns them",
    ]
    cols = ["i", "j", "NoV", "roughness", "A", "B", "A_u16", "B_u16"]
    rows = []
    for j in range(height):
        for i in range(width):
            rows.append([i, j, "%.9g" % nov[i], "%.9g" % rough[j],
                         "%.9g" % (qa[j, i] / 65535.0), "%.9g" % (qb[j, i] / 65535.0), qa[j, i], qb[j, i]])
    checks = sanity_split_sum("unreal", qa / 65535.0, qb / 65535.0, nov, rough, "A", "B")
    return header, cols, rows, checks


# ---------------------------------------------------------------------------------------------
# Godot 4.5+ Forward+: integrate_dfg.glsl compute shader (8 x 8 groups over 128 x 128), RG16F image.
# ---------------------------------------------------------------------------------------------
GODOT_SRC = ("godotengine/godot servers/rendering/renderer_rd/shaders/forward_clustered/integrate_dfg.glsl, "
             "merged form of PR #103934 (layout rg16f, integrate_brdf without cloth, "
             "roughness = (SIZE - y + 0.5) / SIZE, imageStore at (x, y)); dispatch and RG16F texture: "
             "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.cpp @00618982cfeb8b2647feac6d0e1caa95fbaa9f45; "
             "read: scene_forward_clustered_inc.glsl prefiltered_dfg() @00618982 textureLod(dfg, vec2(NoV, 1 - roughness)).rg")
GODOT_E8387D_SRC = ("godotengine/godot@e8387d695efee663e2f427bd427792a6f0c633f0 "
                    "servers/rendering/renderer_rd/shaders/forward_clustered/integrate_dfg.glsl "
                    "(rgba16f with a cloth channel; invocation y integrates roughness (y + 0.5) / SIZE, stored at row SIZE - 1 - y)")


def godot_integrate(nv_row, rough_col, nsamp=1024):
    """R, G = integrate_brdf(NdotV, roughness) on the grid rough_col (rows) x nv_row (columns)."""
    m_pi = F(3.14159265359)
    rough = rough_col[:, None] * np.ones((1, nv_row.size), F)
    ndv = np.ones((rough_col.size, 1), F) * nv_row[None, :]
    a = rough * rough
    a2m1 = a * a - F(1.0)
    k = (rough * rough) / F(2.0)                                # geometry_schlick_ggx: a = roughness, k = a^2 / 2
    vx = np.sqrt(F(1.0) - ndv * ndv)
    vz = ndv
    g_v = vz / (vz * (F(1.0) - k) + k)                          # saturate(dot(n, v)) = v.z
    A = np.zeros_like(rough)
    B = np.zeros_like(rough)
    for i in range(nsamp):
        xi_x = F(i) / F(nsamp)
        xi_y = F(float(reverse_bits32(i))) * F(2.3283064365386963e-10)
        phi = F(2.0) * m_pi * xi_x
        sphi, cphi = sin_cos_f32(phi)
        cos_t = np.sqrt((F(1.0) - xi_y) / (F(1.0) + a2m1 * xi_y))
        sin_t = np.sqrt(F(1.0) - cos_t * cos_t)
        hx, hy, hz = cphi * sin_t, sphi * sin_t, cos_t
        # N = +z: up = (1, 0, 0), tangent = (0, -1, 0), bitangent = (1, 0, 0): world = (H.y, -H.x, H.z)
        hx, hy, hz = normalize3(hy, -hx, hz)
        vdh_raw = vx * hx + vz * hz
        s = F(2.0) * vdh_raw
        lx, ly, lz = normalize3(s * hx - vx, s * hy, s * hz - vz)
        ndl = np.clip(lz, F(0), F(1))
        ndh = np.clip(hz, F(0), F(1))
        vdh = np.clip(vdh_raw, F(0), F(1))
        ok = ndl > F(0.0)
        g_l = ndl / (ndl * (F(1.0) - k) + k)
        G = g_l * g_v
        with np.errstate(divide="ignore", invalid="ignore"):
            g_vis = (G * vdh) / (ndh * vz)
        fc = np.power(F(1.0) - vdh, F(5.0))
        A = np.where(ok, A + fc * g_vis, A)
        B = np.where(ok, B + g_vis, B)
    return A / F(nsamp), B / F(nsamp)


def godot_table(variant="master"):
    size = 128
    nv = (f32(np.arange(size)) + F(0.5)) / F(size)
    y = np.arange(size)
    if variant == "master":
        rough_row = (F(size) - f32(y) + F(0.5)) / F(size)          # row y holds what invocation y integrated
        src = GODOT_SRC
    else:
        rough_inv = (f32(y) + F(0.5)) / F(size)                     # invocation y
        rough_row = rough_inv[::-1].copy()                          # stored at row 127 - y
        src = GODOT_E8387D_SRC
    A, B = godot_integrate(nv, rough_row)
    hA = A.astype(np.float16)
    hB = B.astype(np.float16)
    fmt = ("RD::DATA_FORMAT_R16G16_SFLOAT (RG16F)" if variant == "master" else
           "RG16F as master here (the e8387d shader declares rgba16f and writes a cloth term into B, not reproduced)")
    header = [
        "Godot 4.5+ Forward+ DFG LUT, generated at start-up by a compute shader (8 x 8 invocations per group, one per texel)",
        "source: " + src,
        "layout: 128 x 128 texels, " + fmt + "; memory row y = j (image row 0 first, = sampler v near 0),",
        "  column x = i; i: NdotV = (i + 0.5) / 128 (integrated and read alike);",
        "  j: roughness_integrated = the perceptual roughness the generator integrated row j at (alpha = roughness^2);",
        "  roughness_read = 1 - (j + 0.5) / 128 = the roughness whose lookup lands on row j's centre (prefiltered_dfg reads v = 1 - roughness)",
        "samples: 1024 per texel, Hammersley (phi = 2 pi i / 1024 on a frame rotated by -90 deg about N, radical inverse drives cos theta),",
        "  GGX half vectors with a = roughness^2, G = Schlick-GGX G1(NdotV) G1(NdotL) with k = roughness^2 / 2 = alpha / 2, weight G VdotH / (NdotH NdotV)",
        "channels: R = sum Fc w / 1024 (Fresnel-weighted part, = lutbake B), G = sum w / 1024 (= E = A + B), Fc = (1 - VdotH)^5;",
        "  stored as float16 (round to nearest even, as numpy; Vulkan allows RTZ too); R, G below are the half values",
    ]
    cols = ["i", "j", "NdotV", "roughness_integrated", "roughness_read", "R_B", "G_E", "R_half_hex", "G_half_hex"]
    rows = []
    for j in range(size):
        rr = 1.0 - (j + 0.5) / size
        for i in range(size):
            rows.append([i, j, "%.9g" % nv[i], "%.9g" % rough_row[j], repr(rr),
                         repr(float(hA[j, i])), repr(float(hB[j, i])),
                         "0x%04x" % hA[j, i].view(np.uint16), "0x%04x" % hB[j, i].view(np.uint16)])
    # sanity in terms of the split-sum pair: A_scale = E - B, B_bias = R
    E = hB.astype(np.float64)
    Bb = hA.astype(np.float64)
    order = np.argsort(rough_row)
    checks = sanity_split_sum("godot" if variant == "master" else "godot_e8387d",
                              (E - Bb)[order], Bb[order], nv, rough_row[order], "G-R", "R")
    return header, cols, rows, checks


# ---------------------------------------------------------------------------------------------
# Unity HDRP PreIntegratedFGD: full-screen pixel shaders into a 64 x 64 A2B10G10R10 render texture.
# ---------------------------------------------------------------------------------------------
HDRP_RES = 64
HDRP_SAMPLES = 4096
TWO_PI = F(6.28318530717958647693)
INV_PI = F(0.31830988618379067154)
FLT_EPS = F(5.960464478e-8)
FLT_MIN = F(1.175494351e-38)

HDRP_COMMON = [
    "format: RenderTexture GraphicsFormat.A2B10G10R10_UNormPack32 (older: RenderTextureFormat.ARGB2101010, linear), bilinear, clamp;",
    "  R, G, B stored as 10-bit unorm code = round(saturate(v) * 1023); columns R, G, B = code / 1023 as the sampler returns them",
    "memory: texel (i, j), i = column, j = row along the sampler's v; the full-screen triangle's TEXCOORD0 is ((i + 0.5) / 64, (j + 0.5) / 64)",
    "  on both D3D (UNITY_UV_STARTS_AT_TOP flips it to match row 0 = top) and GL (row 0 = bottom), so row j = v index, j = 0 first",
]


def hdrp_quantize(v):
    return np.rint(np.clip(v, F(0), F(1)).astype(np.float64) * 1023.0).astype(np.int32)


def hdrp_ggx_table():
    res, nsamp = HDRP_RES, HDRP_SAMPLES
    tc = (np.arange(res) + 0.5) / res                                # exact in float32
    tc = f32(tc)
    rcp_len = F(res) * (F(1.0) / F(res - 1))                       # RemapHalfTexelCoordTo01
    start = F(0.5) * (F(1.0) / F(res - 1))
    c01 = np.clip(tc * rcp_len - start, F(0), F(1))
    nv_col = c01 * c01                                               # NdotV = coordLUT.x^2
    pr_row = c01                                                     # perceptualRoughness = coordLUT.y
    alpha = (pr_row * pr_row)[:, None] * np.ones((1, res), F)       # PerceptualRoughnessToRoughness
    ndv = np.ones((res, 1), F) * np.maximum(nv_col, FLT_EPS)[None, :]
    vx = np.sqrt(F(1.0) - ndv * ndv)
    vz = ndv
    a2 = alpha * alpha
    part_v = np.sqrt((-ndv * a2 + ndv) * ndv + a2)                  # GetSmithJointGGXPartLambdaV
    pr_disney = np.sqrt(alpha)                                       # RoughnessToPerceptualRoughness
    acc_x = np.zeros_like(alpha)
    acc_y = np.zeros_like(alpha)
    acc_z = np.zeros_like(alpha)
    rcp_disney = F(1.0) / F(1.03571)
    for i in range(nsamp):
        ux = F(i) / F(nsamp)                                         # Hammersley2d: (i / N, radical inverse)
        uy = F(float(reverse_bits32(i))) * F(1.0 / 4294967296.0)
        # SampleGGXDir (localToWorld = identity): cos theta from u.x, phi from u.y
        numer = F(1.0) - ux
        denom = F(1.0) + (a2 - F(1.0)) * ux
        with np.errstate(divide="ignore", invalid="ignore"):
            cos_t = np.sqrt(np.where(numer != denom, numer / denom, F(1.0)))
        sphi, cphi = sin_cos_f32(TWO_PI * uy)
        sin_t = np.sqrt(np.clip(F(1.0) - cos_t * cos_t, F(0), F(1)))
        hx, hy, hz = cphi * sin_t, sphi * sin_t, cos_t
        vdh = np.clip(vx * hx + vz * hz, F(0), F(1))
        two_vdh = F(2.0) * vdh
        lz = -vz + two_vdh * hz
        ndl = lz
        lam_v = ndl * part_v
        lam_l = ndv * np.sqrt((-ndl * a2 + ndl) * ndl + a2)
        with np.errstate(divide="ignore", invalid="ignore"):
            vis = F(0.5) / np.maximum(lam_v + lam_l, FLT_MIN)
            w = F(4.0) * vis * ndl * vdh / hz
        ok = ndl > F(0.0)
        fc = np.power(F(1.0) - vdh, F(5.0))
        acc_x = np.where(ok, acc_x + w * fc, acc_x)
        acc_y = np.where(ok, acc_y + w, acc_y)
        # ImportanceSampleLambert: L = SafeNormalize(N + SampleSphereUniform(u.x, u.y)), weight 1
        sphi2, cphi2 = sphi, cphi                                    # same phi = 2 pi u.y
        cos2 = F(1.0) - F(2.0) * ux
        sin2 = np.sqrt(np.clip(F(1.0) - cos2 * cos2, F(0), F(1)))
        px, py, pz = cphi2 * sin2, sphi2 * sin2, F(1.0) + cos2
        inv = F(1.0) / np.sqrt(np.maximum(FLT_MIN, px * px + py * py + pz * pz))
        Lx, Lz = px * inv, pz * inv
        ndl2 = np.clip(Lz, F(0), F(1))
        if ndl2 > F(0.0):
            ldv = Lx * vx + Lz * vz
            fd90 = F(0.5) + (pr_disney + pr_disney * ldv)
            xl = F(1.0) - ndl2
            x5l = xl * (xl * xl) * (xl * xl)
            xv = F(1.0) - ndv
            x5v = xv * (xv * xv) * (xv * xv)
            light = (fd90 - F(1.0)) * x5l + F(1.0)
            view = (fd90 - F(1.0)) * x5v + F(1.0)
            acc_z = acc_z + rcp_disney * (light * view)
    acc_x = acc_x / F(nsamp)
    acc_y = acc_y / F(nsamp)
    acc_z = acc_z / F(nsamp) - F(0.5)
    qx, qy, qz = hdrp_quantize(acc_x), hdrp_quantize(acc_y), hdrp_quantize(acc_z)
    header = [
        "Unity HDRP PreIntegratedFGD_GGXDisneyDiffuse (_PreIntegratedFGD_GGXDisneyDiffuse), rendered once at run time",
        "source: Unity-Technologies/Graphics com.unity.render-pipelines.high-definition/Runtime/Material/PreIntegratedFGD/"
        "preIntegratedFGD_GGXDisneyDiffuse.shader @2650bc9c300af36ecd22611f19625ae04dd787e9 + PreIntegratedFGD.cs (format) + "
        "PreIntegratedFGD.hlsl (read); com.unity.render-pipelines.core/ShaderLibrary/ImageBasedLighting.hlsl "
        "IntegrateGGXAndDisneyDiffuseFGD @7dae456904eedb01a451a0e8dc52217d5cbe7471, BSDF.hlsl, Sampling/*.hlsl",
    ] + HDRP_COMMON + [
        "generator: coordLUT = RemapHalfTexelCoordTo01(TEXCOORD0, 64) = (i / 63, j / 63) (float32); NdotV = coordLUT.x^2 (then max(., FLT_EPS)),",
        "  perceptualRoughness = coordLUT.y, alpha = perceptualRoughness^2; the shader reads it back at Remap01ToHalfTexelCoord(sqrt(NdotV), perceptualRoughness)",
        "samples: 4096 per texel, Hammersley2d(i, 4096) = (i / 4096, reversebits32(i) / 2^32): GGX NDF sampling, cos theta from u.x, phi = 2 pi u.y,",
        "  weight 4 V_SmithJointGGX(height-correlated, exact) NdotL VdotH / NdotH; Disney diffuse with cosine sampling (SampleHemisphereCosine(u.x, u.y, N))",
        "channels: R = x = sum w (1 - VdotH)^5 / 4096 (Fresnel-weighted part, = lutbake B); G = y = sum w / 4096 (= E = A + B);",
        "  B = z = mean DisneyDiffuseNoPI (/1.03571) - 0.5 (the shader adds 0.5 back: diffuse_FGD column); specular FGD = (F90 - F0) x + F0 y",
    ]
    cols = ["i", "j", "u", "v", "NdotV", "perceptual_roughness", "R_x", "G_y", "B_z", "diffuse_FGD",
            "R_u10", "G_u10", "B_u10"]
    rows = []
    for j in range(res):
        for i in range(res):
            rows.append([i, j, "%.9g" % tc[i], "%.9g" % tc[j], "%.9g" % nv_col[i], "%.9g" % pr_row[j],
                         "%.9g" % (qx[j, i] / 1023.0), "%.9g" % (qy[j, i] / 1023.0), "%.9g" % (qz[j, i] / 1023.0),
                         "%.9g" % (qz[j, i] / 1023.0 + 0.5), qx[j, i], qy[j, i], qz[j, i]])
    checks = sanity_split_sum("hdrp_ggx", (qy - qx) / 1023.0, qx / 1023.0, nv_col, pr_row, "G-R", "R")
    d = qz / 1023.0 + 0.5
    mid = (pr_row >= 0.3) & (pr_row <= 0.7)
    checks.append("hdrp_ggx: Disney diffuse FGD (z + 0.5) over perceptual roughness 0.3..0.7: %.4f .. %.4f; at NdotV = 1: %.4f .. %.4f;"
                  " unclamped z range %.4f .. %.4f (saturated codes: %d)"
                  % (d[mid].min(), d[mid].max(), d[:, -1].min(), d[:, -1].max(), acc_z.min(), acc_z.max(),
                     int(((acc_z < 0) | (acc_z > 1)).sum())))
    return header, cols, rows, checks


def charlie_l(x, r):
    r = np.clip(r, F(0), F(1))
    r = F(1.0) - (F(1.0) - r) * (F(1.0) - r)

    def lerp(a, b):
        a, b = F(a), F(b)
        return a + r * (b - a)
    a = lerp(25.3245, 21.5473)
    b = lerp(3.32435, 3.82987)
    c = lerp(0.16801, 0.19823)
    d = lerp(-1.27393, -1.97760)
    e = lerp(-4.85967, -4.32054)
    return a / (F(1.0) + b * np.power(np.abs(x), c)) + d * x + e   # PositivePow = pow(abs(base), power)


def lambda_charlie(ndx, r, l_half):
    lo = np.exp(charlie_l(ndx, r))
    hi = np.exp(F(2.0) * l_half - charlie_l(F(1.0) - ndx, r))
    return np.where(ndx < F(0.5), lo, hi)


def hdrp_charlie_table():
    res, nsamp = HDRP_RES, HDRP_SAMPLES
    tc = f32((np.arange(res) + 0.5) / res)
    nv_col = tc                                                      # NdotV = TEXCOORD0.x
    pr_row = tc                                                      # perceptualRoughness = TEXCOORD0.y
    alpha = (pr_row * pr_row)[:, None] * np.ones((1, res), F)
    ndv_in = np.ones((res, 1), F) * nv_col[None, :]
    vx = np.sqrt(F(1.0) - ndv_in * ndv_in)
    vz = ndv_in
    ndv = np.maximum(vz, F(0.0001))                                  # ClampNdotV(dot(N, V))
    inv_r = F(1.0) / alpha
    l_half = charlie_l(F(0.5), alpha)
    lam_v = lambda_charlie(ndv, alpha, l_half)
    fabric = F(1.0) + alpha * (F(0.5) - F(1.0))                     # FabricLambertNoPI = lerp(1, 0.5, alpha)
    rcp_n = F(1.0) / F(nsamp)
    acc_x = np.zeros_like(alpha)
    acc_y = np.zeros_like(alpha)
    acc_z = np.zeros_like(alpha)
    golden = F(2.3999632297286)
    for i in range(nsamp):
        # SampleConeStrata(i, 1 / N, 0): golden-angle spiral, uniform in solid angle over the hemisphere
        z = F(1.0) - (F(1.0) * F(i)) * rcp_n
        r = np.sqrt(F(1.0) - z * z)
        sa, ca = sin_cos_f32(F(i) * golden)
        lx, ly, lz = r * ca, r * sa, z
        # GetLocalFrame(+z) = rows (-1,0,0), (0,-1,0), (0,0,1): L = (-lx, -ly, lz)
        Lx, Ly, Lz = -lx, -ly, lz
        ndl = lz
        hx, hy, hz = normalize3(vx + Lx, Ly + F(0.0) * vx, vz + Lz)
        ndh = hz
        sin2h = F(1.0) - ndh * ndh
        d_c = INV_PI * ((F(2.0) + inv_r) * np.power(np.abs(sin2h), inv_r * F(0.5)) / F(2.0))
        lam_l = lambda_charlie(F(ndl), alpha, l_half)
        v_c = F(1.0) / ((F(1.0) + lam_v + lam_l) * (F(4.0) * ndv * ndl))
        w = d_c * v_c * ndl
        vdh = vx * hx + vz * hz
        acc_x = acc_x + w * np.power(np.maximum(F(1.0) - vdh, F(0.0)), F(5.0))
        acc_y = acc_y + w
        acc_z = acc_z + fabric * F(1.0)
    acc_x = acc_x * rcp_n
    acc_y = acc_y * rcp_n
    acc_z = acc_z * rcp_n
    qx, qy, qz = hdrp_quantize(acc_x), hdrp_quantize(acc_y), hdrp_quantize(acc_z)
    header = [
        "Unity HDRP PreIntegratedFGD_CharlieFabricLambert (_PreIntegratedFGD_CharlieAndFabric), rendered once at run time",
        "source: Unity-Technologies/Graphics com.unity.render-pipelines.high-definition/Runtime/Material/PreIntegratedFGD/"
        "preIntegratedFGD_CharlieFabricLambert.shader @0b31872d981ed083e13891aabbd258e2e0cee94e (same algorithm as the newest text: "
        "'acc *= 1.0f / sampleCount', 2 pi deferred to the read) + PreIntegratedFGD.hlsl GetPreIntegratedFGDCharlieAndFabricLambert (read) + "
        "core BSDF.hlsl (D_Charlie, V_Charlie, FabricLambertNoPI), Sampling.hlsl (SampleConeStrata), CommonLighting.hlsl (GetLocalFrame)",
    ] + HDRP_COMMON + [
        "generator: NdotV = TEXCOORD0.x = (i + 0.5) / 64, perceptualRoughness = TEXCOORD0.y = (j + 0.5) / 64 (no half-texel remap; the read",
        "  samples float2(NdotV, perceptualRoughness) directly, so each texel centre is read at the values it was integrated at), alpha = perceptualRoughness^2",
        "samples: 4096 per texel, SampleConeStrata (golden-angle spiral, z = 1 - i / 4096) in the frame GetLocalFrame(+z) (azimuth turned 180 deg),",
        "  weight D_Charlie V_Charlie(exact, without the softening) NdotL; Fabric Lambert with cosine sampling (a constant per texel)",
        "channels: R = x = mean w (1 - VdotH)^5, G = y = mean w (the 2 pi of the uniform pdf is applied by the read: specular FGD = lerp(x, y, F0) 2 pi;",
        "  column sheen_E = 2 pi G), B = z = FabricLambertNoPI(alpha) = lerp(1, 0.5, alpha) (diffuse FGD)",
    ]
    cols = ["i", "j", "NdotV", "perceptual_roughness", "R_x", "G_y", "B_z", "sheen_E", "R_u10", "G_u10", "B_u10"]
    rows = []
    for j in range(res):
        for i in range(res):
            rows.append([i, j, "%.9g" % nv_col[i], "%.9g" % pr_row[j],
                         "%.9g" % (qx[j, i] / 1023.0), "%.9g" % (qy[j, i] / 1023.0), "%.9g" % (qz[j, i] / 1023.0),
                         "%.9g" % (2.0 * math.pi * qy[j, i] / 1023.0), qx[j, i], qy[j, i], qz[j, i]])
    e = 2.0 * np.pi * acc_y.astype(np.float64)
    zq = np.rint((1.0 - 0.5 * alpha.astype(np.float64)) * 1023.0)
    checks = ["hdrp_charlie: sheen E = 2 pi y (unquantised) range %.4f .. %.4f; x <= y everywhere: %s; y saturated (> 1) at %d texels;"
              " z codes equal round(1023 lerp(1, 0.5, alpha)) at %d of %d texels, max off by %d (float32 sum of 4096 equal terms)"
              % (e.min(), e.max(), bool((acc_x <= acc_y + 1e-7).all()), int((acc_y > 1).sum()),
                 int((qz == zq).sum()), qz.size, int(np.abs(qz - zq).max()))]
    checks.append("hdrp_charlie: sheen E at the smoothest row (pr %.4f): NdotV %.4f -> %.4f, NdotV %.4f -> %.4f; roughest row: %.4f .. %.4f"
                  % (pr_row[0], nv_col[0], e[0, 0], nv_col[-1], e[0, -1], e[-1].min(), e[-1].max()))
    checks.append(smoothness("hdrp_charlie", "sheen_E", e))
    return header, cols, rows, checks


# ---------------------------------------------------------------------------------------------
# KhronosGroup glTF Sample Renderer (formerly glTF-Sample-Viewer): lut_ggx and lut_charlie, rendered
# once at start-up by the LUT branch of ibl_filtering.frag into 1024 x 1024 textures.
# ---------------------------------------------------------------------------------------------
GLTF_RES = 1024
GLTF_SAMPLES = 512                                                  # sampleLut(): u_sampleCount = 512
GLTF_STRIDE = 16                                                     # default: 64 x 64 of the 1024 x 1024 texels
GLTF_PI = F(3.1415926535897932384626433832795)                      # MATH_PI as a highp literal
GLTF_SRC = [
    "KhronosGroup/glTF-Sample-Renderer source/shaders/ibl_filtering.frag @d3d2f605306756e76396073d3aef81b71012c16d",
    "  (LUT(), getImportanceSample(), hammersley2d(), GGX(), Charlie(), D_Charlie(), V_SmithGGXCorrelated(), V_Ashikhmin();",
    "  the LUT code is the same in KhronosGroup/glTF-Sample-Viewer @b3a7e6680032ab858036e98792c90f9664963053),",
    "  source/ibl_sampler.js @d0a1feac0c3cf41af6b05757f11f358bb5b3ebeb (lutResolution 1024, sampleLut(): u_sampleCount 512,",
    "  u_isGeneratingLUT 1, viewport 1024 x 1024, one full-screen triangle; createLutTexture(): internalFormat() = RGBA16F / HALF_FLOAT",
    "  when EXT_color_buffer_float or EXT_color_buffer_half_float is present (preferredFormat), RGBA32F if the panorama exceeds 65504",
    "  and float is renderable, RGBA8 without float render targets), LINEAR filter, CLAMP_TO_EDGE;",
    "  read: source/Renderer/shaders/ibl.glsl @79f90e28d7951352833398695eb16de606a4fa63 (texture(u_GGXLUT, clamp(vec2(NdotV, roughness))).rg,",
    "  texture(u_CharlieLUT, clamp(vec2(NdotV, sheenRoughness))).b) with pbr.frag @9dfbb82b9068b68a925084e67a00eb77bb2192cc passing",
    "  materialInfo.perceptualRoughness and materialInfo.sheenRoughnessFactor (both the perceptual value, unsquared)",
]
GLTF_LAYOUT = [
    "layout: texel (i, j) = column i, framebuffer / texture row j counted from row 0 (GL: bottom = t near 0); the pass integrates at",
    "  texCoord = ((i + 0.5) / 1024, (j + 0.5) / 1024) = (NdotV, roughness) (fragment centres; fullscreen.vert is not in the index:",
    "  assumed the usual attribute-less triangle with texCoord = clip xy * 0.5 + 0.5), and the renderer reads at vec2(NdotV, roughness),",
    "  so texel centres are read at the values they were integrated at; every texel with i % S == o and j % S == o (S = stride, o = (S - 1) // 2) is listed",
    "storage: the RGBA16F path (the preferred one): each channel rounded to half (round to nearest even, as numpy; GL lets a",
    "  float-to-half conversion for a render target round either way); *_f32 columns are the shader's float32 outputs (the RGBA32F path)",
]


def gltf_hammersley(i, n):
    """hammersley2d(i, N) = (float(i) / float(N), float(bitreverse32(i)) * 2^-32), in float32."""
    return F(i) / F(n), F(float(reverse_bits32(i))) * F(2.3283064365386963e-10)


def gltf_texels(stride):
    off = (stride - 1) // 2
    idx = np.arange(off, GLTF_RES, stride)
    return idx, (f32(idx) + F(0.5)) / F(GLTF_RES)                 # (i + 0.5) / 1024, exact in float32


def gltf_lut(kind, nv, rough, nsamp=GLTF_SAMPLES):
    """LUT(NdotV, roughness) of ibl_filtering.frag for u_distribution = cGGX (kind 'ggx') or cCharlie ('charlie'),
    on the grid rough (rows) x nv (columns); returns the float32 (R, G, B) it writes."""
    two_pi = F(2.0) * GLTF_PI
    r = rough[:, None] * np.ones((1, nv.size), F)                   # u_roughness is unused: LUT() gets texCoord.y
    ndv = np.ones((rough.size, 1), F) * nv[None, :]
    vx = np.sqrt(F(1.0) - ndv * ndv)                                # V = (sqrt(1 - NdotV^2), 0, NdotV), N = +z
    vz = ndv
    alpha = r * r                                                   # both samplers square the roughness they get
    acc_a = np.zeros_like(r)
    acc_b = np.zeros_like(r)
    acc_c = np.zeros_like(r)
    if kind == "ggx":
        a2 = np.power(r, F(4.0))                                    # V_SmithGGXCorrelated: pow(roughness, 4.0)
    else:
        sr = np.maximum(r, F(0.000001))                             # D_Charlie(roughness, .) uses it as alpha as is
        inv_r = F(1.0) / sr
        expo = alpha / (F(2.0) * alpha + F(1.0))                    # Charlie(): sinTheta = xi.y^(alpha / (2 alpha + 1))
    for s in range(nsamp):
        xi_x, xi_y = gltf_hammersley(s, nsamp)
        sphi, cphi = sin_cos_f32(two_pi * xi_x)                     # phi = 2 pi xi.x for every distribution
        if kind == "ggx":
            cos_t = np.clip(np.sqrt((F(1.0) - xi_y) / (F(1.0) + (alpha * alpha - F(1.0)) * xi_y)), F(0), F(1))
            sin_t = np.sqrt(F(1.0) - cos_t * cos_t)
        else:
            sin_t = np.power(xi_y, expo)                            # pow(0, e > 0) = 0 at sample 0
            cos_t = np.sqrt(F(1.0) - sin_t * sin_t)
        # local direction, normalised; generateTBN(+z) = (tangent (1,0,0), bitangent (0,1,0), N): the identity
        hx, hy, hz = normalize3(sin_t * cphi, sin_t * sphi, cos_t)
        vdh_raw = vx * hx + vz * hz
        s2 = F(2.0) * vdh_raw                                       # reflect(-V, H) = 2 (V.H) H - V, then normalised
        lx, ly, lz = normalize3(s2 * hx - vx, s2 * hy, s2 * hz - vz)
        ndl = np.clip(lz, F(0), F(1))
        ndh = np.clip(hz, F(0), F(1))
        vdh = np.clip(vdh_raw, F(0), F(1))
        ok = ndl > F(0.0)
        if kind == "ggx":
            ggx_v = ndl * np.sqrt(ndv * ndv * (F(1.0) - a2) + a2)
            ggx_l = ndv * np.sqrt(ndl * ndl * (F(1.0) - a2) + a2)
            with np.errstate(divide="ignore", invalid="ignore"):
                vis = F(0.5) / (ggx_v + ggx_l)
                v_pdf = vis * vdh * ndl / ndh
            fc = np.power(F(1.0) - vdh, F(5.0))
            acc_a = np.where(ok, acc_a + (F(1.0) - fc) * v_pdf, acc_a)
            acc_b = np.where(ok, acc_b + fc * v_pdf, acc_b)
        else:
            sin2h = F(1.0) - ndh * ndh
            d_c = (F(2.0) + inv_r) * np.power(sin2h, inv_r * F(0.5)) / two_pi
            with np.errstate(divide="ignore", invalid="ignore"):
                v_a = np.clip(F(1.0) / (F(4.0) * ((ndl + ndv) - ndl * ndv)), F(0), F(1))
            acc_c = np.where(ok, acc_c + v_a * d_c * ndl * vdh, acc_c)
    n = F(nsamp)
    return (F(4.0) * acc_a) / n, (F(4.0) * acc_b) / n, ((F(4.0) * two_pi) * acc_c) / n


def gltf_half(v):
    h = np.asarray(v, np.float32).astype(np.float16)
    return h, h.view(np.uint16)


def gltf_ggx_table(stride=None):
    stride = stride or GLTF_STRIDE
    idx, tc = gltf_texels(stride)
    R, G, B = gltf_lut("ggx", tc, tc)
    hR, xR = gltf_half(R)
    hG, xG = gltf_half(G)
    header = [
        "glTF Sample Renderer lut_ggx (u_GGXLUT), rendered once at run time by ibl_filtering.frag's LUT branch (u_distribution = cGGX)",
        "source: " + GLTF_SRC[0]] + GLTF_SRC[1:] + GLTF_LAYOUT + [
        "generator: NdotV = texCoord.x, roughness = texCoord.y (perceptual), alpha = roughness^2; V = (sqrt(1 - NdotV^2), 0, NdotV)",
        "samples: 512 per texel, Hammersley (xi.x = i / 512 -> phi = 2 pi xi.x, xi.y = radical inverse -> cos theta), GGX half vectors",
        "  with alpha^2, L = normalize(reflect(-V, H)); weight V_SmithGGXCorrelated(NdotV, NdotL) (height-correlated, exact, a2 = roughness^4)",
        "  * VdotH * NdotL / NdotH, kept where saturate(L.z) > 0",
        "channels: R = A = 4 sum (1 - Fc) w / 512 (scale), G = B = 4 sum Fc w / 512 (bias), Fc = (1 - VdotH)^5; B channel = 0, alpha = 1;",
        "  the renderer uses k_S * R + G (k_S = F0 + Fr (1 - NdotV)^5, Fdez-Aguera's roughness-dependent Fresnel) and Ems = 1 - (R + G)",
        "  columns R_A, G_B = the half values; stride %d (%d x %d of 1024 x 1024 texels)" % (stride, idx.size, idx.size),
    ]
    cols = ["i", "j", "NdotV", "roughness", "R_A", "G_B", "R_A_f32", "G_B_f32", "R_half_hex", "G_half_hex"]
    rows = []
    for b, j in enumerate(idx):
        for a, i in enumerate(idx):
            rows.append([i, j, "%.9g" % tc[a], "%.9g" % tc[b], repr(float(hR[b, a])), repr(float(hG[b, a])),
                         "%.9g" % R[b, a], "%.9g" % G[b, a], "0x%04x" % xR[b, a], "0x%04x" % xG[b, a]])
    checks = sanity_split_sum("gltf_ggx", hR, hG, tc, tc, "R", "G")
    return header, cols, rows, checks


def gltf_charlie_table(stride=None):
    stride = stride or GLTF_STRIDE
    idx, tc = gltf_texels(stride)
    _, _, C = gltf_lut("charlie", tc, tc)
    hC, xC = gltf_half(C)
    header = [
        "glTF Sample Renderer lut_charlie (u_CharlieLUT), rendered once at run time by ibl_filtering.frag's LUT branch (u_distribution = cCharlie)",
        "source: " + GLTF_SRC[0]] + GLTF_SRC[1:] + GLTF_LAYOUT + [
        "generator: NdotV = texCoord.x, roughness = texCoord.y = sheenRoughness (perceptual); V = (sqrt(1 - NdotV^2), 0, NdotV)",
        "samples: 512 per texel, Hammersley; half vectors from Charlie(): sinTheta = xi.y^(a / (2a + 1)) with a = roughness^2 (density",
        "  D_Charlie(a = roughness^2) cos theta_h), phi = 2 pi xi.x; L = normalize(reflect(-V, H)), kept where saturate(L.z) > 0",
        "  weight: D_Charlie(roughness, NdotH), i.e. the Charlie NDF with alpha = roughness (not squared), * V_Ashikhmin(NdotL, NdotV)",
        "  = clamp(1 / (4 (NdotL + NdotV - NdotL NdotV)), 0, 1) * NdotL * VdotH; result 4 * 2 pi * sum / 512: the estimator of a",
        "  uniformly sampled half vector (pdf 1 / 2 pi), so with the Charlie-distributed half vectors it is not an unbiased sheen albedo",
        "channels: R = G = 0, B = that sum = the sheen directional albedo as the renderer computes it (column B_sheen_E); the renderer",
        "  multiplies the prefiltered sheen radiance and sheenColor by it; the albedo scaling uses a separate baked texture (lut_sheen_E.png)",
        "  stride %d (%d x %d of 1024 x 1024 texels)" % (stride, idx.size, idx.size),
    ]
    cols = ["i", "j", "NdotV", "roughness", "B_sheen_E", "B_sheen_E_f32", "B_half_hex"]
    rows = []
    for b, j in enumerate(idx):
        for a, i in enumerate(idx):
            rows.append([i, j, "%.9g" % tc[a], "%.9g" % tc[b], repr(float(hC[b, a])), "%.9g" % C[b, a], "0x%04x" % xC[b, a]])
    e = hC.astype(np.float64)
    checks = ["gltf_charlie: B range %.4f .. %.4f; smoothest row (roughness %.5f): NdotV %.5f -> %.4f, NdotV %.5f -> %.4f;"
              " roughest row (%.5f): %.4f .. %.4f" % (e.min(), e.max(), tc[0], tc[0], e[0, 0], tc[-1], e[0, -1],
                                                     tc[-1], e[-1].min(), e[-1].max())]
    checks.append(smoothness("gltf_charlie", "B", e))
    return header, cols, rows, checks


# ---------------------------------------------------------------------------------------------
# sanity figures
# ---------------------------------------------------------------------------------------------
def smoothness(name, label, t):
    t = np.asarray(t, np.float64)
    d2x = np.abs(t[:, 2:] - 2 * t[:, 1:-1] + t[:, :-2])
    d2y = np.abs(t[2:, :] - 2 * t[1:-1, :] + t[:-2, :])
    kx = np.unravel_index(np.argmax(d2x), d2x.shape)
    ky = np.unravel_index(np.argmax(d2y), d2y.shape)
    return ("%s: %s max |2nd difference| along NdotV %.2e (row %d, col %d), along roughness %.2e (row %d, col %d);"
            " 99th percentile %.2e / %.2e"
            % (name, label, d2x.max(), kx[0], kx[1] + 1, d2y.max(), ky[0] + 1, ky[1],
               np.percentile(d2x, 99), np.percentile(d2y, 99)))


def sanity_split_sum(name, A, B, nv, rough, la, lb):
    """A = scale, B = bias, rows sorted by increasing roughness, columns by increasing NdotV."""
    A = np.asarray(A, np.float64)
    B = np.asarray(B, np.float64)
    s = A + B
    out = []
    out.append("%s: smoothest row (roughness %.5f), highest NdotV (%.5f): scale %s = %.6f, bias %s = %.6f"
               % (name, rough[0], nv[-1], la, A[0, -1], lb, B[0, -1]))
    out.append("%s: scale + bias max %.6f (row %d, col %d), min %.6f; bias > scale + bias anywhere: %s; negative anywhere: %s"
               % (name, s.max(), *np.unravel_index(np.argmax(s), s.shape), s.min(),
                  bool((B > s + 1e-12).any()), bool((A < 0).any() or (B < 0).any())))
    out.append(smoothness(name, "scale", A))
    out.append(smoothness(name, "bias", B))
    return out


# ---------------------------------------------------------------------------------------------
# ---------------------------------------------------------------------------------------------
# OSPRay: MicrofacetAlbedoTables.ispc, built at start-up on the CPU in float (ISPC): 32 x 32
# stratified samples of the GGX visible normals per texel (Heitz 2017, sampleVisible), weight
# G2 / G1 (height-correlated), min(mean, 1); averages a 1025-point trapezoid over the linearly
# interpolated directional table, min(., 1).
# ---------------------------------------------------------------------------------------------
OSPRAY_SRC = ("RenderKit/ospray modules/cpu/render/bsdfs/MicrofacetAlbedoTables.ispc (@01beea16), "
              "MicrofacetAlbedo.ih, GGXDistribution.ih (sampleVisible, evalG1, evalG2), Fresnel.ih, "
              "Optics.ih, MicrofacetDistribution.ih (roughnessToAlpha: max(r^2, 0.001)) (@078c589a)")


def ospray_lambda(alpha, x, y, z):
    """GGXDistribution.ih evalLambda (isotropic alpha), float32."""
    inv_a2 = (np.square(x * alpha) + np.square(y * alpha)) / np.square(z)
    return f32(0.5) * (f32(-1.0) + np.sqrt(f32(1.0) + inv_a2))


def ospray_samples(cos_o, alpha):
    """For each view cosine (array), the 32 x 32 stratified visible normals: wo, wh (float32)."""
    n = 32
    u = np.minimum((np.arange(n, dtype=np.float32) + f32(0.5)) / f32(n), f32(1.0 - 1e-6))
    sx, sy = np.meshgrid(u, u, indexing="ij")                # s = ((i + 0.5) / n, (j + 0.5) / n)
    sx, sy = sx.ravel()[None, :], sy.ravel()[None, :]
    cos_o = np.maximum(np.asarray(cos_o, np.float32), f32(1e-6))[:, None]
    wo = (np.sqrt(np.maximum(f32(0.0), f32(1.0) - cos_o * cos_o)), np.zeros_like(cos_o), cos_o)
    vx, vy, vz = normalize3(alpha * wo[0], alpha * wo[1], wo[2])
    # T1 = normalize(cross(V, z)) = normalize(V.y, -V.x, 0) unless V is (nearly) the normal
    tl = np.sqrt(vy * vy + vx * vx)
    pole = vz >= f32(0.9999)
    t1x = np.where(pole, f32(1.0), vy / np.where(pole, f32(1.0), tl))
    t1y = np.where(pole, f32(0.0), -vx / np.where(pole, f32(1.0), tl))
    t1z = np.zeros_like(vz)
    t2x, t2y, t2z = t1y * vz - t1z * vy, t1z * vx - t1x * vz, t1x * vy - t1y * vx
    a = f32(1.0) / (f32(1.0) + vz)
    r = np.sqrt(sx)
    pi = f32(math.pi)
    lower = sy < a
    phi = np.where(lower, sy / a * pi, pi + (sy - a) / (f32(1.0) - a) * pi)
    p1 = r * np.cos(phi)
    p2 = r * np.sin(phi) * np.where(lower, f32(1.0), vz)
    p3 = np.sqrt(np.maximum(f32(0.0), f32(1.0) - p1 * p1 - p2 * p2))
    hx, hy, hz = p1 * t1x + p2 * t2x + p3 * vx, p1 * t1y + p2 * t2y + p3 * vy, p1 * t1z + p2 * t2z + p3 * vz
    wh = normalize3(alpha * hx, alpha * hy, np.maximum(f32(0.0), hz))
    return wo, wh


def ospray_albedo(cos_o, roughness, eta=None, lobes="reflection"):
    """MicrofacetAlbedo_integrate (eta None), MicrofacetDielectricAlbedo_integrate (lobes 'both')
    or MicrofacetDielectricReflectionAlbedo_integrate (lobes 'reflection' with eta)."""
    alpha = np.maximum(np.square(f32(roughness)), f32(0.001))
    wo, wh = ospray_samples(cos_o, alpha)
    c_oh = wo[0] * wh[0] + wo[1] * wh[1] + wo[2] * wh[2]
    lam_o = ospray_lambda(alpha, *wo)
    g1 = np.where(wo[2] * c_oh > 0, f32(1.0) / (f32(1.0) + lam_o), f32(0.0))
    rcp_g1 = np.where(g1 > 0, f32(1.0) / np.where(g1 > 0, g1, f32(1.0)), f32(0.0))   # rcp_safe

    def g2(wi, c_ih):
        ok = (wo[2] * c_oh > 0) & (wi[2] * c_ih > 0)
        return np.where(ok, f32(1.0) / (f32(1.0) + lam_o + ospray_lambda(alpha, *wi)), f32(0.0))

    wr = tuple(f32(2.0) * c_oh * h - o for h, o in zip(wh, wo))          # reflect(wo, wh)
    reflection = np.where(wr[2] > 0, g2(wr, c_oh) * rcp_g1, f32(0.0))
    if eta is None:
        weight = reflection
    else:
        eta = f32(eta)
        sqr_cos_t = f32(1.0) - eta * eta * (f32(1.0) - c_oh * c_oh)
        tir = sqr_cos_t < 0
        cos_t = np.where(tir, f32(0.0), np.sqrt(np.maximum(sqr_cos_t, f32(0.0))))
        rper = (eta * c_oh - cos_t) / (eta * c_oh + cos_t)
        rpar = (c_oh - eta * cos_t) / (c_oh + eta * cos_t)
        fresnel = np.where(tir, f32(1.0), f32(0.5) * (rpar * rpar + rper * rper))
        weight = fresnel * reflection
        if lobes == "both":
            wt = tuple(eta * (c_oh * h - o) - cos_t * h for h, o in zip(wh, wo))  # refract
            c_ih = wt[0] * wh[0] + wt[1] * wh[1] + wt[2] * wh[2]
            weight = weight + np.where(wt[2] < 0, (f32(1.0) - fresnel) * g2(wt, c_ih) * rcp_g1, f32(0.0))
    return np.minimum(weight.astype(np.float32).sum(axis=1, dtype=np.float32) / f32(1024), f32(1.0))


def ospray_average(directional):
    """MicrofacetAlbedoTable_integrateAvg: trapezoid over 1025 cosines of the interpolated table."""
    size = len(directional)
    cos_o = np.arange(1025, dtype=np.float32) / f32(1024)
    x = cos_o * f32(size - 1)
    i = np.minimum(np.floor(x).astype(int), size - 2)
    value = directional[i] * (f32(1.0) - (x - i)) + directional[i + 1] * (x - i)
    weight = np.where((np.arange(1025) == 0) | (np.arange(1025) == 1024), f32(0.5), f32(1.0))
    return min(2.0 * float(np.sum(value * cos_o * weight, dtype=np.float32)) / 1024, 1.0)


def ospray_ggx_table():
    cos_o = np.arange(32, dtype=np.float32) / f32(31)
    header = [OSPRAY_SRC, "MicrofacetAlbedoTable_dir[j * 32 + i]: i = cosThetaO = i / 31, j = roughness = j / 31; "
              "avg: the trapezoid average of row j"]
    rows, e = [], np.zeros((32, 32))
    for j in range(32):
        e[j] = ospray_albedo(cos_o, np.float32(j) / f32(31))
        avg = ospray_average(e[j].astype(np.float32))
        for i in range(32):
            rows.append([i, j, "%.9g" % e[j, i], "%.9g" % avg])
    checks = ["E at the smoothest row: %.6f .. %.6f (1 but for the clamp alpha >= 0.001)" % (e[0].min(), e[0].max())]
    return header, ["i", "j", "E", "Eavg"], rows, checks


def ospray_dielectric_table(kind):
    """kind 'glass' (eta in [1/3, 1], both lobes) or 'reflection' (the reflection alone)."""
    cos_o = np.arange(16, dtype=np.float32) / f32(15)
    lo, hi = f32(1.0) / f32(3.0), f32(1.0)
    header = [OSPRAY_SRC, "Microfacet%sAlbedoTable_dir[(k * 16 + j) * 16 + i]: i = cosThetaO = i / 15, "
              "j: eta = lerp(j / 15, 1/3, 1), k = roughness = k / 15; avg: trapezoid average of each (j, k)"
              % ("Dielectric" if kind == "glass" else "DielectricReflection")]
    rows = []
    for k in range(16):
        for j in range(16):
            t = f32(j) / f32(15)
            eta = (f32(1.0) - t) * lo + t * hi
            e = ospray_albedo(cos_o, np.float32(k) / f32(15), eta, "both" if kind == "glass" else "reflection")
            avg = ospray_average(e.astype(np.float32))
            for i in range(16):
                rows.append([i, j, k, "%.9g" % e[i], "%.9g" % avg])
    return header, ["i", "j", "k", "E", "Eavg"], rows, []


def ospray_sheen_lambda(r, cos_theta, soften=False):
    """SheenDistribution.ih evalLambda (evalLambdaI with soften), float32: the glTF fit of
    Charlie's Lambda; the light's raised to 1 + 2 (1 - cos)^8."""
    w0 = np.square(f32(1.0) - r)
    w1 = f32(1.0) - w0
    a, b = w0 * f32(25.3245) + w1 * f32(21.5473), w0 * f32(3.32435) + w1 * f32(3.82987)
    c, d = w0 * f32(0.16801) + w1 * f32(0.19823), w0 * f32(-1.27393) + w1 * f32(-1.97760)
    e = w0 * f32(-4.85967) + w1 * f32(-4.32054)

    def big_l(x):
        return a / (f32(1.0) + b * np.power(f32(x), c)) + d * x + e
    cos_theta = f32(cos_theta)
    lam = np.where(cos_theta < f32(0.5), np.exp(big_l(cos_theta)),
                   np.exp(f32(2.0) * big_l(f32(0.5)) - big_l(f32(1.0) - cos_theta))).astype(np.float32)
    if soften:
        lam = np.power(lam, f32(1.0) + f32(2.0) * np.square(np.square(np.square(f32(1.0) - cos_theta))))
    return lam.astype(np.float32)


def ospray_sheen_albedo(cos_o, roughness):
    """MicrofacetSheenAlbedo_integrate: 32 x 32 stratified uniform-hemisphere light samples,
    D G / (4 cosThetaO pdf), r = roughnessToAlpha(roughness), min(mean, 1); float32."""
    n = 32
    r = np.maximum(np.square(f32(roughness)), f32(0.001))
    u = np.minimum((np.arange(n, dtype=np.float32) + f32(0.5)) / f32(n), f32(1.0 - 1e-6))
    sx, sy = np.meshgrid(u, u, indexing="ij")                # s = ((i + 0.5) / n, (j + 0.5) / n)
    sx, sy = sx.ravel()[None, :], sy.ravel()[None, :]
    cos_o = np.maximum(np.asarray(cos_o, np.float32), f32(1e-6))[:, None]
    wo = (np.sqrt(np.maximum(f32(0.0), f32(1.0) - cos_o * cos_o)), np.zeros_like(cos_o), cos_o)
    phi = f32(2.0 * math.pi) * sx                            # uniformSampleHemisphere
    sin_i = np.sqrt(np.maximum(f32(0.0), f32(1.0) - sy * sy))
    wi = (np.cos(phi) * sin_i, np.sin(phi) * sin_i, sy)
    wh = normalize3(wo[0] + wi[0], wo[1] + wi[1], wo[2] + wi[2])
    cos_h = wh[2]
    c_oh = wo[0] * wh[0] + wo[1] * wh[1] + wo[2] * wh[2]
    c_ih = wi[0] * wh[0] + wi[1] * wh[1] + wi[2] * wh[2]
    inv_r = f32(1.0) / r
    sin_h = np.sqrt(np.maximum(f32(0.0), f32(1.0) - cos_h * cos_h))
    dist = (f32(2.0) + inv_r) * np.power(sin_h, inv_r) * f32(1.0 / (2.0 * math.pi))
    ok = (cos_o * c_oh > 0) & (wi[2] * c_ih > 0)
    g = np.where(ok, f32(1.0) / (f32(1.0) + ospray_sheen_lambda(r, cos_o)
                                 + ospray_sheen_lambda(r, wi[2], soften=True)), f32(0.0))
    pdf = f32(1.0 / (2.0 * math.pi))
    sample = dist * g * (f32(1.0) / (f32(4.0) * cos_o * pdf))
    return np.minimum(sample.astype(np.float32).sum(axis=1, dtype=np.float32) / f32(1024), f32(1.0))


def ospray_sheen_table():
    cos_o = np.arange(16, dtype=np.float32) / f32(15)
    header = [OSPRAY_SRC + "; MicrofacetAlbedo.ih MicrofacetSheenAlbedo_integrate, SheenDistribution.ih "
              "(eval, evalLambda, evalLambdaI, evalG2), math/sampling.ih uniformSampleHemisphere",
              "MicrofacetSheenAlbedoTable_dir[j * 16 + i]: i = cosThetaO = i / 15, j = roughness = j / 15"]
    rows = []
    for j in range(16):
        e = ospray_sheen_albedo(cos_o, np.float32(j) / f32(15))
        for i in range(16):
            rows.append([i, j, "%.9g" % e[i]])
    return header, ["i", "j", "E"], rows, []


# ---------------------------------------------------------------------------------------------
# MaterialX: mx_generate_dir_albedo_table (GPU, float), 64 spherical Fibonacci samples per
# texel: GGX A, B by visible-normal sampling (a spherical cap, Dupuy and Benyoub 2023), weights
# G2 (height-correlated) / G1; the Imageworks sheen by uniform hemisphere samples. 128 x 128 float.
# ---------------------------------------------------------------------------------------------
MATERIALX_SRC = ("AcademySoftwareFoundation/MaterialX@4177b2cb libraries/pbrlib/genglsl/lib/"
                 "mx_generate_albedo_table.glsl, mx_microfacet.glsl (mx_spherical_fibonacci), "
                 "mx_microfacet_specular.glsl (mx_ggx_dir_albedo_monte_carlo, mx_ggx_importance_sample_VNDF, "
                 "mx_ggx_smith_G1/G2), mx_microfacet_sheen.glsl (mx_imageworks_sheen_dir_albedo_monte_carlo); "
                 "source/MaterialXView/Viewer.cpp ALBEDO_TABLE_SIZE 128")


def materialx_table(size=128):
    eps = f32(1e-8)
    count = 64
    k = np.arange(count, dtype=np.float32)
    xi_x = (k + f32(0.5)) / f32(count)
    xi_y = np.mod((k + f32(1.0)) * f32(1.6180339887498948), f32(1.0))
    u = (np.arange(size, dtype=np.float32) + f32(0.5)) / f32(size)
    nv = np.clip(u, eps, f32(1.0))[None, :, None]                 # [1, x, sample]
    alpha = u[:, None, None]                                       # [y, 1, 1]
    vx, vz = np.sqrt(f32(1.0) - nv * nv), nv
    # mx_ggx_importance_sample_VNDF: a spherical cap about the stretched view.
    sx, sy, sz = normalize3(vx * alpha, np.zeros_like(vx * alpha), vz + f32(0.0) * alpha)
    phi = f32(2.0 * math.pi) * xi_x
    z = (f32(1.0) - xi_y) * (f32(1.0) + sz) - sz
    sin_t = np.sqrt(np.clip(f32(1.0) - z * z, f32(0.0), f32(1.0)))
    hx, hy, hz = normalize3((sin_t * np.cos(phi) + sx) * alpha, (sin_t * np.sin(phi) + sy) * alpha,
                            np.maximum(z + sz, f32(0.0)))
    vh_raw = vx * hx + vz * hz
    lz = f32(2.0) * vh_raw * hz - vz                               # L = -reflect(V, H)
    nl = np.clip(lz, eps, f32(1.0))
    vh = np.clip(vh_raw, eps, f32(1.0))
    fc = np.clip(f32(1.0) - vh, f32(0.0), f32(1.0)) ** 5
    a2 = alpha * alpha
    lam_l = np.sqrt(a2 + (f32(1.0) - a2) * nl * nl)
    lam_v = np.sqrt(a2 + (f32(1.0) - a2) * nv * nv)
    g2 = f32(2.0) * nl * nv / (lam_l * nv + lam_v * nl)
    tan2 = (f32(1.0) - nv * nv) / (nv * nv)
    g1 = f32(2.0) / (f32(1.0) + np.sqrt(f32(1.0) + a2 * tan2))
    a_sum = (g2 * (f32(1.0) - fc)).sum(axis=2, dtype=np.float32)
    b_sum = (g2 * fc).sum(axis=2, dtype=np.float32)
    scale = g1[..., 0] * f32(count)
    table_a, table_b = a_sum / scale, b_sum / scale
    # Imageworks sheen: uniform hemisphere, Charlie D with r = max(roughness, 0.005), Ashikhmin V.
    cos_l = f32(1.0) - xi_y
    sin_l = np.sqrt(f32(1.0) - cos_l * cos_l)
    lx, ly = np.cos(phi) * sin_l, np.sin(phi) * sin_l
    hx, hy, hz = normalize3(lx + vx, ly + f32(0.0) * vx, cos_l + vz)
    nl = np.clip(cos_l + f32(0.0) * vz, eps, f32(1.0))
    nh = np.clip(hz, eps, f32(1.0))
    inv_r = f32(1.0) / np.maximum(alpha, f32(0.005))
    d = (f32(2.0) + inv_r) * np.power(f32(1.0) - nh * nh, inv_r * f32(0.5)) / f32(2.0 * math.pi)
    brdf = d / (f32(4.0) * (nl + nv - nl * nv))
    sheen = (brdf * nl / f32(0.5 / math.pi)).sum(axis=2, dtype=np.float32) / f32(count)
    header = [MATERIALX_SRC, "texel (i, j): NdotV = (i + 0.5) / 128, alpha (and the sheen's roughness) = (j + 0.5) / 128; "
              "R = A, G = B, B = Imageworks sheen albedo, float"]
    rows = []
    for j in range(size):
        for i in range(size):
            rows.append([i, j, "%.9g" % table_a[j, i], "%.9g" % table_b[j, i], "%.9g" % sheen[j, i]])
    checks = ["A + B at alpha ~ 0, NdotV ~ 1: %.6f" % (table_a[0, -1] + table_b[0, -1])]
    return header, ["i", "j", "A", "B", "sheen"], rows, checks


ENGINES = {
    "unreal": ("unreal_preintegrated_gf.csv", unreal_table),
    "godot": ("godot_dfg.csv", lambda: godot_table("master")),
    "godot_e8387d": ("godot_dfg_e8387d.csv", lambda: godot_table("e8387d")),
    "hdrp_ggx": ("hdrp_fgd_ggx_disney.csv", hdrp_ggx_table),
    "hdrp_charlie": ("hdrp_fgd_charlie.csv", hdrp_charlie_table),
    "gltf_ggx": ("gltf_lut_ggx.csv", lambda: gltf_ggx_table(GLTF_STRIDE)),
    "gltf_charlie": ("gltf_lut_charlie.csv", lambda: gltf_charlie_table(GLTF_STRIDE)),
    "ospray_ggx": ("ospray_ggx.csv", ospray_ggx_table),
    "materialx": ("materialx_albedo_table.csv", materialx_table),
    "ospray_glass": ("ospray_dielectric.csv", lambda: ospray_dielectric_table("glass")),
    "ospray_reflection": ("ospray_dielectric_reflection.csv", lambda: ospray_dielectric_table("reflection")),
    "ospray_sheen": ("ospray_sheen.csv", ospray_sheen_table),
}
DEFAULT = ["unreal", "godot", "hdrp_ggx", "hdrp_charlie", "gltf_ggx", "gltf_charlie"]


def write_csv(path, header, cols, rows):
    with open(path, "w") as f:
        for h in header:
            f.write("# " + h + "\n")
        f.write(",".join(cols) + "\n")
        for r in rows:
            f.write(",".join(str(x) for x in r) + "\n")


def main(argv):
    global GLTF_STRIDE
    argv = list(argv)
    for k in range(len(argv) - 1, 0, -1):                          # --stride N / --stride=N (glTF tables only)
        a = argv[k]
        if a == "--stride" or a.startswith("--stride="):
            val = a.split("=", 1)[1] if "=" in a else (argv[k + 1] if k + 1 < len(argv) else "")
            if not val.isdigit() or not 1 <= int(val) <= GLTF_RES:
                print("--stride needs an integer from 1 to %d" % GLTF_RES, file=sys.stderr)
                return 2
            GLTF_STRIDE = int(val)
            del argv[k:k + (1 if "=" in a else 2)]
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) >= 2 else 2
    out_dir = argv[1]
    names = argv[2:] or DEFAULT
    expanded = []
    for n in names:
        if n == "hdrp":
            expanded += ["hdrp_ggx", "hdrp_charlie"]
        elif n == "gltf":
            expanded += ["gltf_ggx", "gltf_charlie"]
        elif n == "all":
            expanded += list(ENGINES)
        elif n in ENGINES:
            expanded.append(n)
        else:
            print("unknown engine %r; known: %s, hdrp, gltf, all" % (n, ", ".join(ENGINES)), file=sys.stderr)
            return 2
    os.makedirs(out_dir, exist_ok=True)
    for n in expanded:
        fname, fn = ENGINES[n]
        t0 = time.time()
        header, cols, rows, checks = fn()
        path = os.path.join(out_dir, fname)
        write_csv(path, header, cols, rows)
        print("%s: wrote %s (%d texels) in %.1f s" % (n, path, len(rows), time.time() - t0))
        for c in checks:
            print("  " + c)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
