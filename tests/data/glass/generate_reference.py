#!/usr/bin/python3
"""Reference values of the rough-dielectric albedos glass_E and spec_E (and a few averages).

Definitions (README.md beside this file): frame n = +z, o the direction energy arrives from,
mu = o.z in (0, 1], eta = (IOR on the far side) / (IOR on the side of o), alpha = r^2.

    glass_E = int D(h) (o.h)^+ / mu [ F G(o, i_r) 1{i_r.z > 0} + (1 - F) G(o, i_t) 1{i_t.z < 0} ] dw_h
    spec_E  = the same with the reflection term only,

F the exact unpolarised dielectric Fresnel at c = o.h (F = 1 under total internal reflection),
i_r = 2 c h - o, i_t = (c/eta - c_t) h - o/eta with c_t = sqrt(1 - (1 - c^2)/eta^2), and
G = 1/(1 + Lambda(mu) + Lambda(|i.z|)) (correlated) or 1/((1 + Lambda(mu))(1 + Lambda(|i.z|)))
(separable). Changing variables from h to i turns the transmission term into Walter et al.
2007's BTDF in the form that integrates to the transmitted fraction of the energy (eta_far^2 in
the numerator, no radiance factor); README.md has the derivation.

Method (no code shared with lutbake's C++, whose rule is written separately): the
variable is the half vector h = (theta, phi); phi is folded onto [0, pi]. For fixed theta every
factor of the integrand depends on phi only through c = A cos(phi) + B (A = sin(theta_o)
sin(theta), B = mu cos(theta)), so the places where it is not analytic are levels of c:
c = 0 (the visible-normal cut, end of the range), the reflection horizon c = mu/(2 cos theta),
the TIR edge c_T = sqrt(1 - eta^2) (square-root branch of F on its transmitting side), and the
transmission horizon c = (m^2 + k)/(2m), m = mu/cos(theta), k = 1 - eta^2. Each becomes a phi
break; each phi segment carries a Gauss-Legendre template graded by 2 toward both ends
(IN_LEVELS levels). In theta: geometric panels alpha 2^k out of the lobe centre, and breaks,
graded by 2 from both sides (OUT_LEVELS levels), at every theta where a phi break enters
the range through phi = 0 or pi: pi/2 - theta_o (the cut reaches phi = pi),
(theta_o +- pi/2)/2 (reflection horizon), theta_o +- theta_T, theta_T - theta_o (TIR edge),
the roots of the transmission horizon at phi = 0, pi (bracketed by a scan, bisection), and
where two c levels cross (reflection horizon = TIR edge at cos(theta) = mu/(2 sqrt(k)),
transmission horizon = TIR edge at cos(theta) = mu/sqrt(k)).

Each value is computed with n = 12 and n = 20 nodes per panel on the same panels; the file
holds the 20-node value and err = |V20 - V12| + 1e-15 (a two-order estimate: it cannot see a
feature the panels miss; the sanity checks below are the independent part).

Averages: Eavg = 2 int E mu dmu by Gauss-Legendre on mu panels graded by 2 toward 0
(AVG_LEVELS levels) and toward the mu where E is not analytic (mu_breaks()), at two outer
orders (8 and 12 nodes a panel), E at every node by a lighter
inner rule (12 nodes, 10 and 8 grading levels); err = outer difference + the largest
difference between the light rule and the full 20-node rule at every 24th node.

Sanity checks (--check): eta = 1 against (1 + Lambda)/(1 + 2 Lambda) (correlated) and
1/(1 + Lambda) ... (separable: (1+Lambda) G1(mu)^2 = 1/(1 + Lambda)); spec_E -> F(mu) as r -> 0
(r = 1e-3); an independent integral over the light direction i (Walter's BSDF in (mu_i,
phi_i), tensor Gauss-Legendre, coarse) at a few points; and the two-sided reciprocity
relation of the transmitted averages, T_avg(1/eta) = T_avg(eta) / eta^2.

Usage: generate_reference.py [--check] [--E-only] [--avg-only] [--quick]
Writes glass_E.csv and glass_Eavg.csv beside this file. Needs numpy only (math.erfc for
Beckmann's Lambda).
"""
import argparse
import math
import os
import sys
import time

