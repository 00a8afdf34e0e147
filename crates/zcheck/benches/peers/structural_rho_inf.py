#!/usr/bin/env python3
"""Independent check of crates/zcheck/tests/data/structural/*.zm.

For HHT-alpha and generalized-alpha on x'' = -w^2 x (y = x, v = x'/w,
a = x''/w^2, Phi = w dt), this builds the amplification matrix A(Phi) of
(a, v, y) straight from the literature definitions in SymPy (not from the
.zm files), and

  1. computes rho_inf = lim_{Phi->oo} spectral radius = spectral radius of
     lim A(Phi), exactly, for a table of parameter values, against the closed
     forms (HHT: (1 + alpha)/(1 - alpha); generalized-alpha: rho_inf);
  2. checks that zcheck's chi(z) (`zcheck derive FILE --format json`, with the
     parameters substituted) is a constant multiple of det(z I - A(Phi));
  3. checks rho(A(Phi)) at Phi = 1e6 numerically (numpy).

Prints the Markdown table used in tests/data/structural/README.md.
Usage: python structural_rho_inf.py [--zcheck PATH]
"""

import argparse
import json
import os
import subprocess
import sys

import numpy as np
import sympy as sp

HERE = os.path.dirname(os.path.abspath(__file__))
STRUCT = os.path.normpath(os.path.join(HERE, "..", "..", "tests", "data", "structural"))
REPO = os.path.normpath(os.path.join(HERE, "..", "..", "..", ".."))

Phi, z = sp.symbols("Phi z", positive=True)
a0, v0, y0, a1, v1, y1 = sp.symbols("a0 v0 y0 a1 v1 y1")


def amplification(eq_motion, beta, gamma):
    """A(Phi) with (a1, v1, y1) = A (a0, v0, y0), from the equation of motion
    (an expression that vanishes) and Newmark's updates."""
    eqs = [
        eq_motion,
        y1 - (y0 + Phi * v0 + Phi**2 * ((sp.Rational(1, 2) - beta) * a0 + beta * a1)),
        v1 - (v0 + Phi * ((1 - gamma) * a0 + gamma * a1)),
    ]
    sol = sp.solve(eqs, [a1, v1, y1], dict=True)[0]
    return sp.Matrix([[sp.simplify(sp.diff(sol[u1], u0)) for u0 in (a0, v0, y0)] for u1 in (a1, v1, y1)])


def hht(alpha):
    gamma = sp.Rational(1, 2) - alpha
    beta = (1 - alpha) ** 2 / 4
    return amplification(a1 + (1 + alpha) * y1 - alpha * y0, beta, gamma)


def genalpha(am, af, beta, gamma):
    return amplification((1 - am) * a1 + am * a0 + (1 - af) * y1 + af * y0, beta, gamma)


def genalpha_rho(r):
    am = (2 * r - 1) / (r + 1)
    af = r / (r + 1)
    return genalpha(am, af, (1 - am + af) ** 2 / 4, sp.Rational(1, 2) - am + af)


def rho_inf(A):
    """The limit of the spectral radius: the entries of A(Phi) need not
    converge (a_{n+1} grows like Phi v_n), but the coefficients of the monic
    characteristic polynomial do; its limit's roots are the limits of the
    eigenvalues."""
    chi = sp.Poly(sp.cancel((z * sp.eye(A.shape[0]) - A).det()), z)
    lead = chi.LC()
    lim = sp.Poly([sp.limit(sp.cancel(c / lead), Phi, sp.oo) for c in chi.all_coeffs()], z)
    ev = sp.roots(lim)
    assert sum(ev.values()) == lim.degree(), lim
    r = max((sp.Abs(e) for e in ev), key=lambda e: float(e))
    return sp.nsimplify(sp.simplify(r)), lim, ev


def rho_numeric(A, phi=1e6):
    M = np.array(A.subs(Phi, phi).evalf(30).tolist(), dtype=complex)
    return max(abs(np.linalg.eigvals(M)))


def zcheck_chi(zcheck, path, params):
    r = subprocess.run([zcheck, "derive", path, "--format", "json"], capture_output=True, text=True)
    if r.returncode != 0:
        return None, r.stderr.strip()
    d = json.loads(r.stdout)
    text = d.get("charpoly") or d.get("chi")
    if text is None:
        return None, f"no charpoly in JSON keys {sorted(d)}"
    syms = {k: sp.Symbol(k) for k in params}
    syms.update({"Phi": Phi, "z": z})
    e = sp.sympify(text.replace("^", "**"), locals=syms)
    return sp.expand(e.subs({syms[k]: v for k, v in params.items()})), None


