"""Parity with NodePy on `m.order()` (issue 35) over its whole RK catalogue
(``loadRKM('All')``): the classical order (NodePy's ``order()``), the stage
order (``stage_order()``) and the SSP coefficient
(``absolute_monotonicity_radius()``).

zcheck decides each exactly on the numbers it is given; NodePy uses
tolerances and, for eleven methods, binary floats. The documented
differences:

- Floats stored (the INEXACT files, NodePy's own floats read as their
  shortest decimals: PD8, CMR6, Tsit5, SSP22star, SSP53, SSP54, SSP63, SSP75,
  SSP85, SSP95): the exact order of those decimals is 0 or 1 (their b does
  not sum to 1 exactly), and zcheck gives ``order_within_tolerance`` beside
  it (1e-12 by default for long decimals), which is NodePy's order at the
  same tolerance. Tsit5 is order 5 within 1e-12 and 4 within NodePy's
  default 1e-14, but its largest fifth-order residual lies in
  (1e-14, 1.1e-14]: NodePy's float sums decide 1e-14 by their rounding,
  which differs between hosts (4 with AVX-512, 5 with AVX2 only), so only
  1e-12 is compared with NodePy there.
- SDIRK34 holds cos(pi/18), which zcheck's entries cannot write: its file has
  17-digit decimals, compared within 1e-12 the same way.
- The stage order is exact only: on the INEXACT files it is not compared.
- NodePy's SSP coefficient is a bisection (to about 1e-10 by default) where
  zcheck's is an exact algebraic number: they agree to 1e-6 (SSP104: NodePy
  5.99999949, exactly 6); where NodePy
  finds no bound (an implicit method absolutely monotonic for every r) it
  returns its search cap, and zcheck +inf.
"""

import contextlib
import io
import math
import os

import pytest

import zcheck
from conftest import RK_DIR, inexact, rk_stems, same_document

TOL = 1e-12


def quiet(f, *args, **kw):
    with contextlib.redirect_stdout(io.StringIO()):
        return f(*args, **kw)


@pytest.fixture(scope="module")
def orders():
    return {s: zcheck.Method.from_file(os.path.join(RK_DIR, s + ".toml")).order() for s in rk_stems()}


@pytest.mark.parametrize("stem", rk_stems())
def test_classical_order(stem, orders, nodepy_rk):
    ours = orders[stem]
    m = nodepy_rk[stem]
    if inexact(stem):
        within = ours["order_within_tolerance"]
        assert within is not None, stem
        assert within["tolerance"]["value"] == TOL
        theirs = int(quiet(m.order, tol=TOL))
        assert within["order"] == theirs, (stem, within, theirs)
        return
    theirs = int(quiet(m.order))
    assert ours["order"] == theirs, (stem, ours["order"], theirs)
    assert ours["order_within_tolerance"] is None, stem
    # The trees of the next order: one fails at least, with its exact residual.
    assert ours["failed_conditions"], stem


def test_tsit5_at_two_tolerances(nodepy_rk):
    path = os.path.join(RK_DIR, "Tsit5.toml")
    m = zcheck.Method.from_file(path)
    assert m.order()["order"] == 0
    # The largest fifth-order residual, exactly, lies in (1e-14, 1.1e-14]:
    # within NodePy's rounding of 1e-14, so that tolerance is not compared.
    within = lambda t: m.order(tolerance=t)["order_within_tolerance"]["order"]
    assert (within("1e-14"), within("1.1e-14")) == (4, 5)
    assert m.order()["order_within_tolerance"]["order"] == 5 == quiet(nodepy_rk["Tsit5"].order, tol=1e-12)


@pytest.mark.parametrize("stem", rk_stems())
def test_stage_order(stem, orders, nodepy_rk):
    if inexact(stem):
        pytest.skip("exact stage order of float-derived decimals (documented above)")
    theirs = int(quiet(nodepy_rk[stem].stage_order))
    assert orders[stem]["stage_order"] == theirs, (stem, orders[stem]["stage_order"], theirs)


@pytest.mark.parametrize("stem", rk_stems())
def test_ssp_coefficient(stem, orders, nodepy_rk):
    ours = orders[stem]["ssp_coefficient"]
    assert ours is not None, (stem, orders[stem]["notes"])
    theirs = float(quiet(nodepy_rk[stem].absolute_monotonicity_radius))
    if ours["exact"] == "inf":
        assert ours["value"] is None
        assert theirs >= 100, (stem, theirs)  # NodePy's search cap
        return
    assert math.isclose(ours["value"], theirs, rel_tol=1e-6, abs_tol=1e-9), (stem, ours, theirs)


