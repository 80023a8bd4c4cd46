#!/usr/bin/python3
"""Reference values of the sheen albedo E(mu_o, alpha) and its average E_avg.

Independent of lutbake's C++: the half vector h is the variable (x =
cos(theta_h), azimuth phi_h), not the light direction, and every integral is
a composite Gauss-Legendre rule on fixed, heavily graded panels, evaluated at
two orders (n = 16 and 24 nodes per panel, the same panels). The value is the
24-node one; the stated error is |V24 - V16| plus the bounds of the parts
cut off (far tail of the lobe), plus 1e-15 |V| for rounding.

    E = 8 K int_{x_min}^1 dx (1 - x^2)^(q/2) int_0^{phi_max(x)} (o.h) W(mu_i) dphi,

from E = int D W d(omega_i), d(omega_i) = 4 (o.h) d(omega_h), d(omega_h) = dx dphi
and phi folded onto [0, pi]; D = K (1 - x^2)^(q/2), K = (2 + q) / (2 pi), q = 1/alpha;
o.h = s_o s_h cos(phi) + mu_o x, mu_i = 2 (o.h) x - mu_o; x_min = cos((theta_o + pi/2)/2).
W = V mu_i: charlie 1 / (4 mu_o (1 + Lambda(mu_o) + Lambda(mu_i))), ashikhmin
mu_i / (4 (mu_i + mu_o - mu_i mu_o)); Lambda is the glTF fit.

Panels. In x: graded by 2 (40 levels, and at least down to x_min / 64)
toward x_min (where phi_max -> 0 as a square root), toward 1 (the branch
point of (1 - x^2)^(q/2)), and from both sides toward the x where phi_max
reaches pi, where mu_i = 1 (phi = 0), and where mu_i = 0.5 meets phi = 0 or
pi; no panel longer than the lobe width
sqrt(2 alpha) / 2 up to where (1 - x^2)^(q/2) has fallen by e^-100. In phi:
[0, phi_half] and [phi_half, phi_max] (phi_half: mu_i = 0.5, Lambda's C1
point), each graded by 2 toward both ends (32 levels: Lambda's mu^c branch
point at mu_i = 0, reached at phi_max, and mu_i = 1 at phi = 0). Near
phi_max mu_i is formed without cancellation as
2 B sin^2(d/2) + A sin(phi_max) sin(d), d = phi_max - phi.

E_avg = 2 int_0^1 E(mu) mu dmu by Gauss-Legendre rules of 10 and 14 nodes
on the same mu panels (charlie: uniform panels in y = mu^c below
min(1/8, sqrt(alpha) / 2), where Lambda(mu_o) has its branch point and is
analytic in y; ashikhmin: graded by 2 toward 0, 16 levels; both: [15/16, 1]
by mu = 1 - u^2 / 16, in which s_o is analytic; a break at 1/2 for charlie).
E at each node by a lighter grading (NODE: n = 16); every 50th node is also
computed by the full rule, and 4 x the largest relative difference seen is
charged to every node. The x grading always reaches x_min / 64 (phi_max(x)
changes on the scale x_min ~ mu_o / 2 there; without this, E at mu_o = 1e-8
was off by 2e-8 relative).

Usage: generate_reference.py [--quick] [--E-only | --avg-only] (writes
sheen_E.csv and/or sheen_Eavg.csv beside this file). Needs numpy only.
"""
import math
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))


def gauss(n):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (x + 1.0), 0.5 * w


RULES = {n: gauss(n) for n in (16, 24)}


class Fit:
    """The glTF README's l(x, alpha) and Lambda."""

    def __init__(self, alpha):
        w = (1.0 - alpha) ** 2
        mix = lambda p, q: p * (1.0 - w) + q * w
        self.a = mix(21.5473, 25.3245)
        self.b = mix(3.82987, 3.32435)
        self.c = mix(0.19823, 0.16801)
        self.d = mix(-1.97760, -1.27393)
        self.e = mix(-4.32054, -4.85967)

    def l(self, x):
        return self.a / (1.0 + self.b * np.power(x, self.c)) + self.d * x + self.e

    def lam(self, mu, one_minus_mu):
        mu = np.asarray(mu, dtype=float)
        one_minus_mu = np.asarray(one_minus_mu, dtype=float)
        lo = np.exp(self.l(np.clip(mu, 0.0, 0.5)))
        hi = np.exp(2.0 * self.l(0.5) - self.l(np.clip(one_minus_mu, 0.0, 0.5)))
        return np.where(mu < 0.5, lo, hi)


def graded(a, b, levels, left=True, right=True):
    """Break points of [a, b] graded by 2 toward the chosen ends."""
    pts = {a, b}
    L = b - a
    for k in range(1, levels + 1):
        if left:
            pts.add(a + L * 0.5 ** (k + (1 if right else 0)))
        if right:
            pts.add(b - L * 0.5 ** (k + (1 if left else 0)))
    if left and right:
        pts.add(0.5 * (a + b))
    return sorted(p for p in pts if a <= p <= b)


