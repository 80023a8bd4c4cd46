#!/usr/bin/python3
"""Independent furnace values for tests/integrators/furnace_test.cpp.

Method: the directional albedo int f(o, i) mu_i d(omega_i) over the light
direction i = (theta_i, phi_i) of the hemisphere, with the BRDFs written
here from their formulas (nothing shared with lutbake's code, which
integrates in other variables: cones about the mirror, the half vector,
closed-form azimuths). Tensor Gauss-Legendre rules on panels split where
the integrands have kinks or peaks: theta_i at theta_o and around the
mirror lobe, phi_i at pi/2 (Oren-Nayar's and EON's cos(dphi) switches) and
near pi (the mirror). Every value is computed with 96 and 192 nodes per
panel and dimension; the value is the finer one's, the error column
|fine - coarse| + 1e-13 (Gauss-Legendre converges geometrically on these
analytic panels, so the coarse rule's error bounds the fine one's).

Run: /usr/bin/python3 tests/data/furnace/reference.py > tests/data/furnace/reference.csv
"""
import numpy as np

PI = np.pi


def gl(a, b, n):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (b - a) * x + 0.5 * (b + a), 0.5 * (b - a) * w


def albedo(brdf, mu_o, theta_breaks, phi_breaks, n):
    """2 int_0^pi dphi int_0^pi/2 dtheta f mu_i sin(theta_i)."""
    s_o = np.sqrt(1 - mu_o * mu_o)
    o = np.array([s_o, 0.0, mu_o])
    total = 0.0
    tb = sorted(set(b for b in theta_breaks if 0 <= b <= PI / 2))
    pb = sorted(set(b for b in phi_breaks if 0 <= b <= PI))
    for ta, tb_ in zip(tb[:-1], tb[1:]):
        if tb_ <= ta:
            continue
        t, wt = gl(ta, tb_, n)
        for pa, pb_ in zip(pb[:-1], pb[1:]):
            if pb_ <= pa:
                continue
            p, wp = gl(pa, pb_, n)
            T, P = np.meshgrid(t, p, indexing="ij")
            W = np.outer(wt, wp)
            i = np.stack([np.sin(T) * np.cos(P), np.sin(T) * np.sin(P), np.cos(T)])
            f = brdf(o, i)
            total += np.sum(W * f * np.cos(T) * np.sin(T))
    return 2.0 * total


def phong_n2(n):
    def f(o, i):
        r = np.array([-o[0], 0.0, o[2]])
        c = np.maximum(0.0, r[0] * i[0] + r[2] * i[2])
        return (n + 2) / (2 * PI) * c**n
    return f


def blinn_exact(n):
    c = (n + 2) * (n + 4) / (8 * PI * (n + 2.0 ** (-n / 2)))
    def f(o, i):
        h = o[:, None, None] + i
        hz = h[2] / np.sqrt(np.sum(h * h, axis=0))
        return c * hz**n
    return f


def oren_nayar(sigma, full):
    s2 = sigma * sigma
    def f(o, i):
        th_o = np.arccos(o[2])
        th_i = np.arccos(np.clip(i[2], -1, 1))
        a = np.maximum(th_o, th_i)
        b = np.minimum(th_o, th_i)
        si = np.sqrt(i[0] ** 2 + i[1] ** 2)
        cphi = np.where(si > 0, i[0] / np.maximum(si, 1e-300), 0.0)  # o has phi = 0
        if not full:
            A = 1 - 0.5 * s2 / (s2 + 0.33)
            B = 0.45 * s2 / (s2 + 0.09)
            return (A + B * np.maximum(0, cphi) * np.sin(a) * np.tan(b)) / PI
        C1 = 1 - 0.5 * s2 / (s2 + 0.33)
        K2 = 0.45 * s2 / (s2 + 0.09)
        C2 = np.where(cphi >= 0, K2 * np.sin(a), K2 * (np.sin(a) - (2 * b / PI) ** 3))
        C3 = 0.125 * s2 / (s2 + 0.09) * (4 * a * b / PI**2) ** 2
        L1 = C1 + cphi * C2 * np.tan(b) + (1 - np.abs(cphi)) * C3 * np.tan((a + b) / 2)
        L2 = 0.17 * s2 / (s2 + 0.13) * (1 - cphi * (2 * b / PI) ** 2)
        return (L1 + L2) / PI
    return f


C1F = 0.5 - 2 / (3 * PI)
C2F = 2 / 3 - 28 / (15 * PI)


