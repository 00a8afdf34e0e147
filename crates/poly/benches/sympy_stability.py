#!/usr/bin/env python3
"""The same job as benches/stability.rs, in SymPy, for the ratios in BENCHMARKS.md.

Setup (not part of the tests):  python3 -m venv /tmp/sympy-venv &&
/tmp/sympy-venv/bin/pip install sympy
Run:  /tmp/sympy-venv/bin/python crates/poly/benches/sympy_stability.py

For each method, chi(z; Phi) is the charpoly printed by `zcheck derive`
(passed here as text, so both sides start from the same polynomial). Two
jobs are timed:

- the core job (the first measurements): the resultant of chi and its
  reciprocal z^n chi(1/z), chi(1), chi(-1), the leading and constant
  coefficients and the discriminant in z, each factored over Q, and the
  positive real roots of every factor isolated exactly (real_roots);
- the same job: every condition zcheck's analysis computes, the core plus
  the ties of moduli (r = -s; for degree 3 and 4 a real root against a
  complex pair) and, when chi has a self-reciprocal factor (the resultant
  vanishes identically), the cofactor's resultant and the discriminant of G
  with g(z) = z^m G(z + 1/z). Its positive roots are checked against the
  critical points `zcheck stability` reports (as floats: a check outside
  the test suite); the core job misses some on most rows.

Neither classifies the intervals between the points or decides boundedness
at them (zcheck does both), so both ratios understate zcheck's lead. Times
are the best of 3 runs. ZCHECK names the zcheck binary (default: on PATH).
"""
import subprocess, sys, time, os
import sympy as sp

METHODS = ["ab2", "ab3", "ab4", "ab5", "ab6", "ab7", "ab8", "leapfrog", "nystrom3",
           "nystrom4", "nystrom5", "nystrom6", "rk4", "merson", "ssprk104"]
HERE = os.path.dirname(os.path.abspath(__file__))
ZCHECK = os.environ.get("ZCHECK", "zcheck")
z, Phi = sp.symbols("z Phi")


def charpoly(name):
    path = os.path.join(HERE, "..", "methods", name + ".zm")
    out = subprocess.run([ZCHECK, "derive", path, "--format", "json"], capture_output=True,
                         text=True, check=True).stdout
    import json
    return sp.sympify(json.loads(out)["charpoly"].replace("^", "**"), locals={"z": z, "Phi": Phi})


def positive_roots(conds):
    roots = []
    for c in conds:
        c = sp.expand(c)
        if c.free_symbols:
            for f, _ in sp.factor_list(c)[1]:
                roots += [r for r in sp.Poly(f, Phi).real_roots() if r > 0]
    return roots


def core_conditions(chi):
    """The core: a_n, a_0, chi(+-1), Res(chi, chi*), the discriminant."""
    p = sp.Poly(chi, z)
    n = p.degree()
    rev = sp.Poly(sp.expand(z**n * chi.subs(z, 1 / z)), z)
    return [p.LC(), p.coeffs()[-1], chi.subs(z, 1), chi.subs(z, -1),
            sp.resultant(p, rev, z), sp.discriminant(p, z)]


def job(chi):
    """The core job, as in the first measurements."""
    return positive_roots(core_conditions(chi))


y, x = sp.symbols("y x")


def newton_poly(sums, m):
    """The monic polynomial in x of degree m with power sums sums[1..m]."""
    e = [sp.Integer(1)]
    for k in range(1, m + 1):
        e.append(sp.expand(sum((-1) ** (i - 1) * e[k - i] * sums[i] for i in range(1, k + 1)) / k))
    return sp.Poly(sum((-1) ** k * e[k] * x ** (m - k) for k in range(m + 1)), x)