import numpy as np

_ERFC = np.frompyfunc(math.erfc, 1, 1)


def erfc(a):
    return np.asarray(_ERFC(np.asarray(a, float)), dtype=float)


def brentq(g, a, b, xtol=0.0, rtol=0.0):
    """Bisection to full double precision (the name kept for readability)."""
    ga = g(a)
    for _ in range(200):
        m = 0.5 * (a + b)
        if m == a or m == b:
            break
        gm = g(m)
        if (gm < 0.0) == (ga < 0.0):
            a, ga = m, gm
        else:
            b = m
    return 0.5 * (a + b)

HERE = os.path.dirname(os.path.abspath(__file__))
IN_LEVELS = 16
OUT_LEVELS = 14
AVG_LEVELS = 8


def gauss(n):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (x + 1.0), 0.5 * w


RULES = {n: gauss(n) for n in (8, 12, 16, 20)}


def graded(a, b, levels):
    pts = {a, b, 0.5 * (a + b)}
    L = b - a
    for k in range(2, levels + 2):
        pts.add(a + L * 0.5 ** k)
        pts.add(b - L * 0.5 ** k)
    return sorted(pts)


def template(n, levels):
    """Nodes on [0, 1] graded toward both ends: (t, weight)."""
    x, w = RULES[n]
    b = np.array(graded(0.0, 1.0, levels))
    lo, hi = b[:-1], b[1:]
    t = (lo[:, None] + (hi - lo)[:, None] * x[None, :]).ravel()
    wt = ((hi - lo)[:, None] * w[None, :]).ravel()
    return t, wt


# ------------------------------------------------------------------------------------------
# Model

def lam(ndf, alpha, mu):
    """Smith Lambda(mu) for the NDF, mu in (0, 1] (array)."""
    mu = np.asarray(mu, float)
    s2 = np.maximum(0.0, (1.0 - mu) * (1.0 + mu))
    if ndf == "ggx":
        t2 = alpha * alpha * s2 / (mu * mu)
        return t2 / (2.0 * (np.sqrt(1.0 + t2) + 1.0))
    # Beckmann: a = mu / (alpha sin), Lambda = (erf(a) - 1)/2 + exp(-a^2)/(2 a sqrt(pi))
    with np.errstate(divide="ignore", invalid="ignore"):
        a = mu / (alpha * np.sqrt(s2))
        v = 0.5 * (np.exp(-a * a) / (a * math.sqrt(math.pi)) - erfc(a))
    return np.where(s2 > 0.0, v, 0.0)


def ndf_D(ndf, alpha, x, sx=None):
    """D(h) as a function of x = cos(theta_h) and sx = sin(theta_h) (given, so that
    1 - x^2 does not cancel near the lobe centre at tiny alpha)."""
    a2 = alpha * alpha
    if sx is None:
        sx = np.sqrt(np.maximum(0.0, (1.0 - x) * (1.0 + x)))
    x2, s2 = x * x, sx * sx
    if ndf == "ggx":
        d = s2 + a2 * x2
        return a2 / (math.pi * d * d)
    return np.exp(-s2 / (x2 * a2)) / (math.pi * a2 * x2 * x2)


def fresnel(c, eta):
    """Unpolarised dielectric Fresnel at cos c (>= 0) and cos of the refracted angle."""
    g2 = eta * eta - 1.0 + c * c
    tir = g2 <= 0.0
    ct = np.sqrt(np.maximum(g2, 0.0)) / eta
    rs = (c - eta * ct) / (c + eta * ct)
    rp = (eta * c - ct) / (eta * c + ct)
    F = 0.5 * (rs * rs + rp * rp)
    return np.where(tir, 1.0, F), ct, tir


def smith(smith_form, lam_o, lam_i):
    if smith_form == "correlated":
        return 1.0 / (1.0 + lam_o + lam_i)
    return 1.0 / ((1.0 + lam_o) * (1.0 + lam_i))


