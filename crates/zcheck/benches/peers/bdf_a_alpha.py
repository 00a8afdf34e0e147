#!/usr/bin/env python3
"""A(alpha) of BDF1-6 by a high-precision boundary locus, against Hairer &
Wanner, Solving ODEs II, Table V.2.3 (printed to two decimals).

The boundary locus is w(theta) = rho(e^{i theta}) / sigma(e^{i theta}) with
rho(z) = sum_j alpha_j z^j, sigma(z) = sum_j beta_j z^j (BDF: exact rationals,
from NodePy's backward_difference_formula(k), and equal to the exported
tests/data/nodepy/lmm/BDFk.toml). For BDF the unstable set is the bounded
region enclosed by the locus, so

    alpha = min over theta with Re w(theta) < 0 of |arg(-w(theta))|,

and 90 degrees when the locus never enters Re w < 0. The minimum is found by
a scan of 200000 points in (0, pi) (the locus is symmetric) followed by
mpmath.findroot on d/dtheta arg(-w(theta)) = 0 at 50 digits, from the best
scan point; the value is cross-checked against the scan's minimum and by
testing that points just inside the sector (angle alpha - 1e-9, at many radii)
are stable and a point just outside (on the ray through the tangency) is not.

Writes tests/data/nodepy/bdf_a_alpha.json.
"""

import json
import os
import sys

import mpmath
import numpy as np
import sympy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import exact  # noqa: E402

mpmath.mp.dps = 50
PRINTED = {1: "90", 2: "90", 3: "86.03", 4: "73.35", 5: "51.84", 6: "17.84"}


def bdf(k):
    from nodepy import linear_multistep_method as lm

    m = lm.backward_difference_formula(k)
    al = [sympy.Rational(sympy.sympify(a)) if not isinstance(a, float) else sympy.Rational(int(a)) for a in m.alpha]
    be = [sympy.Rational(sympy.sympify(b)) if not isinstance(b, float) else sympy.Rational(int(b)) for b in m.beta]
    return al, be


def locus(al, be):
    A = [mpmath.mpf(a.p) / a.q for a in al]
    B = [mpmath.mpf(b.p) / b.q for b in be]

    def w(th):
        zz = mpmath.expj(th)
        return mpmath.polyval(A[::-1], zz) / mpmath.polyval(B[::-1], zz)

    return w


def stable(al, be, w):
    cs = [complex(a) - w * complex(b) for a, b in zip(al, be)]
    return max(abs(np.roots(cs[::-1]))) <= 1 + 1e-12


def a_alpha(k):
    al, be = bdf(k)
    w = locus(al, be)
    th = np.linspace(1e-6, np.pi, 200001)
    A = np.array([float(a) for a in al])
    B = np.array([float(b) for b in be])
    zz = np.exp(1j * th)
    wn = np.polyval(A[::-1], zz) / np.polyval(B[::-1], zz)
    left = wn.real < 0
    if not left.any():
        return {"k": k, "alpha_deg": 90.0, "digits": "90", "theta": None, "w": None, "method": "locus never in Re w < 0"}
    ang = np.where(left, np.abs(np.angle(-wn)), np.inf)
    i = int(np.argmin(ang))
    scan_deg = float(np.degrees(ang[i]))

    def g(t):  # arg(-w(t)); its derivative vanishes at the tangency
        v = -w(t)
        return mpmath.atan2(v.imag, v.real)

    t0 = mpmath.findroot(lambda t: mpmath.diff(g, t), mpmath.mpf(th[i]))
    ang_rad = abs(g(t0))
    deg = ang_rad * 180 / mpmath.pi
    wt = w(t0)
    # checks: inside the sector just below alpha is stable; the tangent ray just above is not
    a = float(ang_rad)
    radii = np.concatenate([np.logspace(-4, 4, 400), [abs(complex(wt))]])
    inside = all(stable(al, be, -r * np.exp(1j * s * (a - 1e-9))) for r in radii for s in (1, -1))
    outside = not stable(al, be, complex(wt) * (1 - 1e-7) + 0j) or not stable(al, be, -abs(complex(wt)) * np.exp(1j * (a + 1e-6)))
    return {
        "k": k,
        "alpha_deg": float(deg),
        "digits": mpmath.nstr(deg, 30),
        "tan_alpha": mpmath.nstr(mpmath.tan(ang_rad), 30),
        "theta": mpmath.nstr(t0, 30),
        "w": [mpmath.nstr(wt.real, 30), mpmath.nstr(wt.imag, 30)],
        "scan_deg": scan_deg,
        "sector_inside_stable": bool(inside),
        "beyond_tangency_unstable": bool(outside),
        "method": "boundary locus, scan + mpmath.findroot of d/dtheta arg(-w) = 0 at 50 digits",
    }


def main():
    out = {
        "source": "Hairer & Wanner, Solving Ordinary Differential Equations II, 2nd ed., Table V.2.3 (printed, degrees)",
        "definition": "alpha = min over theta with Re w(theta) < 0 of |arg(-w(theta))|, w(theta) = rho(e^{i theta})/sigma(e^{i theta}); 90 when the locus stays in Re w >= 0",
        "generated_by": "crates/zcheck/benches/peers/bdf_a_alpha.py",
        "versions": exact.versions() | {"mpmath": mpmath.__version__},
        "bdf": {},
    }
    from nodepy import linear_multistep_method as lm

    for k in range(1, 7):
        r = a_alpha(k)
        r["printed_deg"] = PRINTED[k]
        r["nodepy_A_alpha_stability_floor_deg"] = int(lm.backward_difference_formula(k).A_alpha_stability())
        if k > 2:
            r["agrees_with_printed_to_2_decimals"] = f"{r['alpha_deg']:.2f}" == PRINTED[k]
        out["bdf"][f"BDF{k}"] = r
        print(f"BDF{k}: printed {PRINTED[k]:>6}  computed {r['digits']}  (scan {r.get('scan_deg')}, "
              f"sector stable {r.get('sector_inside_stable')}, beyond unstable {r.get('beyond_tangency_unstable')})")
    path = os.path.join(exact.DATA, "bdf_a_alpha.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