def e_fon(mu, r):
    S = np.sqrt(1 - mu * mu)
    G = S * (np.arccos(mu) - S * mu) + 2 / 3 * ((S / mu) * (1 - S**3) - S)
    return (1 + r * G / PI) / (1 + C1F * r)


def eon(r, multiple):
    AF = 1 / (1 + C1F * r)
    Eavg = AF * (1 + C2F * r)
    def f(o, i):
        s = o[0] * i[0] + o[1] * i[1] + o[2] * i[2] - o[2] * i[2]
        t = np.where(s > 0, np.maximum(i[2], o[2]), 1.0)
        fss = AF * (1 + r * s / t) / PI
        if not multiple:
            return fss
        fms = (1 - e_fon(o[2], r)) * (1 - e_fon(i[2], r)) / (PI * (1 - Eavg))
        return fss + fms
    return f


def ggx_lambda(alpha, mu):
    mu = np.clip(mu, 1e-300, 1)
    return (np.sqrt(1 + alpha**2 * (1 - mu**2) / mu**2) - 1) / 2


def fresnel_dielectric(eta, c):
    g2 = eta * eta - 1 + c * c
    g = np.sqrt(np.maximum(g2, 0))
    F = 0.5 * ((g - c) / (g + c)) ** 2 * (1 + ((c * (g + c) - 1) / (c * (g - c) + 1)) ** 2)
    return np.where(g2 < 0, 1.0, F)


def microfacet(r, visibility, fresnel):
    alpha = r * r
    def f(o, i):
        h = o[:, None, None] + i
        h = h / np.sqrt(np.sum(h * h, axis=0))
        ct = h[2]
        D = alpha**2 / (PI * (alpha**2 * ct**2 + (1 - ct**2)) ** 2)
        mo, mi = o[2], np.maximum(i[2], 1e-300)
        if visibility == "correlated":
            G = 1 / (1 + ggx_lambda(alpha, mo) + ggx_lambda(alpha, mi))
        else:
            k = alpha / 2 if visibility == "schlick-ggx-ibl" else (r + 1) ** 2 / 8
            G = mo / (mo * (1 - k) + k) * mi / (mi * (1 - k) + k)
        oh = np.clip(np.sum(o[:, None, None] * h, axis=0), 0, 1)
        if fresnel == "one":
            F = 1.0
        elif fresnel == "schlick0.04":
            F = 0.04 + 0.96 * (1 - oh) ** 5
        else:
            F = fresnel_dielectric(1.5, oh)
        return D * G * F / (4 * mo * mi)
    return f


def breaks(mu_o, width):
    th_o = np.arccos(mu_o)
    tb = [0, th_o - 4 * width, th_o - width, th_o, th_o + width, th_o + 4 * width, PI / 2]
    pb = [0, PI / 2, PI - 4 * width, PI - width, PI]
    return tb, pb


def row(name, variant, p, mu, brdf, width):
    tb, pb = breaks(mu, width)
    coarse = albedo(brdf, mu, tb, pb, 96)
    fine = albedo(brdf, mu, tb, pb, 192)
    print(f"{name},{variant},{p!r},{mu!r},{fine:.17g},{abs(fine - coarse) + 1e-13:.3g}")


print("model,variant,parameter,mu,value,error")
for mu in (0.1, 0.5, 0.9):
    for n in (4.0, 20.0, 100.0):
        row("phong", "n+2", n, mu, phong_n2(n), 2 / np.sqrt(n))
    for n in (1.0, 20.0, 100.0):
        row("blinn-phong", "exact", n, mu, blinn_exact(n), 4 / np.sqrt(n + 1))
    for sigma in (0.3, 1.0):
        row("oren-nayar", "full", sigma, mu, oren_nayar(sigma, True), 0.3)
        row("oren-nayar", "qualitative", sigma, mu, oren_nayar(sigma, False), 0.3)
    for r in (0.5, 1.0):
        row("eon", "fon", r, mu, eon(r, False), 0.3)
        row("eon", "exact", r, mu, eon(r, True), 0.3)
    for r in (0.5, 1.0):
        row("microfacet", "correlated/one", r, mu, microfacet(r, "correlated", "one"), r * r)
        row("microfacet", "correlated/dielectric1.5", r, mu,
            microfacet(r, "correlated", "dielectric"), r * r)
        row("microfacet", "schlick-ggx-ibl/schlick0.04", r, mu,
            microfacet(r, "schlick-ggx-ibl", "schlick0.04"), r * r)
        row("microfacet", "schlick-ggx-direct/one", r, mu,
            microfacet(r, "schlick-ggx-direct", "one"), r * r)