def integrand_c(ndf, smith_form, alpha, mu, eta, lam_o, x, c, extra=False):
    """Bracket [F G_r 1 + (1-F) G_t 1] and its reflection part, as functions of c, x.
    With extra: also the two peer-definition integrands (see albedo())."""
    F, ct, tir = fresnel(c, eta)
    irz = 2.0 * c * x - mu
    ok_r = irz > 0.0
    lr = lam(ndf, alpha, np.where(ok_r, irz, 0.5))
    refl = np.where(ok_r, F * smith(smith_form, lam_o, lr), 0.0)
    itz = (c / eta - ct) * x - mu / eta
    ok_t = (itz < 0.0) & ~tir
    lt = lam(ndf, alpha, np.where(~tir, np.clip(np.abs(itz), 1e-300, 1.0), 0.5))
    gt = (1.0 - F) * smith(smith_form, lam_o, lt)
    trans = np.where(ok_t, gt, 0.0)
    if not extra:
        return refl + trans, refl
    # (a) transmission whose refracted direction ends above the surface (i_t.z > 0), weighted
    # as if valid, with Lambda(|i_t.z|): what a sampler without the side test adds;
    # (b) G1(o) s(c) 1{i_r.z > 0}, s = (F - F0)/(1 - F0): Cycles' ggx_gen_schlick_ior_s.
    wrong = np.where((itz > 0.0) & ~tir, gt, 0.0)
    F0 = ((eta - 1.0) / (eta + 1.0)) ** 2
    sfac = np.clip((F - F0) / (1.0 - F0), 0.0, 1.0) if eta != 1.0 else np.zeros_like(F)
    vs = np.where(ok_r, sfac / (1.0 + lam_o), 0.0)
    return refl + trans, refl, wrong, vs


# ------------------------------------------------------------------------------------------
# Breaks

def c_features(mu, eta, x):
    """Levels of c (per x node) where the integrand is not analytic: (K, Nx) array, nan = none."""
    feats = [mu / (2.0 * x)]
    if eta < 1.0:
        k = 1.0 - eta * eta
        feats.append(np.full_like(x, math.sqrt(k)))
        m = mu / x
        ctr = (m * m + k) / (2.0 * m)
        ok = (ctr >= m) & (ctr >= math.sqrt(k))
        feats.append(np.where(ok, ctr, np.nan))
    return np.array(feats)


def theta_features(mu, eta):
    th_o = math.acos(mu)
    hp = 0.5 * math.pi
    out = [hp - th_o, 0.5 * (th_o + hp), 0.5 * (hp - th_o)]
    if eta < 1.0:
        k = 1.0 - eta * eta
        th_T = math.acos(math.sqrt(k))
        out += [th_o + th_T, th_o - th_T, th_T - th_o]
        # where the phi breaks cross each other: reflection horizon = TIR edge
        # (cos theta = mu / (2 sqrt k)) and transmission horizon = TIR edge (mu / sqrt k, where the
        # transmission horizon appears)
        for xq in (mu / (2.0 * math.sqrt(k)), mu / math.sqrt(k)):
            if xq < 1.0:
                out.append(math.acos(xq))
        # transmission horizon at phi = 0 (c = cos(theta - theta_o)) and phi = pi
        for sgn in (-1.0, 1.0):
            def g(th):
                x = math.cos(th)
                c = math.cos(th + sgn * th_o)
                g2 = eta * eta - 1.0 + c * c
                if c <= 0.0 or g2 <= 0.0:
                    return float("nan")
                ct = math.sqrt(g2) / eta
                return (c / eta - ct) * x - mu / eta
            grid = np.linspace(0.0, hp, 4001)
            vals = np.array([g(t) for t in grid])
            for j in range(grid.size - 1):
                a, b = vals[j], vals[j + 1]
                if np.isfinite(a) and np.isfinite(b) and a * b < 0.0:
                    out.append(brentq(g, grid[j], grid[j + 1], xtol=1e-15, rtol=1e-15))
    return [t for t in out if 1e-12 < t < hp - 1e-12]


