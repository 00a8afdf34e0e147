"""An independent, slow oracle for the real and imaginary stability limits of
a method on y' = lambda*y, from its characteristic polynomial

    chi(z; w) = sum_j c_j(w) z^j      (w = h*lambda)

(Runge-Kutta: chi = Q(w) z - P(w); linear multistep: c_j = alpha_j - w beta_j).

On the ray w = t*d (d = -1: the negative real axis; d = i: the imaginary
axis), the root set can change its stability only at values t >= 0 where

  * a root lies on the unit circle: Res_z(chi_t, chi_t^*) = 0, with
    chi^*(z) = z^n conj(chi(1/conj z)) (zero for every t when the method is
    symmetric on that ray; then roots leave the circle only in pairs, at
  * a multiple root: Disc_z(chi_t) = 0, or
  * a root at infinity: c_n(t d) = 0.

These breakpoints are found exactly (SymPy resultants) and then numerically
(mpmath polyroots, 60 digits); each open segment between them is tested at
its midpoint and each breakpoint itself (roots with |z| <= 1, those on the
circle simple), at 60 digits. A dense double-precision scan checks the
answer. The limit is the supremum r with stability on (0, r) and at every
breakpoint below r; None when the whole ray is stable.
"""

import mpmath
import numpy as np
import sympy

mpmath.mp.dps = 60
W, Z = sympy.symbols("w z")
T = sympy.Symbol("t", real=True)


def roots(hi):
    """All roots of the polynomial with coefficients `hi` (highest first),
    robust to roots at 0 and to multiple roots (mpmath, then more steps)."""
    hi = list(hi)
    zeros = 0
    while len(hi) > 1 and hi[-1] == 0:
        hi.pop()
        zeros += 1
    out = [mpmath.mpc(0)] * zeros
    if len(hi) <= 1:
        return out
    if len(hi) == 2:
        return out + [-mpmath.mpc(hi[1]) / hi[0]]
    for steps, extra in ((400, 400), (3000, 1500), (20000, 4000)):
        try:
            r = mpmath.polyroots(hi, maxsteps=steps, extraprec=extra)
            return out + list(r if isinstance(r, (list, tuple)) else [r])
        except mpmath.libmp.libhyper.NoConvergence:
            continue
    raise RuntimeError("polyroots did not converge")


def _poly_roots_nonneg(expr):
    """Real roots t > 0 of a polynomial in T (complex coefficients allowed)."""
    expr = sympy.expand(expr)
    if expr == 0:
        return None
    p = sympy.Poly(expr, T)
    if p.degree() <= 0:
        return []
    # strip the factor t^m
    coeffs = p.all_coeffs()
    while coeffs and coeffs[-1] == 0:
        coeffs.pop()
    if len(coeffs) <= 1:
        return []
    cs = [mpmath.mpc(complex(sympy.N(sympy.re(c), 70))) if False else
          mpmath.mpc(sympy.N(sympy.re(c), 70), sympy.N(sympy.im(c), 70)) for c in coeffs]
    rts = roots(cs)
    out = []
    for r in rts:
        r = mpmath.mpc(r)
        if abs(r.imag) <= mpmath.mpf("1e-25") * max(1, abs(r)) and r.real > mpmath.mpf("1e-40"):
            out.append(mpmath.mpf(r.real))
    return out


def stable_at(cs_w, w):
    """cs_w: list of sympy expressions in W (lowest power of z first).
    Stable: every root |z| <= 1, roots on the circle simple."""
    cs = [mpmath.mpc(complex(0)) for _ in cs_w]
    for j, c in enumerate(cs_w):
        cs[j] = _eval(c, w)
    n = len(cs) - 1
    while n > 0 and abs(cs[n]) < mpmath.mpf("1e-40"):
        return False  # a root at infinity (pole of R, or alpha_k - w beta_k = 0)
    if n == 0:
        return True
    hi = list(reversed(cs[: n + 1]))
    rts = roots(hi)
    tol = mpmath.mpf("1e-25")
    on = []
    for r in rts:
        m = abs(r)
        if m > 1 + tol:
            return False
        if abs(m - 1) <= tol:
            on.append(r)
    for i in range(len(on)):
        for j in range(i + 1, len(on)):
            if abs(on[i] - on[j]) < mpmath.mpf("1e-12"):
                return False
    return True