def full_job(chi):
    """The core job plus the conditions zcheck also computes: ties of moduli
    (r = -s: Res(E, O) with chi = E(z^2) + z O(z^2); for degree 3 and 4, a
    real root against a complex pair: Res(squares, pair products)), and for
    a self-reciprocal factor (Res(chi, chi*) = 0 identically) the cofactor's
    resultant and the discriminant of G with g(z) = z^m G(z + 1/z)."""
    p = sp.Poly(chi, z)
    n = p.degree()
    conds = core_conditions(chi)
    if sp.expand(conds[4]) == 0:
        rev = sp.Poly(sp.expand(z**n * chi.subs(z, 1 / z)), z)
        g = sp.gcd(p, rev)
        h = sp.quo(p, g)
        if h.degree() >= 2:
            hrev = sp.Poly(sp.expand(z**h.degree() * h.as_expr().subs(z, 1 / z)), z)
            conds.append(sp.resultant(h, hrev, z))
        for s in (1, -1):
            while g.degree() >= 1 and sp.expand(g.as_expr().subs(z, s)) == 0:
                g = sp.quo(g, sp.Poly(z - s, z))
        if g.degree() >= 2 and g.degree() % 2 == 0:
            m = g.degree() // 2
            # G(z + 1/z) = g(z) / z^m: solve for G's coefficients in x.
            gg = sp.expand(g.as_expr() / z**m)
            big_g = 0
            for k in range(m, -1, -1):
                c = sp.expand(gg).coeff(z, k) if k > 0 else sp.expand(gg).coeff(z, 0)
                big_g += c * x**k
                gg = sp.expand(gg - c * (z + 1 / z) ** k)
            conds.append(sp.discriminant(sp.Poly(big_g, x), x))
    cs = p.all_coeffs()[::-1]
    e_part = sum(cs[2 * k] * y**k for k in range((n + 2) // 2))
    o_part = sum(cs[2 * k + 1] * y**k for k in range((n + 1) // 2))
    ep, op = sp.Poly(e_part, y), sp.Poly(o_part, y)
    if not ep.is_zero and not op.is_zero:
        if op.degree() == 0:
            conds.append(op.as_expr())
        elif ep.degree() == 0:
            conds.append(ep.as_expr())
        else:
            conds.append(sp.resultant(ep, op, y))
    if n in (3, 4):
        monic = [c / cs[n] for c in cs]
        # Power sums of the roots, by Newton's identities.
        pairs = n * (n - 1) // 2
        s = [sp.Integer(n)]
        for k in range(1, max(2 * pairs, 2 * n) + 1):
            t = -k * monic[n - k] if k <= n else 0
            t -= sum(monic[n - i] * s[k - i] for i in range(1, min(k, n + 1)) if k - i >= 0)
            s.append(sp.expand(t))
        pair_sums = [None] + [sp.expand((s[k] ** 2 - s[2 * k]) / 2) for k in range(1, pairs + 1)]
        square_sums = [None] + [s[2 * k] for k in range(1, n + 1)]
        products = newton_poly(pair_sums, pairs)
        squares = newton_poly(square_sums, n)
        conds.append(sp.together(sp.resultant(squares, products, x)).as_numer_denom()[0])
    return positive_roots(conds)


def zcheck_points(name):
    """The critical points of `zcheck stability`, as floats (for the check)."""
    path = os.path.join(HERE, "..", "methods", name + ".zm")
    out = subprocess.run([ZCHECK, "stability", path, "--format", "json"], capture_output=True,
                         text=True, check=True).stdout
    import json
    return sorted(c["phi"] for c in json.loads(out)["critical_points"])


def distinct(xs):
    return sorted({round(float(x), 9) for x in xs})


def main():
    print("method     core job (ms)   same job (ms)   same job's points")
    for name in METHODS:
        chi = charpoly(name)
        times = []
        for f in (job, full_job):
            best = float("inf")
            for _ in range(3):
                t = time.perf_counter()
                roots = f(chi)
                best = min(best, time.perf_counter() - t)
            times.append(best)
        # The same job must find the same critical points as zcheck.
        same = distinct(roots) == distinct(zcheck_points(name))
        print(f"{name:10s} {times[0] * 1e3:13.2f} {times[1] * 1e3:15.2f}   "
              f"{'= zcheck' if same else 'DIFFER from zcheck'}", flush=True)


if __name__ == "__main__":
    sys.exit(main())