def theta_breaks(alpha, mu, eta, levels):
    hp = 0.5 * math.pi
    br = {0.0, hp}
    t = alpha / 8.0
    while t < hp:
        br.add(t)
        t *= 2.0
    br = sorted(br)
    # no panel wider than 0.2
    extra = []
    for a, b in zip(br[:-1], br[1:]):
        m = int(math.ceil((b - a) / 0.2))
        extra += [a + (b - a) * k / m for k in range(1, m)]
    br = sorted(set(br) | set(extra))
    for f in theta_features(mu, eta):
        lo = max(b for b in br if b < f)
        hi = min(b for b in br if b > f)
        if f - lo < 1e-14 or hi - f < 1e-14:
            continue
        new = {f}
        for k in range(1, levels + 1):
            new.add(f - (f - lo) * 0.5 ** k)
            new.add(f + (hi - f) * 0.5 ** k)
        br = sorted(set(br) | new)
    return np.array(br)


# ------------------------------------------------------------------------------------------
# The integral at one point

def albedo(ndf, smith_form, alpha, mu, eta, n, in_levels=IN_LEVELS, out_levels=OUT_LEVELS,
           chunk=64, extra=False):
    """(glass_E, spec_E) with the n-node rule; with extra also (wrong, vndf_s): the integrals of
    the two extra integrands of integrand_c (for reading peer tables under their definitions)."""
    xg, wg = RULES[n]
    br = theta_breaks(alpha, mu, eta, out_levels)
    lo, hi = br[:-1], br[1:]
    TH = (lo[:, None] + (hi - lo)[:, None] * xg[None, :]).ravel()
    WTH = ((hi - lo)[:, None] * wg[None, :]).ravel()
    t, wt = template(n, in_levels)
    s_o = math.sqrt(max(0.0, (1.0 - mu) * (1.0 + mu)))
    lam_o = float(lam(ndf, alpha, mu))
    tot_g = tot_s = tot_w = tot_v = 0.0
    for st in range(0, TH.size, chunk):
        th = TH[st:st + chunk]
        wth = WTH[st:st + chunk]
        x = np.cos(th)
        sx = np.sin(th)
        A = s_o * sx
        B = mu * x
        with np.errstate(divide="ignore", invalid="ignore"):
            cm = np.where(A > 0.0, -B / A, -2.0)
        phimax = np.where(cm <= -1.0, math.pi, np.arccos(np.clip(cm, -1.0, 1.0)))
        # phi breaks from the c features
        feats = c_features(mu, eta, x)
        with np.errstate(divide="ignore", invalid="ignore"):
            cphi = (feats - B[None, :]) / A[None, :]
        inside = np.isfinite(cphi) & (cphi > -1.0) & (cphi < 1.0)
        phis = np.where(inside, np.arccos(np.clip(cphi, -1.0, 1.0)), np.nan)
        phis = np.where(phis < phimax[None, :], phis, np.nan)
        allb = np.vstack([np.zeros_like(x)[None, :], phis, phimax[None, :]])
        allb = np.where(np.isnan(allb), phimax[None, :], allb)   # empty segments at the end
        allb = np.sort(allb, axis=0)                                 # (K+2, Nx)
        seg_lo, seg_hi = allb[:-1], allb[1:]                         # (K+1, Nx)
        span = seg_hi - seg_lo
        phi = seg_lo[:, :, None] + span[:, :, None] * t[None, None, :]
        w = span[:, :, None] * wt[None, None, :]
        c = A[None, :, None] * np.cos(phi) + B[None, :, None]
        c = np.minimum(c, 1.0)
        good = c > 0.0
        cc = np.where(good, c, 0.5)
        Xb = np.broadcast_to(x[None, :, None], cc.shape)
        parts = integrand_c(ndf, smith_form, alpha, mu, eta, lam_o, Xb, cc, extra)
        pref = ndf_D(ndf, alpha, x, sx) * sx * wth * 2.0 / mu                 # 2: phi folded
        kern = np.where(good, cc * w, 0.0)
        sums = [float(np.sum(pref * np.sum(kern * p, axis=(0, 2)))) for p in parts]
        tot_g += sums[0]
        tot_s += sums[1]
        if extra:
            tot_w += sums[2]
            tot_v += sums[3]
    if extra:
        return tot_g, tot_s, tot_w, tot_v
    return tot_g, tot_s