@pytest.mark.parametrize("stem", rk_stems())
def test_from_nodepy_gives_the_files_order(stem, orders, nodepy_rk):
    m = nodepy_rk[stem]
    if stem == "SDIRK34":
        pytest.skip("cos(pi/18): no exact entry (test_nodepy_parity)")
    ours = zcheck.Method.from_nodepy(m).order()
    if inexact(stem):
        # NodePy's floats against the exporter's decimals of them (equal to
        # about 1e-15: SSP22star's b sums to 1 exactly in one, not the other).
        key = "order_within_tolerance"
        assert ours[key]["order"] == orders[stem][key]["order"], stem
    else:
        assert ours["order"] == orders[stem]["order"], stem
    # A NodePy pair brings its embedded weights.
    if hasattr(m, "bhat"):
        assert ours["kind"] == "embedded_pair", stem
        if not inexact(stem) and all(not isinstance(x, float) for x in m.bhat):
            theirs = int(quiet(m.embedded_method.order))
            assert ours["embedded_order"] == theirs, (stem, ours["embedded_order"], theirs)


def test_order_document_shape():
    m = zcheck.Method.from_tableau(
        [[0, 0, 0, 0], [1, 0, 0, 0], [0, "1/2", 0, 0], [0, 0, "1/3", 0]], ["5/24", "7/24", "1/4", "1/4"]
    )
    o = m.order()
    assert (o["order"], o["linear_order"], o["kind"]) == (2, 4, "runge_kutta")
    (failed,) = o["failed_conditions"]
    assert (failed["tree"], failed["residual"]["exact"]) == ("[[][]]", "7/144")
    assert failed["residual"]["exact"].to_sympy() * 144 == 7
    assert m.region()["order"] == 2 and m.region()["linear_order"] == 4
    euler = zcheck.Method.builtin("standard_euler").order(modified=2)
    assert [t["coefficient"]["exact"] for t in euler["modified_equation"]] == ["-1/2", "1/3", "1/12"]
    assert zcheck.Method.builtin("verlet").order()["kind"] == "splitting"
    with pytest.raises(zcheck.Error, match="no nonlinear reading"):
        zcheck.Method.from_zm("method m\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n").order()
    with pytest.raises(zcheck.Error, match="--modified 11"):
        zcheck.Method.builtin("rk4").order(modified=11)
    with pytest.raises(zcheck.Error, match="bhat has 1 entries"):
        zcheck.Method.from_tableau([[0, 0], [1, 0]], ["1/2", "1/2"], bhat=[1])


def test_order_documents_tag_what_the_general_reader_tags(tmp_path):
    # m.order() reads its JSON with a hook that looks at numbers only; the
    # general one, which every other document uses, scans every key. On
    # every kind of method, with a modified equation and a tolerance, they
    # give the same document, with Exact in the same places.
    def exacts(x):
        if isinstance(x, dict):
            return sum(exacts(v) for v in x.values())
        if isinstance(x, list):
            return sum(map(exacts, x))
        return isinstance(x, zcheck.Exact)

    prk = tmp_path / "prk.toml"
    prk.write_text('[q]\nA = [[0, 0], ["1/2", "1/2"]]\nb = ["1/2", "1/2"]\n'
                   '[p]\nA = [["1/2", 0], ["1/2", 0]]\nb = ["1/2", "1/2"]\n')
    methods = [zcheck.Method.from_file(os.path.join(RK_DIR, s + ".toml")) for s in rk_stems()]
    methods += [zcheck.Method.builtin("verlet"), zcheck.Method.from_file(prk),
                zcheck.Method.from_multistep([-1, 1], ["-1/2", "3/2"])]
    tagged = 0
    for m in methods:
        for kw in ({}, {"modified": 3, "tolerance": "1e-10"}):
            try:
                text = m._native.order(kw.get("modified"), kw.get("tolerance"))
            except zcheck.Error:
                continue  # --modified is for RK kinds only
            general = zcheck._parse(text)
            fast = zcheck._parse(text, hook=zcheck._tag_number)
            assert same_document(general, fast), m.name
            tagged += exacts(fast)
    assert tagged > 1000


def test_a_splitting_from_a_file(tmp_path):
    # Strang's splitting is Stormer-Verlet: order 2, symplectic, and on the
    # oscillator the paper's Verlet (the same chi, Phi_max = 2).
    path = tmp_path / "strang.toml"
    path.write_text('drift = ["1/2", "1/2"]\nkick = [1, 0]\n')
    m = zcheck.Method.from_file(path)
    o = m.order()
    assert (o["kind"], o["order"], o["symplectic"]) == ("splitting", 2, True)
    assert m.charpoly == zcheck.Method.builtin("verlet").charpoly
    assert m.stability()["phi_max_exact"] == "2"
