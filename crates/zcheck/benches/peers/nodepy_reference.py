#!/usr/bin/env python3
"""Write crates/zcheck/tests/data/nodepy/reference.json: what NodePy says
about every method of the exported catalogue (export_catalogue.py), beside an
independent computation of our own, each field labelled with its source.

Per RK method (keyed by file stem):
  nodepy.order                       rkm.order()  (B-series order, floats, tol 1e-14)
  nodepy.order_tol1e-10              rkm.order(tol=1e-10)
  nodepy.real_stability_interval     rkm.real_stability_interval() for explicit methods;
                                     NodePy has it only on ExplicitRungeKuttaMethod, so for
                                     implicit ones nodepy.stability_function.real_stability_interval(p, q)
                                     is called on rkm.stability_function() (errors recorded)
  nodepy.imaginary_stability_interval  likewise
  nodepy.stability_function          rkm.stability_function(): numerator / denominator
                                     coefficients, lowest power first, exact strings where
                                     NodePy's are exact, else floats
  own.*                              from the exported TOML file read exactly (the decimals
                                     of float methods as exact rationals, i.e. the method
                                     zcheck reads): P, Q exactly; the order p on y' = lambda y
                                     and the error constant C in e^w - R(w) = C w^(p+1) + ...;
                                     real and imaginary limits by lines.py (resultants +
                                     60-digit roots + a dense scan); rho_inf = |lim R(w)|.
Per LMM: nodepy.order (order(), tol 1e-10), nodepy.A_alpha_stability (integer degrees,
floor), nodepy.is_zero_stable; own.order and own.error_constant C_(p+1)/sigma(1), exact;
own real/imag limits by lines.py; own.rho_inf: the largest |root| of sigma (null when
beta_k = 0).

Usage: python nodepy_reference.py [--only STEM ...]
"""

import argparse
import json
import os
import sys
import time
import tomllib
import warnings

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mpmath  # noqa: E402
import numpy as np  # noqa: E402
import sympy  # noqa: E402

import exact  # noqa: E402
import lines  # noqa: E402

W = lines.W


def jnum(x):
    """A float for JSON (inf/nan as strings)."""
    if x is None:
        return None
    x = float(x)
    if np.isinf(x):
        return "inf"
    if np.isnan(x):
        return "nan"
    return x


def coeff_strings(poly1d):
    """np.poly1d coefficients, lowest power first: exact strings when exact."""
    out, ok = [], True
    for c in list(poly1d.coeffs)[::-1]:
        if isinstance(c, (float, np.floating)):
            if float(c).is_integer():
                out.append(str(int(c)))
            else:
                ok = False
                out.append(float(c))
            continue
        try:
            s = exact.to_entry(sympy.sympify(c))
            out.append(s)
        except exact.Inexact:
            try:
                e = sympy.nsimplify(sympy.sympify(c)) if False else sympy.sympify(c)
                if e.is_number and not e.has(sympy.Float):
                    out.append(str(e))
                else:
                    ok = False
                    out.append(float(e))
            except Exception:
                ok = False
                out.append(float(c))
    return out, ok


def limit_field(lim, info):
    return {
        "value": None if lim is None else float(lim),
        "digits": None if lim is None else mpmath.nstr(lim, 30),
        "breakpoints": info["breakpoints"],
        "resultant_identically_zero": info["resultant_identically_zero"],
        "scan_check": info["scan"],
    }


def read_toml(path):
    with open(path, "rb") as f:
        return tomllib.load(f)


def ex(v):
    return sympy.Integer(v) if isinstance(v, int) else exact.from_entry(v)