def albedo_with_error(ndf, smith_form, alpha, mu, eta):
    g12, s12 = albedo(ndf, smith_form, alpha, mu, eta, 12)
    g20, s20 = albedo(ndf, smith_form, alpha, mu, eta, 20)
    return (g20, abs(g20 - g12) + 1e-15), (s20, abs(s20 - s12) + 1e-15)


def mu_breaks(eta, levels):
    """Panels for the mu integral: quarters, graded by 2 toward 0, and graded from both sides
    toward the mu where E(mu) is not analytic (eta < 1: mu = sqrt(1 - eta^2), where the TIR
    features of theta_features() reach theta = 0; mu = eta, where theta_o + theta_T = pi/2;
    mu = 2 sqrt(1 - eta^2), where the reflection-horizon/TIR crossing reaches theta = 0)."""
    br = {k / 4.0 for k in range(5)} | {0.25 * 0.5 ** k for k in range(1, levels + 1)}
    specials = []
    if eta < 1.0:
        k = 1.0 - eta * eta
        specials = [math.sqrt(k), eta, 2.0 * math.sqrt(k)]
    br = sorted(br)
    for f in specials:
        if not 0.0 < f < 1.0:
            continue
        lo = max(b for b in br if b < f)
        hi = min(b for b in br if b > f)
        new = {f}
        for j in range(1, 4):
            new.add(f - (f - lo) * 0.5 ** j)
            new.add(f + (hi - f) * 0.5 ** j)
        br = sorted(set(br) | new)
    return br


def average(ndf, smith_form, alpha, eta, n_outer=(8, 12), levels=AVG_LEVELS):
    """(glass_Eavg, err, spec_Eavg, err)."""
    br = mu_breaks(eta, levels)
    cache = {}
    worst = 0.0
    res = {}
    for no in n_outer:
        xg, wg = RULES[no] if no in RULES else gauss(no)
        sg = ss = 0.0
        for a, b in zip(br[:-1], br[1:]):
            for xi, wi in zip(xg, wg):
                mu = a + (b - a) * xi
                key = round(mu, 17)
                if key not in cache:
                    cache[key] = albedo(ndf, smith_form, alpha, mu, eta, 12, in_levels=10,
                                        out_levels=8)
                g, s = cache[key]
                sg += 2.0 * mu * g * (b - a) * wi
                ss += 2.0 * mu * s * (b - a) * wi
        res[no] = (sg, ss)
    # inner error: the full 20-node rule against the light one at every 24th node
    keys = sorted(cache)
    for key in keys[:: 24]:
        g20, s20 = albedo(ndf, smith_form, alpha, key, eta, 20)
        g12, s12 = cache[key]
        worst = max(worst, abs(g20 - g12), abs(s20 - s12))
    (g0, s0), (g1, s1) = res[n_outer[0]], res[n_outer[1]]
    return g1, abs(g1 - g0) + worst + 1e-15, s1, abs(s1 - s0) + worst + 1e-15


# ------------------------------------------------------------------------------------------
# Independent checks

def fresnel_scalar(mu, eta):
    return float(fresnel(np.array(mu), eta)[0])


