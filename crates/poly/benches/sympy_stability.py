#!/usr/bin/env python3
"""The same job as benches/stability.rs, in SymPy, for the ratios in BENCHMARKS.md.

Setup (not part of the tests):  python3 -m venv /tmp/sympy-venv &&
/tmp/sympy-venv/bin/pip install sympy
Run:  /tmp/sympy-venv/bin/python crates/poly/benches/sympy_stability.py

For each method, chi(z; Phi) is the charpoly printed by `zcheck derive`
(passed here as text, so both sides start from the same polynomial). SymPy
does the core of the analysis: the resultant of chi and its reciprocal
z^n chi(1/z), chi(1), chi(-1), the leading and constant coefficients and the
discriminant in z, each factored over Q, and the positive real roots of every
factor isolated exactly (real_roots). It does not classify the intervals, so
the ratio understates zcheck's lead. Times are the best of 3 runs.
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


def job(chi):
    p = sp.Poly(chi, z)
    n = p.degree()
    rev = sp.Poly(sp.expand(z**n * chi.subs(z, 1 / z)), z)
    conds = [p.LC(), p.coeffs()[-1], chi.subs(z, 1), chi.subs(z, -1),
             sp.resultant(p, rev, z), sp.discriminant(p, z)]
    roots = []
    for c in conds:
        c = sp.expand(c)
        if c.free_symbols:
            for f, _ in sp.factor_list(c)[1]:
                roots += [r for r in sp.Poly(f, Phi).real_roots() if r > 0]
    return roots


def main():
    for name in METHODS:
        chi = charpoly(name)
        best = float("inf")
        for _ in range(3):
            t = time.perf_counter()
            job(chi)
            best = min(best, time.perf_counter() - t)
        print(f"{name:10s} sympy {best * 1e3:10.2f} ms", flush=True)


if __name__ == "__main__":
    sys.exit(main())