def proportional(p, q):
    """p = f(Phi) q with f free of z (zcheck's chi is det A(Phi) det(zI - P))."""
    ratio = sp.cancel(p / q)
    return z not in ratio.free_symbols, ratio


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--zcheck", default=os.environ.get("ZCHECK", os.path.join(REPO, "target", "release", "zcheck")))
    args = ap.parse_args()
    ok = True
    rows = []
    R = sp.Rational
    for alpha in [R(0), R(-1, 20), R(-1, 10), R(-1, 6), R(-1, 5), R(-1, 4), R(-3, 10), R(-1, 3)]:
        A = hht(alpha)
        r, Ainf, ev = rho_inf(A)
        closed = (1 + alpha) / (1 - alpha)
        chi, err = zcheck_chi(args.zcheck, os.path.join(STRUCT, "hht_alpha.zm"), {"alpha": alpha})
        prop = proportional(chi, (z * sp.eye(3) - A).det())[0] if chi is not None else err
        rows.append(("hht_alpha.zm", f"alpha = {alpha}", r, closed, sp.simplify(r - closed) == 0, rho_numeric(A), ev, prop))
    for rr in [R(0), R(1, 4), R(1, 2), R(3, 4), R(9, 10), R(1)]:
        A = genalpha_rho(rr)
        r, Ainf, ev = rho_inf(A)
        chi, err = zcheck_chi(args.zcheck, os.path.join(STRUCT, "generalized_alpha.zm"), {"rho_inf": rr})
        prop = proportional(chi, (z * sp.eye(3) - A).det())[0] if chi is not None else err
        rows.append(("generalized_alpha.zm", f"rho_inf = {rr}", r, rr, sp.simplify(r - rr) == 0, rho_numeric(A), ev, prop))
    # the four-parameter program at Chung-Hulbert's choice, at HHT (alpha_m = 0) and at WBZ (alpha_f = 0)
    four = os.path.join(STRUCT, "generalized_alpha_params.zm")
    for label, am, af in [("Chung-Hulbert rho_inf = 1/2", R(0), R(1, 3)),
                          ("HHT alpha = -1/4 (alpha_m = 0, alpha_f = 1/4)", R(0), R(1, 4)),
                          ("WBZ alpha_B = -1/10 (alpha_f = 0)", R(-1, 10), R(0))]:
        gamma = R(1, 2) - am + af
        beta = (1 - am + af) ** 2 / 4
        A = genalpha(am, af, beta, gamma)
        r, Ainf, ev = rho_inf(A)
        if af == 0:  # WBZ: rho_inf = (1 + alpha_B)/(1 - alpha_B) with alpha_B = alpha_m
            closed = (1 + am) / (1 - am)
        elif am == 0:
            closed = (1 - af) / (1 + af)
        else:
            closed = R(1, 2)
        chi, err = zcheck_chi(args.zcheck, four, {"alpha_m": am, "alpha_f": af, "beta": beta, "gamma": gamma})
        prop = proportional(chi, (z * sp.eye(3) - A).det())[0] if chi is not None else err
        rows.append(("generalized_alpha_params.zm", f"{label}: alpha_m = {am}, alpha_f = {af}, beta = {beta}, gamma = {gamma}",
                     r, closed, sp.simplify(r - closed) == 0, rho_numeric(A), ev, prop))

    print("| program | parameters | rho_inf (SymPy, exact) | closed form | equal | rho at Phi = 1e6 (numpy) | roots of lim chi (monic) | zcheck chi ∝ det(zI - A) |")
    print("|---|---|---|---|---|---|---|---|")
    for f, p, r, c, eq, num, ev, prop in rows:
        evs = ", ".join(f"{sp.nsimplify(k)}" + (f" (x{m})" if m > 1 else "") for k, m in ev.items())
        print(f"| {f} | {p} | {r} | {c} | {eq} | {num:.9f} | {evs} | {prop} |")
        ok &= bool(eq) and prop is True and abs(num - float(r)) < 2e-3  # a triple root converges like Phi^(-2/3)
    print("\nall checks pass" if ok else "\nSOME CHECK FAILED")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