def walter_over_i(ndf, smith_form, alpha, mu, eta, n=20, levels=20):
    """Independent integral over the light direction i with Walter's BSDF, (theta_i, phi_i)
    tensor Gauss-Legendre graded toward the peak directions, the horizon and, below the
    surface, toward theta_i = acos(mu/eta) (i.z = -mu/eta: where the microfacet normal of a
    transmitted i reaches the horizon; no i nearer the horizon is reached). A check only:
    converges slowly where eta < 1 (the TIR edge is a curve across the grid)."""
    o = np.array([math.sqrt(1 - mu * mu), 0.0, mu])
    lam_o = float(lam(ndf, alpha, mu))
    xg, wg = gauss(n)
    hp = 0.5 * math.pi
    tot = 0.0
    th_r = math.acos(mu)
    st = math.sqrt(max(0.0, 1 - mu * mu)) / eta
    th_t = math.asin(st) if st < 1.0 else hp
    for side in ("r", "t"):
        feats = [th_r] if side == "r" else [th_t] + ([math.acos(mu / eta)] if mu < eta else [])
        tb = {0.0, hp}
        for f in feats:
            if 0.0 < f < hp:
                tb |= set(graded(0.0, f, levels)) | set(graded(f, hp, levels))
        tb = sorted(tb)
        pb = graded(0.0, math.pi, levels)
        TH = np.concatenate([a + (b - a) * xg for a, b in zip(tb[:-1], tb[1:]) if b > a])
        WT = np.concatenate([(b - a) * wg for a, b in zip(tb[:-1], tb[1:]) if b > a])
        PH = np.concatenate([a + (b - a) * xg for a, b in zip(pb[:-1], pb[1:])])
        WP = np.concatenate([(b - a) * wg for a, b in zip(pb[:-1], pb[1:])])
        T, P = np.meshgrid(TH, PH, indexing="ij")
        W = np.outer(WT, WP) * np.sin(T) * 2.0
        mui = np.cos(T)
        ix, iy = np.sin(T) * np.cos(P), np.sin(T) * np.sin(P)
        G = smith(smith_form, lam_o, lam(ndf, alpha, mui))
        with np.errstate(divide="ignore", invalid="ignore"):
            if side == "r":
                hx, hy, hz = o[0] + ix, iy, o[2] + mui
                nrm = np.sqrt(hx * hx + hy * hy + hz * hz)
                hx, hy, hz = hx / nrm, hy / nrm, hz / nrm
                c = hx * o[0] + hz * o[2]
                F = fresnel(np.maximum(c, 0.0), eta)[0]
                val = np.where(c > 0, F * G * ndf_D(ndf, alpha, hz) / (4.0 * mu), 0.0)
            else:
                iz = -mui
                # h = -(o + eta i) / |.| (eta > 1) or +(o + eta i) / |.| (eta < 1): the one with
                # h.z > 0; a pair is reachable iff then o.h > 0 > i.h
                hx, hy, hz = o[0] + eta * ix, eta * iy, o[2] + eta * iz
                nrm = np.sqrt(hx * hx + hy * hy + hz * hz) * np.where(hz < 0, -1.0, 1.0)
                hx, hy, hz = hx / nrm, hy / nrm, hz / nrm
                c = hx * o[0] + hz * o[2]
                ih = hx * ix + hy * iy + hz * iz
                F, _, tir = fresnel(np.maximum(c, 0.0), eta)
                f = ((1 - F) * G * ndf_D(ndf, alpha, np.maximum(hz, 1e-300)) * np.abs(c * ih) * eta * eta
                     / (mu * (c + eta * ih) ** 2))
                val = np.where((c > 0) & (ih < 0) & (hz > 0) & ~tir, f, 0.0)
        tot += float(np.sum(W * val))
    return tot