def rk_own(path):
    t = read_toml(path)
    A = sympy.Matrix([[ex(v) for v in row] for row in t["A"]])
    b = sympy.Matrix([ex(v) for v in t["b"]])
    s = A.shape[0]
    e = sympy.ones(s, 1)
    explicit = all(A[i, j] == 0 for i in range(s) for j in range(i, s))
    if explicit:
        P = sympy.Integer(1)
        v = e
        for j in range(1, s + 1):
            P += sympy.expand((b.T * v)[0]) * W**j
            v = (A * v).applyfunc(sympy.expand)
        Q = sympy.Integer(1)
    else:
        P = sympy.expand((sympy.eye(s) - W * A + W * e * b.T).det(method="berkowitz"))
        Q = sympy.expand((sympy.eye(s) - W * A).det(method="berkowitz"))
    P = sympy.expand(sympy.radsimp(P))
    Q = sympy.expand(sympy.radsimp(Q))
    Pp, Qp = sympy.Poly(P, W), sympy.Poly(Q, W)
    # series of e^w - P/Q
    N = 2 * max(Pp.degree(), Qp.degree()) + 4
    ser = sympy.series(sympy.exp(W) - P / Q, W, 0, N).removeO()
    sp = sympy.Poly(sympy.expand(ser), W)
    order, C = None, None
    for k in range(0, N):
        ck = sympy.nsimplify(sympy.simplify(sp.coeff_monomial(W**k))) if False else sympy.simplify(sp.coeff_monomial(W**k))
        if ck != 0:
            order, C = k - 1, ck
            break
    # order with a tolerance, for methods read from rounded decimals
    order_tol = None
    for k in range(0, N):
        ck = sp.coeff_monomial(W**k)
        if abs(float(ck)) > 1e-12 * (1.0 / float(sympy.factorial(k))):
            order_tol = k - 1
            break
    if Pp.degree() > Qp.degree():
        rho_inf = None
    elif Pp.degree() < Qp.degree():
        rho_inf = sympy.Integer(0)
    else:
        rho_inf = sympy.simplify(sympy.Abs(Pp.LC() / Qp.LC()))
    cs = [-P, Q]
    rl, ri = lines.ray_limit(cs, "real"), lines.ray_limit(cs, "imag")

    def strs(p):
        return [str(sympy.simplify(c)) for c in reversed(p.all_coeffs())]

    return {
        "source": "own: exact SymPy from the exported TOML (decimals read exactly), lines.py for the limits",
        "stability_numerator": strs(Pp),
        "stability_denominator": strs(Qp),
        "linear_order": order,
        "linear_order_tol_1e-12": order_tol,
        "error_constant": None if C is None else {"exact": str(C), "value": float(C)},
        "rho_inf": None if rho_inf is None else {"exact": str(rho_inf), "value": float(rho_inf)},
        "real_limit": limit_field(*rl),
        "imag_limit": limit_field(*ri),
    }


def rk_nodepy(m):
    import nodepy.stability_function as sf

    out = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        out["order"] = int(m.order())
        out["order_tol1e-10"] = int(m.order(tol=1e-10))
        p, q = m.stability_function()
        explicit = hasattr(m, "real_stability_interval")
        src = "rkm.%s()" if explicit else "nodepy.stability_function.%s(*rkm.stability_function())"
        for name in ("real_stability_interval", "imaginary_stability_interval"):
            try:
                v = getattr(m, name)() if explicit else getattr(sf, name)(p, q)
                out[name] = {"value": jnum(v), "source": src % name}
            except Exception as e:  # NodePy fails on some implicit methods
                out[name] = {"value": None, "error": f"{type(e).__name__}: {e}", "source": src % name}
        num, ok1 = coeff_strings(p)
        den, ok2 = coeff_strings(q)
        out["stability_function"] = {
            "numerator": num,
            "denominator": den,
            "exact": ok1 and ok2,
            "source": "rkm.stability_function() (mode='exact'), lowest power first",
        }
    return out