_cache = {}


def _eval(c, w):
    key = id(c)
    f = _cache.get(key)
    if f is None or f[0] is not c:
        p = sympy.Poly(c, W)
        co = [mpmath.mpc(sympy.N(sympy.re(a), 70), sympy.N(sympy.im(a), 70)) for a in p.all_coeffs()]
        f = (c, co)
        _cache[key] = f
    return mpmath.polyval(f[1], w)


def ray_limit(cs_w, direction):
    """The stability limit along w = t*direction, t >= 0 (see module doc).
    Returns (limit or None, info dict)."""
    d = sympy.Integer(-1) if direction == "real" else sympy.I
    dm = mpmath.mpf(-1) if direction == "real" else mpmath.mpc(0, 1)
    ct = [sympy.expand(c.subs(W, d * T)) for c in cs_w]
    n = len(ct) - 1
    while n > 0 and ct[n] == 0:
        n -= 1
    ct = ct[: n + 1]
    chi = sum(c * Z**j for j, c in enumerate(ct))
    chistar = sum(sympy.conjugate(c) * Z ** (n - j) for j, c in enumerate(ct))
    chistar = sympy.expand(chistar)
    info = {"resultant_identically_zero": False}
    bps = []
    if n >= 1:
        res = sympy.resultant(sympy.Poly(chi, Z), sympy.Poly(chistar, Z))
        res = res.as_expr() if hasattr(res, "as_expr") else res
        r = _poly_roots_nonneg(res)
        if r is None:
            info["resultant_identically_zero"] = True
        else:
            bps += r
    if n >= 2:
        disc = sympy.discriminant(sympy.Poly(chi, Z))
        disc = disc.as_expr() if hasattr(disc, "as_expr") else disc
        r = _poly_roots_nonneg(disc)
        if r:
            bps += r
    r = _poly_roots_nonneg(ct[n])
    if r:
        bps += r
    bps = sorted(bps)
    uniq = []
    for b in bps:
        if not uniq or abs(b - uniq[-1]) > mpmath.mpf("1e-40") * max(1, b):
            uniq.append(b)
    info["breakpoints"] = [float(b) for b in uniq]
    prev = mpmath.mpf(0)
    limit = None
    for b in uniq + [None]:
        mid = (prev + b) / 2 if b is not None else (2 * prev + 1)
        if not stable_at(cs_w, mid * dm):
            limit = prev
            break
        if b is None:
            break
        if not stable_at(cs_w, b * dm):
            limit = b
            break
        prev = b
    info["scan"] = _scan_check(cs_w, dm, limit)
    return limit, info


def _scan_check(cs_w, dm, limit):
    """Double-precision scan: stable on (0, limit) (at 4000 points, |z| <= 1 +
    1e-9) and, when finite, |z| > 1 + 1e-14 somewhere in (limit, 1.02 limit + 0.01]."""
    polys = [np.array([complex(a) for a in reversed(sympy.Poly(c, W).all_coeffs())]) for c in cs_w]

    def maxroot(w):
        cs = [np.polyval(p[::-1], w) for p in polys]
        while len(cs) > 1 and abs(cs[-1]) < 1e-300:
            return np.inf
        if len(cs) == 2:
            return abs(cs[0] / cs[1])
        return max(abs(np.roots(cs[::-1])))

    dmc = complex(dm)
    top = float(limit) if limit is not None else 1e3
    ts = np.linspace(0, top, 4001)[1:-1]
    bad = [t for t in ts if maxroot(t * dmc) > 1 + 1e-9]
    ok = not bad
    beyond = None
    if limit is not None:
        lo = float(limit)
        tb = np.linspace(lo, lo * 1.02 + 1e-2, 401)[1:]
        beyond = any(maxroot(t * dmc) > 1 + 1e-14 for t in tb)
    return {"stable_below": ok, "first_bad_below": (float(bad[0]) if bad else None), "unstable_just_beyond": beyond}