def checks(quick=False):
    ok = True
    print("# check: eta = 1 closed form", flush=True)
    for ndf in ("ggx", "beckmann"):
        for sm in ("correlated", "separable"):
            for r in (0.3, 0.7, 1.0):
                for mu in (0.1, 0.5, 1.0):
                    a = r * r
                    L = float(lam(ndf, a, mu))
                    exact = (1 + L) / (1 + 2 * L) if sm == "correlated" else 1 / (1 + L)
                    g, s = albedo(ndf, sm, a, mu, 1.0, 20)
                    bad = abs(g - exact) > 1e-9 or abs(s) > 1e-15
                    ok &= not bad
                    print(f"  {ndf:8s} {sm:10s} r={r} mu={mu}: E={g:.15f} closed={exact:.15f} "
                          f"diff={g - exact:+.2e} spec={s:.1e}{'  FAIL' if bad else ''}")
    print("# check: spec_E -> F(mu) at r = 1e-3 (GGX, correlated)", flush=True)
    for eta in (1.5, 1 / 1.5, 2.42):
        for mu in (0.3, 0.8, 1.0):
            g, s = albedo("ggx", "correlated", 1e-6, mu, eta, 20)
            F = fresnel_scalar(mu, eta)
            bad = abs(s - F) > 1e-4 or abs(g - 1) > 1e-4
            ok &= not bad
            print(f"  eta={eta:.4f} mu={mu}: spec={s:.10f} F={F:.10f} diff={s - F:+.1e} "
                  f"glass-1={g - 1:+.1e}{'  FAIL' if bad else ''}")
    print("# check: integral over the light direction (Walter BSDF; 12 vs 20 nodes as its error)",
          flush=True)
    for ndf, sm, r, mu, eta in (("ggx", "correlated", 0.7, 0.5, 1.5),
                                ("ggx", "correlated", 0.7, 0.5, 1 / 1.5),
                                ("ggx", "separable", 1.0, 0.8, 1.33),
                                ("beckmann", "correlated", 0.7, 0.3, 1 / 1.33)):
        g, s = albedo(ndf, sm, r * r, mu, eta, 20)
        w = walter_over_i(ndf, sm, r * r, mu, eta)
        we = abs(w - walter_over_i(ndf, sm, r * r, mu, eta, n=12))
        bad = abs(w - g) > 3 * we + 1e-7
        ok &= not bad
        print(f"  {ndf} {sm} r={r} mu={mu} eta={eta:.4f}: h-rule {g:.10f} i-rule {w:.10f} "
              f"diff {w - g:+.1e} (i-rule error ~{we:.1e}){'  FAIL' if bad else ''}")
    print("# check: reciprocity T_avg(1/eta) = T_avg(eta) / eta^2 (from glass_Eavg.csv)", flush=True)
    path = os.path.join(HERE, "glass_Eavg.csv")
    avg = {}
    if os.path.exists(path):
        with open(path) as f:
            lines = [l for l in f if not l.startswith("#")]
        head = lines[0].strip().split(",")
        for l in lines[1:]:
            r = dict(zip(head, l.strip().split(",")))
            avg[(r["table"], r["ndf"], r["smith"], r["roughness"], float(r["eta"]))] = (
                float(r["value"]), float(r["err"]))
    else:
        print("  glass_Eavg.csv missing: computing one pair")
        for e in (1.5, 1 / 1.5):
            g, eg, s, es = average("ggx", "correlated", 0.25, e)
            avg[("glass_Eavg", "ggx", "correlated", "0.5", e)] = (g, eg)
            avg[("spec_Eavg", "ggx", "correlated", "0.5", e)] = (s, es)
    for (tab, ndf, sm, r, e), (g, eg) in sorted(avg.items()):
        if tab != "glass_Eavg" or e <= 1.0:
            continue
        inv = [k for k in avg if k[0] == "glass_Eavg" and k[1:4] == (ndf, sm, r)
               and abs(k[4] * e - 1.0) < 1e-12]
        if not inv:
            continue
        gB, eB = avg[inv[0]]
        s, es = avg[("spec_Eavg", ndf, sm, r, e)]
        sB, esB = avg[("spec_Eavg",) + inv[0][1:]]
        TA, TB = g - s, gB - sB
        diff = TB - TA / e ** 2
        tol = eg + es + eB + esB + 1e-12
        bad = abs(diff) > tol
        ok &= not bad
        print(f"  {ndf} {sm} r={r} eta={e:.4g}: T_avg(eta)={TA:.12f} T_avg(1/eta)={TB:.12f} "
              f"T_avg(eta)/eta^2={TA / e ** 2:.12f} diff={diff:+.2e} (tol {tol:.1e})"
              f"{'  FAIL' if bad else ''}")
    print("checks", "passed" if ok else "FAILED")
    return ok


# ------------------------------------------------------------------------------------------

ETAS = [("1.33", 1.33), ("1.5", 1.5), ("2.42", 2.42), ("1/1.33", 1 / 1.33), ("1/1.5", 1 / 1.5),
        ("1/2.42", 1 / 2.42), ("1", 1.0)]