def lmm_own(path):
    t = read_toml(path)
    al = [ex(v) for v in t["alpha"]]
    be = [ex(v) for v in t["beta"]]
    k = len(al) - 1
    # C_q = (1/q!) sum_j (alpha_j j^q - q beta_j j^(q-1)), C_0 = sum alpha_j
    sigma1 = sum(be)
    order, C = None, None
    for q in range(0, 2 * k + 4):
        if q == 0:
            cq = sum(al)
        else:
            cq = sum(al[j] * sympy.Integer(j) ** q - q * be[j] * sympy.Integer(j) ** (q - 1) for j in range(k + 1)) / sympy.factorial(q)
        cq = sympy.nsimplify(cq) if False else sympy.simplify(cq)
        if cq != 0:
            order = q - 1
            C = sympy.simplify(cq / sigma1) if sigma1 != 0 else None
            break
    if be[k] == 0:
        rho_inf = None
    else:
        rts = lines.roots([mpmath.mpf(sympy.N(c, 70)) for c in reversed(be)])
        rho_inf = max(abs(r) for r in rts) if rts else mpmath.mpf(0)
    cs = [al[j] - W * be[j] for j in range(k + 1)]
    rl, ri = lines.ray_limit(cs, "real"), lines.ray_limit(cs, "imag")
    return {
        "source": "own: exact SymPy from the exported TOML; C = C_(p+1)/sigma(1); lines.py for the limits",
        "order": order,
        "error_constant": None if C is None else {"exact": str(C), "value": float(C)},
        "rho_inf": None if rho_inf is None else {"digits": mpmath.nstr(rho_inf, 30), "value": float(rho_inf),
                                                 "source": "max |root of sigma| (mpmath, 60 digits)"},
        "real_limit": limit_field(*rl),
        "imag_limit": limit_field(*ri),
    }


def lmm_nodepy(m):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return {
            "order": int(m.order()),
            "A_alpha_stability_deg_floor": int(m.A_alpha_stability()),
            "is_zero_stable": bool(m.is_zero_stable()),
            "note": "NodePy's LinearMultistepMethod has no real/imaginary stability interval; see own.*",
        }


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--only", nargs="*", help="only these stems (output not written)")
    args = ap.parse_args()
    rkdir, lmdir = os.path.join(exact.DATA, "rk"), os.path.join(exact.DATA, "lmm")
    out = {"versions": exact.versions(), "generated_by": "crates/zcheck/benches/peers/nodepy_reference.py",
           "rk": {}, "lmm": {}}
    t0 = time.time()
    for stem, (key, m) in sorted(exact.rk_catalogue().items()):
        if args.only and stem not in args.only:
            continue
        t = time.time()
        path = os.path.join(rkdir, stem + ".toml")
        rec = {"nodepy_key": key, "nodepy_class": type(m).__name__, "stages": len(m),
               "file_exact": "INEXACT" not in open(path).read()}
        rec["nodepy"] = rk_nodepy(m)
        rec["own"] = rk_own(path)
        out["rk"][stem] = rec
        print(f"rk  {stem:14s} {time.time() - t:6.2f}s  nodepy p={rec['nodepy']['order']} "
              f"real={rec['nodepy']['real_stability_interval']['value']} imag={rec['nodepy']['imaginary_stability_interval']['value']} | "
              f"own p={rec['own']['linear_order']} real={rec['own']['real_limit']['value']} imag={rec['own']['imag_limit']['value']}",
              flush=True)
    for stem, (label, m) in sorted(exact.lmm_catalogue().items()):
        if args.only and stem not in args.only:
            continue
        t = time.time()
        path = os.path.join(lmdir, stem + ".toml")
        rec = {"nodepy_constructor": label, "steps": len(m)}
        rec["nodepy"] = lmm_nodepy(m)
        rec["own"] = lmm_own(path)
        out["lmm"][stem] = rec
        print(f"lmm {stem:14s} {time.time() - t:6.2f}s  nodepy p={rec['nodepy']['order']} | own p={rec['own']['order']} "
              f"real={rec['own']['real_limit']['value']} imag={rec['own']['imag_limit']['value']}", flush=True)
    print(f"total {time.time() - t0:.1f}s")
    if not args.only:
        with open(os.path.join(exact.DATA, "reference.json"), "w") as f:
            json.dump(out, f, indent=1, sort_keys=True)
            f.write("\n")


if __name__ == "__main__":
    main()