def nodes_on(breaks, n):
    x, w = RULES[n]
    breaks = np.asarray(breaks)
    lo, hi = breaks[:-1], breaks[1:]
    keep = hi > lo
    lo, hi = lo[keep], hi[keep]
    X = (lo[:, None] + (hi - lo)[:, None] * x[None, :]).ravel()
    Wt = ((hi - lo)[:, None] * w[None, :]).ravel()
    return X, Wt


# The inner template: [0, 1] graded toward both ends, as (offset from 0,
# offset from 1, weight) so that both ends keep their relative accuracy.
def template(n, levels):
    x, w = RULES[n]
    pts = graded(0.0, 1.0, levels)
    lo = np.array(pts[:-1])
    hi = np.array(pts[1:])
    t = (lo[:, None] + (hi - lo)[:, None] * x[None, :]).ravel()
    # distance to 1, computed from the panel's upper end to keep accuracy
    d1 = ((1.0 - hi)[:, None] + (hi - lo)[:, None] * (1.0 - x)[None, :]).ravel()
    wt = ((hi - lo)[:, None] * w[None, :]).ravel()
    return t, d1, wt


TEMPLATES = {(n, k): template(n, k) for n in (16, 24) for k in (12, 16, 32)}

# Grading depths: FULL for the E table; NODE for the nodes of E_avg (checked
# against FULL as it goes, see average()); LIGHT in between, for experiments.
FULL = {"x": 40, "special": 30, "phi": 32}
LIGHT = {"x": 20, "special": 15, "phi": 16}
NODE = {"x": 14, "special": 10, "phi": 12}


