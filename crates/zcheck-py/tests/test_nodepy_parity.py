"""Parity with NodePy on its Runge-Kutta catalogue: the stability function
R = P/Q, the imaginary stability interval and the order.

NodePy is called live (the version pip installed); where NodePy 1.1.1 is
known to differ for its own reasons (crates/zcheck/benches/peers/README.md),
the reference values in crates/zcheck/tests/data/nodepy/reference.json
stand in: NodePy's order() is the B-series order, zcheck's region `order`
too (NSSP32: 2), beside its `linear_order` (NSSP32: 3); its imaginary interval of an implicit method is always 0, and three
float-derived explicit methods have noise for an interval (SSP53, SSP54,
PD8). The eleven INEXACT files (binary floats read as their decimals, or
SDIRK34's cos(pi/18)) are compared numerically.
"""

import contextlib
import io
import math
import os

import pytest
import sympy

import zcheck
from conftest import RK_DIR, inexact, rk_stems

W = sympy.Symbol("w")
Z = sympy.Symbol("z")
# Float-derived files whose exact imaginary interval is round-off's, not the
# method's: the decimals leave |R(iy)| > 1 on a sliver (0, ~1e-8) or break
# A-stability (SDIRK34), so the exact limit is 0 where NodePy's float search
# (or the reference's) finds the method's interval, or noise (SSP53, SSP54, PD8;
# crates/zcheck/benches/peers/README.md).
NOISY_IMAG = {"SSP53", "SSP54", "PD8", "SSP63", "SDIRK34"}


def p_q(region):
    """P(w), Q(w) of the stability function from the region's charpoly
    chi(z, w) = Q(w) z - P(w) (a Runge-Kutta method has one root)."""
    chi = sympy.Poly(zcheck.to_sympy(region["charpoly"]), Z)
    assert chi.degree() == 1, region["charpoly"]
    q, minus_p = chi.all_coeffs()
    return sympy.expand(-minus_p), sympy.expand(q)


def nodepy_p_q(m):
    with contextlib.redirect_stdout(io.StringIO()):
        p, q = m.stability_function()

    def poly(c):
        return sum(sympy.sympify(x) * W**k for k, x in enumerate(reversed(list(c.coeffs))))

    return poly(p), poly(q)


def close(a, b, tol):
    return abs(a - b) <= tol * (1 + abs(b))


@pytest.fixture(scope="module")
def regions():
    return {s: zcheck.Method.from_file(os.path.join(RK_DIR, s + ".toml")).region() for s in rk_stems()}


def test_the_catalogue_is_nodepys(nodepy_rk):
    assert sorted(nodepy_rk) == rk_stems()


@pytest.mark.parametrize("stem", rk_stems())
def test_stability_function(stem, regions, nodepy_rk):
    p, q = p_q(regions[stem])
    np_p, np_q = nodepy_p_q(nodepy_rk[stem])
    if not inexact(stem):
        assert sympy.simplify(sympy.expand(p * np_q - np_p * q)) == 0, (stem, p, q, np_p, np_q)
        return
    # Numerically, at points around the origin and out to |w| = 4.
    for w in [0.5, -1, -2.5, 1j, 3j, -1 + 1j, -3 + 2j, 4]:
        ours = complex(p.subs(W, w)) / complex(q.subs(W, w))
        theirs = complex(sympy.N(np_p.subs(W, w))) / complex(sympy.N(np_q.subs(W, w)))
        assert close(ours, theirs, 1e-9), (stem, w, ours, theirs)


@pytest.mark.parametrize("stem", rk_stems())
def test_imaginary_interval(stem, regions, nodepy_rk, reference):
    ours = regions[stem]["imag_limit"]  # None: the whole imaginary axis
    own = reference[stem]["own"]["imag_limit"]
    if stem in NOISY_IMAG:
        pytest.skip("round-off's interval, not the method's")
    # Against the reference (SymPy, 30 digits).
    if own is None or own.get("value") is None:
        assert ours is None, (stem, ours)
    else:
        assert ours is not None and close(ours["value"], own["value"], 1e-12), (stem, ours, own)
    m = nodepy_rk[stem]
    if not hasattr(m, "imaginary_stability_interval"):
        return  # NodePy gives implicit methods no interval (0 through stability_function)
    with contextlib.redirect_stdout(io.StringIO()):
        theirs = float(m.imaginary_stability_interval())
    assert ours is not None and close(ours["value"], theirs, 1e-6), (stem, ours, theirs)


@pytest.mark.parametrize("stem", rk_stems())
def test_order(stem, regions, reference):
    ref = reference[stem]
    linear = ref["own"]["linear_order"]
    nodepy = ref["nodepy"]["order"]
    r = regions[stem]
    # `linear_order` is the order on y' = lambda*y; `order` the classical
    # (B-series) order, NodePy's `order()`, on every exact file (the
    # float-derived ones: test_order_parity.py, within a tolerance).
    assert r["linear_order"] == linear, (stem, r["linear_order"], linear)
    if not inexact(stem):
        assert r["order"] == nodepy, (stem, r["order"], nodepy)


@pytest.mark.parametrize("stem", rk_stems())
def test_from_nodepy_reads_the_same_method(stem, regions, nodepy_rk):
    m = nodepy_rk[stem]
    if stem == "SDIRK34":
        # 1/2 + sqrt(3)*cos(pi/18)/3 has no exact form in zcheck's entries.
        with pytest.raises(zcheck.Error, match=r"A\[1\]\[1\]"):
            zcheck.Method.from_nodepy(m)
        return
    ours = p_q(zcheck.Method.from_nodepy(m).region())
    theirs = p_q(regions[stem])
    if not inexact(stem):
        assert sympy.expand(ours[0] * theirs[1] - ours[1] * theirs[0]) == 0, stem
        return
    # NodePy's floats against the exporter's decimals of them: equal to
    # about 1e-15 (the last digit of a shortest decimal may differ).
    for w in [0.5, -2.5, 3j, -3 + 2j]:
        a = complex(ours[0].subs(W, w)) / complex(ours[1].subs(W, w))
        b = complex(theirs[0].subs(W, w)) / complex(theirs[1].subs(W, w))
        assert close(a, b, 1e-12), (stem, w, a, b)


@pytest.mark.parametrize("stem", rk_stems())
def test_stability_over_phi_runs(stem):
    s = zcheck.Method.from_file(os.path.join(RK_DIR, stem + ".toml")).stability()
    assert s["stability"] in {
        "limited",
        "bounded_for_all_phi",
        "unbounded_for_all_phi",
        "unstable_near_zero",
    }, s["stability"]
    if s["phi_max"] is not None:
        assert math.isclose(s["phi_max"], s["phi_max_detail"]["value"])