RS = [0.2, 0.3, 0.5, 0.7, 1.0]
MUS = [0.1, 0.3, 0.5, 0.8, 1.0]


def points(quick=False):
    pts = []
    for ndf, sm in (("ggx", "correlated"), ("ggx", "separable")):
        for en, e in ETAS:
            for r in RS:
                for mu in MUS:
                    pts.append((ndf, sm, en, e, r, mu))
    for en, e in (("1.5", 1.5), ("1/1.5", 1 / 1.5), ("1", 1.0)):
        for r in (0.3, 0.7):
            for mu in (0.1, 0.5, 1.0):
                pts.append(("beckmann", "correlated", en, e, r, mu))
    if quick:
        pts = pts[::17]
    return pts


def write_E(path, quick=False):
    pts = points(quick)
    t0 = time.time()
    with open(path, "w") as f:
        f.write("# glass_E / spec_E reference: tests/data/glass/generate_reference.py "
                "(README.md beside it)\n")
        f.write("table,ndf,smith,eta_name,eta,roughness,alpha,mu,value,err\n")
        for k, (ndf, sm, en, e, r, mu) in enumerate(pts):
            (g, eg), (s, es) = albedo_with_error(ndf, sm, r * r, mu, e)
            for tab, v, er in (("glass_E", g, eg), ("spec_E", s, es)):
                f.write(f"{tab},{ndf},{sm},{en},{e:.17g},{r},{r * r:.17g},{mu},{v:.17g},{er:.3g}\n")
            f.flush()
            print(f"[{k + 1}/{len(pts)} {time.time() - t0:.0f}s] {ndf} {sm} eta={en} r={r} mu={mu}: "
                  f"glass {g:.12f} +- {eg:.1e}  spec {s:.12f} +- {es:.1e}", file=sys.stderr, flush=True)


AVG_POINTS = [("ggx", "correlated", "1.5", 1.5, 0.5), ("ggx", "correlated", "1/1.5", 1 / 1.5, 0.5),
              ("ggx", "correlated", "1.5", 1.5, 1.0), ("ggx", "correlated", "1/1.5", 1 / 1.5, 1.0)]


def write_avg(path, only=None):
    """All AVG_POINTS into a new file, or (only = list of indices) append those points."""
    t0 = time.time()
    fresh = only is None or not os.path.exists(path)
    with open(path, "w" if only is None else "a") as f:
        if fresh:
            f.write("# glass_Eavg / spec_Eavg reference: tests/data/glass/generate_reference.py "
                    "(README.md beside it)\n")
            f.write("table,ndf,smith,eta_name,eta,roughness,alpha,value,err\n")
        for j, (ndf, sm, en, e, r) in enumerate(AVG_POINTS):
            if only is not None and j not in only:
                continue
            g, eg, s, es = average(ndf, sm, r * r, e)
            for tab, v, er in (("glass_Eavg", g, eg), ("spec_Eavg", s, es)):
                f.write(f"{tab},{ndf},{sm},{en},{e:.17g},{r},{r * r:.17g},{v:.17g},{er:.3g}\n")
            f.flush()
            print(f"[{time.time() - t0:.0f}s] avg {ndf} {sm} eta={en} r={r}: glass {g:.12f} +- {eg:.1e} "
                  f"spec {s:.12f} +- {es:.1e}", file=sys.stderr, flush=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--E-only", action="store_true")
    ap.add_argument("--avg-only", action="store_true")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--avg-index", default=None,
                    help="with --avg-only: compute only these AVG_POINTS (e.g. 0,1) and append")
    ap.add_argument("--out", default=HERE)
    a = ap.parse_args()
    if a.check:
        sys.exit(0 if checks(a.quick) else 1)
    if not a.avg_only:
        write_E(os.path.join(a.out, "glass_E.csv"), a.quick)
    if not a.E_only:
        only = [int(q) for q in a.avg_index.split(",")] if a.avg_index else None
        write_avg(os.path.join(a.out, "glass_Eavg.csv"), only)


if __name__ == "__main__":
    main()