def albedo(vis, alpha, mu_o, n, depth=FULL, chunk=256):
    """E at one point with the n-node rule; returns (value, tail bound)."""
    q = 1.0 / alpha
    p = 0.5 * q
    K = (2.0 + q) / (2.0 * math.pi)
    s_o = math.sqrt(max(0.0, (1.0 - mu_o) * (1.0 + mu_o)))
    fit = Fit(alpha)
    theta_o = math.acos(mu_o)
    lam_o = float(fit.lam(mu_o, 1.0 - mu_o))
    # x_min = cos((theta_o + pi/2) / 2) = sqrt((1 - s_o) / 2), 1 - s_o = mu_o^2 / (1 + s_o)
    x_min = math.sqrt(0.5 * mu_o * mu_o / (1.0 + s_o))
    # the lobe: (1 - x^2)^p falls by e^-100 from x_min at x_min + L
    L = math.sqrt(x_min * x_min + 200.0 / q) - x_min
    x_end = min(1.0, x_min + L)
    # Toward x_min at least down to ~x_min / 64 (phi_max(x) changes on the
    # scale x_min there; 1/x_min ~ 2/mu_o), at most 60 levels.
    levels = depth["x"]
    if x_min > 0.0:
        levels = max(levels, min(60, math.ceil(math.log2((x_end - x_min) / x_min)) + 6))
    breaks = set(graded(x_min, x_end, levels, left=True, right=(x_end >= 1.0)))
    width = max(math.sqrt(2.0 * alpha) / 2.0, 1e-300)
    m = int(min(4096, math.ceil((x_end - x_min) / width)))
    for k in range(1, m):
        breaks.add(x_min + (x_end - x_min) * k / m)
    specials = []
    if theta_o < 0.5 * math.pi:
        specials.append(0.25 * math.pi - 0.5 * theta_o)
    specials += [0.5 * theta_o, 0.5 * (theta_o + math.pi / 3), 0.5 * (theta_o - math.pi / 3),
                 0.5 * (math.pi / 3 - theta_o)]
    for th in specials:
        if th <= 0.0:
            continue
        xs = math.cos(th)
        if x_min < xs < x_end:
            lo = max(x for x in breaks if x < xs)
            hi = min(x for x in breaks if x > xs)
            breaks.update(graded(lo, xs, depth["special"], left=False, right=True))
            breaks.update(graded(xs, hi, depth["special"], left=True, right=False))
    breaks = sorted(breaks)
    X, WX = nodes_on(breaks, n)
    # tail beyond x_end: (o.h) W <= Wmax (charlie: o.h <= 1, W <= 1/(4 mu_o (1+lam_o)));
    # int_{x_end}^1 (1 - x^2)^p dx pi <= pi (1 - x_end) (1 - x_end^2)^p
    if vis == "charlie":
        wmax = 1.0 / (4.0 * mu_o * (1.0 + lam_o))
    else:
        wmax = 0.25
    tail = 0.0
    if x_end < 1.0:
        tail = 8.0 * K * wmax * math.pi * (1.0 - x_end) * math.exp(p * math.log1p(-x_end * x_end))
    t, d1, wt = TEMPLATES[(n, depth["phi"])]
    total = 0.0
    for start in range(0, X.size, chunk):
        x = X[start:start + chunk][:, None]
        wx = WX[start:start + chunk][:, None]
        sx = np.sqrt(np.maximum(0.0, (1.0 - x) * (1.0 + x)))
        # mu_i = A cos(phi) + B
        A = 2.0 * x * s_o * sx
        B = mu_o * (2.0 * x * x - 1.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            cstar = np.where(A > 0.0, -B / A, np.where(B > 0.0, -2.0, 2.0))
        phimax = np.where(cstar <= -1.0, math.pi, np.arccos(np.clip(cstar, -1.0, 1.0)))
        valid = cstar < 1.0
        # phi_half where mu_i = 0.5
        with np.errstate(divide="ignore", invalid="ignore"):
            ch = np.where(A > 0.0, (0.5 - B) / A, 2.0)
        has_half = (ch > -1.0) & (ch < 1.0)
        phihalf = np.where(has_half, np.arccos(np.clip(ch, -1.0, 1.0)), 0.0)
        phihalf = np.minimum(phihalf, phimax)
        lnD = p * np.log1p(-x * x)
        pref = wx * 8.0 * K * np.exp(lnD)
        acc = np.zeros(x.shape[0])
        for lo, hi in ((np.zeros_like(phihalf), phihalf), (phihalf, phimax)):
            span = hi - lo
            phi = lo + span * t[None, :]
            dfromend = span * d1[None, :] + (phimax - hi)  # phimax - phi
            weight = span * wt[None, :]
            cphi = np.cos(phi)
            # mu_i near phi_max without cancellation (where phi_max < pi)
            mu_far = A * cphi + B
            mu_near = 2.0 * B * np.sin(0.5 * dfromend) ** 2 + A * np.sin(phimax) * np.sin(dfromend)
            use_near = (phimax < math.pi) & (dfromend < 0.5)
            mu_i = np.where(use_near, mu_near, mu_far)
            mu_i = np.minimum(mu_i, 1.0)
            oh = s_o * sx * cphi + mu_o * x
            ok = (mu_i > 0.0) & (oh > 0.0) & valid & (span > 0.0)
            mu_c = np.where(ok, mu_i, 0.5)
            if vis == "charlie":
                one_minus = np.where(use_near, 1.0 - mu_c, 1.0 - mu_c)
                lam_i = fit.lam(mu_c, one_minus)
                f = oh / (4.0 * mu_o * (1.0 + lam_o + lam_i))
            else:
                f = oh * mu_c / (4.0 * (mu_c + mu_o * (1.0 - mu_c)))
            f = np.where(ok, f, 0.0)
            acc += np.sum(weight * f, axis=1)
        total += float(np.sum(pref[:, 0] * acc))
    return total, tail


def albedo_with_error(vis, alpha, mu, depth=FULL):
    v16, tail = albedo(vis, alpha, mu, 16, depth)
    v24, _ = albedo(vis, alpha, mu, 24, depth)
    err = abs(v24 - v16) + tail + 1e-15 * abs(v24)
    return v24, err


def average(vis, alpha):
    """E_avg with its error: outer rules of 12 and 16 nodes per panel on the
    same panels, E at each node by the LIGHT rule with its own error."""
    fit = Fit(alpha)
    c = fit.c
    lobe = 2.0 * math.sqrt(alpha)
    q = 1.0 / alpha
    K = (2.0 + q) / (2.0 * math.pi)

    def tail_bound(mu):
        # int_mu^1 2 mu E <= pi K (1 - mu) dhatmax(mu_o = mu, mu_i = 0) (mu W_max <= 1/4)
        s = math.sqrt(max(0.0, (1 - mu) * (1 + mu)))
        return math.pi * K * (1 - mu) * math.exp(-0.5 * q * math.log1p(mu * mu / (1 + s) ** 2))

    end = 1.0
    if tail_bound(0.5) < 1e-16:
        lo, hi = 0.0, 1.0
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if tail_bound(mid) <= 1e-16:
                hi = mid
            else:
                lo = mid
        end = hi
    tail = tail_bound(end) if end < 1.0 else 0.0
    h0 = min(0.125, 0.25 * lobe, 0.5 * end)
    panels = []  # (a, b, kind): "y": y = mu^c; "u": mu = 1 - (1 - a) u^2, u in [a', b']
    if vis == "charlie":
        Y = h0 ** c
        m = max(1, math.ceil(Y / 0.15))
        panels += [(Y * k / m, Y * (k + 1) / m, "y") for k in range(m)]
        lower = h0
    else:
        lower = 0.0
    pts = set(graded(lower, end, 16, left=True, right=False) if vis == "ashikhmin" else [lower, end])
    top = end
    if end >= 1.0:
        # [15/16, 1] by mu = 1 - u^2 / 16 (s_o analytic in u), graded toward 1 before it
        top = 1.0 - 1.0 / 16.0
        pts.update([0.75, 0.875, top])
        pts = {x for x in pts if x <= top}
    if vis == "charlie" and lower < 0.5 < top:
        pts.add(0.5)
    pts = sorted(pts)
    width = min(0.125, lobe / 2)
    for a, b in zip(pts[:-1], pts[1:]):
        m = max(1, math.ceil((b - a) / width))
        panels += [(a + (b - a) * k / m, a + (b - a) * (k + 1) / m, "mu") for k in range(m)]
    if end >= 1.0:
        panels += [(0.0, 0.5, "u"), (0.5, 1.0, "u")]
    # E at the nodes by the NODE grading (n = 16); every 50th node also by
    # the FULL one with its error, and the largest relative difference seen,
    # times 4, is charged to every node.
    cache = {}
    checks = []

    def node(mu):
        if mu not in cache:
            v, _ = albedo(vis, alpha, mu, 16, NODE)
            cache[mu] = v
            if len(cache) % 50 == 1:
                full, err = albedo_with_error(vis, alpha, mu)
                checks.append((abs(full - v) + err) / max(1.0, abs(full)))
        return cache[mu]

    values = {}
    mass = 0.0
    for n in (10, 14):
        x, w = gauss(n)
        total = 0.0
        for a, b, kind in panels:
            for xi, wi in zip(x, w):
                if kind == "y":
                    y = a + (b - a) * xi
                    mu = y ** (1.0 / c)
                    wt = (b - a) * wi * mu / (c * y)
                elif kind == "u":
                    u = a + (b - a) * xi
                    mu = 1.0 - u * u / 16.0
                    wt = (b - a) * wi * u / 8.0
                else:
                    mu = a + (b - a) * xi
                    wt = (b - a) * wi
                v = node(float(mu))
                total += 2.0 * mu * wt * v
                if n == 14:
                    mass += 2.0 * mu * wt * max(1.0, abs(v))
        values[n] = total
    node_error = 4.0 * max(checks) * mass
    return values[14], abs(values[14] - values[10]) + node_error + tail + 1e-15 * abs(values[14])


ALPHAS = [1e-8, 1e-6, 1e-4, 9e-4, 1e-3, 0.0025, 0.01, 0.03, 0.07, 0.1, 0.25, 0.3, 0.5, 0.7, 0.9,
          1.0]
MUS = [1e-6, 1e-4, 1e-3, 0.01, 0.03, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 0.99, 1.0]
AVG_ALPHAS = [1.0, 0.5, 0.25, 0.1, 0.01]


def main():
    quick = "--quick" in sys.argv
    start = time.time()
    rows = []
    for vis in (() if "--avg-only" in sys.argv else ("charlie", "ashikhmin")):
        for alpha in ALPHAS:
            for mu in MUS:
                if quick and not (alpha in (0.25, 1.0) and mu in (0.5, 0.1)):
                    continue
                v, e = albedo_with_error(vis, alpha, mu)
                rows.append((vis, alpha, mu, v, e))
                print(f"{vis},{alpha!r},{mu!r},{v:.17g},{e:.3g}", flush=True)
    if rows:
        with open(os.path.join(HERE, "sheen_E.csv"), "w") as f:
            f.write("# sheen_E reference: tests/data/sheen/generate_reference.py (README.md beside it)\n")
            f.write("visibility,alpha,mu,E,error\n")
            for vis, alpha, mu, v, e in rows:
                f.write(f"{vis},{alpha!r},{mu!r},{v:.17g},{e:.3g}\n")
    if "--E-only" in sys.argv:
        print(f"# {time.time() - start:.0f} s", file=sys.stderr)
        return
    avg_rows = []
    for vis in ("charlie", "ashikhmin"):
        for alpha in AVG_ALPHAS:
            if quick and alpha != 1.0:
                continue
            v, e = average(vis, alpha)
            avg_rows.append((vis, alpha, v, e))
            print(f"avg {vis},{alpha!r},{v:.17g},{e:.3g}", flush=True)
    with open(os.path.join(HERE, "sheen_Eavg.csv"), "w") as f:
        f.write("# sheen_Eavg reference: tests/data/sheen/generate_reference.py (README.md beside it)\n")
        f.write("visibility,alpha,Eavg,error\n")
        for vis, alpha, v, e in avg_rows:
            f.write(f"{vis},{alpha!r},{v:.17g},{e:.3g}\n")
    print(f"# {time.time() - start:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
