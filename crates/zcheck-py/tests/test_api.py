"""The Python API: the same documents as the command line, exact values
through SymPy and back, and errors on bad input."""

import json
import math
import os
import subprocess
import threading
import time
from fractions import Fraction

import pytest
import sympy

import zcheck
from conftest import REPO, RK_DIR, same_document

GL2 = (
    [["1/4", "1/4 - sqrt(3)/6"], ["1/4 + sqrt(3)/6", "1/4"]],
    ["1/2", "1/2"],
)


def zcheck_cli(*args):
    """The command line's JSON, when a built binary is at hand."""
    exe = os.environ.get("ZCHECK") or os.path.join(REPO, "target", "release", "zcheck")
    if not os.path.exists(exe):
        pytest.skip(f"no zcheck binary at {exe} (set ZCHECK)")
    out = subprocess.run([exe, *args, "--format", "json"], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


# -- the same documents as the command line ---------------------------------


def test_stability_and_region_are_the_clis_documents():
    path = os.path.join(RK_DIR, "RK44.toml")
    m = zcheck.Method.from_file(path)
    s, r = m.stability(), m.region()
    assert s["phi_max_exact"] == "2*sqrt(2)" and s["phi_max"] == pytest.approx(2 * math.sqrt(2))
    assert r["order"] == 4 and r["real_limit"]["value"] == pytest.approx(2.785293563405282)
    cli_s, cli_r = zcheck_cli("stability", path), zcheck_cli("region", path)
    assert set(s) == set(cli_s) and set(r) == set(cli_r)
    # The name shown differs (the CLI shows the file's method name too).
    assert json.dumps(s, sort_keys=True) == json.dumps(cli_s, sort_keys=True)
    assert json.dumps(r, sort_keys=True) == json.dumps(cli_r, sort_keys=True)


def test_builtins_zm_text_and_parameters():
    m = zcheck.Method.builtin("false_euler_damped")
    assert m.params == ["D"]
    s = m.stability(D=Fraction(1, 10))
    assert s["params"] == {"D": "1/10"}
    assert s == m.stability(D="1/10") == m.stability(D=0.1)
    text = "method mine\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n"
    mine = zcheck.Method.from_zm(text)
    assert mine.charpoly == "z^2 - 2*z + Phi^2*z + 1"
    assert mine.transition_matrix == [["1", "-Phi"], ["Phi", "1 - Phi^2"]]
    assert mine.stability()["phi_max_exact"] == "2"


def test_multistep():
    bdf2 = zcheck.Method.from_multistep([Fraction(1, 3), Fraction(-4, 3), 1], [0, 0, Fraction(2, 3)], name="bdf2")
    r = bdf2.region()
    assert r["a_stable"] and r["l_stable"] and r["order"] == 2


def test_verify_is_checks_witnesses():
    v = zcheck.Method.builtin("false_euler").verify(Fraction(1, 2), steps=1000)
    assert v["agree"] and v["class"] == "harmonic" and v["phi"] == 0.5


def test_design_known_optima_and_the_clis_document():
    # Kinnmark-Gray: |R(iy)|^2 = 1 + (1/4 - 2 a3) y^4 + a3^2 y^6, best
    # imaginary limit 2 at a3 = 1/4 (issue 37).
    kg = zcheck.Method.from_zm("method kg\nparam a3\nstate y\ny = y + w*y + 1/2*w^2*y + a3*w^3*y\n")
    d = zcheck.design(kg, maximize="imag_limit", a3=(0, "1/2"))
    assert d["optimum"]["exact"] == "2" and d["attained"]
    assert d["at"]["a3"]["exact"] == "1/4"
    assert d["grid_check"]["points"] >= 200 and d["grid_check"]["max"]["value"] <= d["optimum"]["value"]
    assert d["optimum"]["exact"].to_sympy() == 2
    # Newmark with gamma bound to 1/2: Phi_max = 2/sqrt(1 - 4 beta), so
    # 2 sqrt(5) at beta = 1/5; the same document as the command line's.
    path = os.path.join(REPO, "crates", "zcheck", "methods", "newmark.zm")
    newmark = zcheck.Method.from_file(path)
    d = zcheck.design(newmark, maximize="phi_max", beta=(0, Fraction(1, 5)), gamma="1/2")
    assert d["optimum"]["exact"] == "2*sqrt(5)" and d["at"]["beta"]["exact"] == "1/5"
    assert sympy.simplify(d["optimum"]["exact"].to_sympy() - 2 * sympy.sqrt(5)) == 0
    cli = zcheck_cli("design", path, "--maximize", "phi_max", "--param", "beta=0..1/5", "--param", "gamma=1/2")
    assert json.dumps(d, sort_keys=True) == json.dumps(cli, sort_keys=True)
    # Both free: Hughes' 1/sqrt(gamma/2 - beta) is largest at (1/5, 1/2),
    # found through the disk bound and checked by the engine there.
    d = zcheck.design(newmark, maximize="phi_max", beta=(0, "1/5"), gamma=("1/2", "3/5"))
    assert d["optimum"]["exact"] == "2*sqrt(5)" and d["attained"]
    assert (d["at"]["beta"]["exact"], d["at"]["gamma"]["exact"]) == ("1/5", "1/2")
    assert d["grid_check"]["points"] == 2500
    with pytest.raises(zcheck.Error, match="unknown objective"):
        zcheck.design(kg, maximize="speed", a3=(0, 1))
    with pytest.raises(zcheck.Error, match="the range is empty"):
        zcheck.design(kg, maximize="imag_limit", a3=(1, 0))


def test_map_gives_numpy_arrays():
    np = pytest.importorskip("numpy")
    m = zcheck.Method.builtin("false_euler_damped")
    d = zcheck.map(m, phi=(0, 3), D=(0, 2), grid=6)
    g = d["grid"]
    assert g["Phi"].shape == g["D"].shape == g["class"].shape == (6, 6)
    assert np.all(np.diff(g["Phi"], axis=1) > 0) and np.all(np.diff(g["D"], axis=0) > 0)
    assert g["witnesses_agree"].all()
    # Phi_max = 2(sqrt(1 + D^2) - D): inside it, the class is stable.
    lim = 2 * (np.sqrt(1 + g["D"] ** 2) - g["D"])
    stable = ~np.isin(g["class"], ["unstable_oscillation", "monotonic_unstable", "alternating_unstable"])
    assert np.array_equal(stable, g["Phi"] < lim)


def test_paper_and_advise():
    claims = zcheck.paper()
    assert len(claims) == 137 and {"id", "statement", "verdict"} <= set(claims[0])
    scene = "tick_hz = 60\nduration_s = 1\n[[mode]]\nhz = 120\n"
    a = zcheck.advise(scene)
    assert a["recommended"] is not None
    path = os.path.join(REPO, "crates", "zcheck", "scenes", "spring_120hz.toml")
    if os.path.exists(path):
        assert zcheck.advise(path)["recommended"]["substeps"] > 0


def test_long_calls_release_the_gil():
    # A thread ticks while the engine works; it could not if the GIL were held.
    ticks, stop = [], threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    t = threading.Thread(target=tick)
    t.start()
    try:
        zcheck.Method.builtin("ab8").stability()
        zcheck.paper()
    finally:
        stop.set()
        t.join()
    assert len(ticks) > 5


# -- exact values through SymPy and back ------------------------------------


def test_sympy_round_trip_of_a_tableau():
    s3 = sympy.sqrt(3)
    A = [[sympy.Rational(1, 4), sympy.Rational(1, 4) - s3 / 6], [sympy.Rational(1, 4) + s3 / 6, sympy.Rational(1, 4)]]
    b = [sympy.Rational(1, 2)] * 2
    from_sympy = zcheck.Method.from_tableau(A, b)
    from_text = zcheck.Method.from_tableau(*GL2)
    assert from_sympy.region()["charpoly"] == from_text.region()["charpoly"]
    # R(w) = 1 + w b^T (I - wA)^-1 1, by SymPy, against the engine's chi = Q z - P.
    w, z = sympy.symbols("w z")
    M = sympy.Matrix(A)
    R = 1 + w * (sympy.Matrix([b]) * (sympy.eye(2) - w * M).inv() * sympy.ones(2, 1))[0]
    chi = zcheck.to_sympy(from_sympy.region()["charpoly"])
    assert sympy.simplify(chi.subs(z, R)) == 0


def test_sympy_rationals_take_the_short_path_to_the_same_text():
    # The entry reader writes SymPy integers and rationals as p/q itself; the
    # general SymPy writer is its oracle.
    from zcheck import _entry
    from zcheck._entries import sympy_entry

    values = [sympy.Integer(0), sympy.Integer(1), sympy.Integer(-7), sympy.Rational(1, 2), sympy.Rational(-3, 8),
              sympy.Rational(19372, 6561), sympy.Rational(-(10**40) - 1, 3**30), sympy.Integer(10**50)]
    for x in values:
        assert _entry(x, "x") == sympy_entry(x, "x"), x
    # Not rationals: the general writer, as before.
    assert _entry(sympy.sqrt(3) / 6, "x") == sympy_entry(sympy.sqrt(3) / 6, "x")
    assert _entry(sympy.Float("0.25"), "x") == sympy_entry(sympy.Float("0.25"), "x")


def test_entry_lists_take_the_fast_path_to_the_same_text():
    # _texts converts by a class lookup where it can; _entry is its oracle,
    # and an entry off the fast path is still named in its error.
    import numpy

    from zcheck import _entry, _texts

    values = [0, 7, -3, "1/3", "sqrt(2)/4", sympy.Integer(5), sympy.Rational(-7, 9), sympy.S.Half,
              sympy.S.One, sympy.S.Zero, sympy.S.NegativeOne, Fraction(3, 8), 0.1, sympy.sqrt(3) / 6, 10**40,
              2.5, -0.0, 1e-05, 1e20, 5e-324, numpy.float64(1 / 3), numpy.float64(1e-07), numpy.float64(0.5)]
    # Twice: float's subclasses join the fast path on first sight.
    for _ in range(2):
        assert _texts(values, lambda i: f"v[{i}]") == [_entry(x, "v") for x in values]
    with pytest.raises(zcheck.Error, match=r"^bhat\[2\]: nan"):
        zcheck.Method.from_tableau([[0, 0], [1, 0]], [0.5, 0.5], bhat=[numpy.float64(1), numpy.float64("nan")])
    with pytest.raises(zcheck.Error, match=r"A\[2\]\[1\]: True: expected a number, not a bool"):
        zcheck.Method.from_tableau([[0, 0], [True, 0]], [0, 1])
    with pytest.raises(zcheck.Error, match=r"b\[2\]: nan"):
        zcheck.Method.from_tableau([[0, 0], [1, 0]], [0.5, float("nan")])


def test_the_stability_objects_are_the_parsed_text():
    # stability() gets its dict built in Rust, its exact strings tagged by
    # one set of known keys. Its oracle is the JSON text parsed with the
    # general hook, which scans every key: alike down to the types (int,
    # float, str, Exact), on every built-in and catalogue method.
    names = sorted(f[:-3] for f in os.listdir(os.path.join(REPO, "crates", "poly", "methods")) if f.endswith(".zm"))
    methods = [zcheck.Method.builtin(n) for n in names]
    methods += [zcheck.Method.from_file(os.path.join(RK_DIR, f)) for f in sorted(os.listdir(RK_DIR))]
    checked = 0
    for m in methods:
        params = {p: "1/10" for p in m.params}
        try:
            text = m._native.stability(zcheck._params(params))
        except zcheck.Error:
            continue
        assert same_document(zcheck._parse(text), m.stability(**params)), m.name
        checked += 1
    assert checked > 80


def test_exact_values_to_sympy():
    s = zcheck.Method.builtin("semi_false_heun").stability()
    e = s["phi_max_exact"]
    assert isinstance(e, zcheck.Exact) and e == "sqrt(2*sqrt(5) - 2)"
    assert sympy.simplify(e.to_sympy() - sympy.sqrt(2 * sympy.sqrt(5) - 2)) == 0
    assert float(e.to_sympy()) == pytest.approx(s["phi_max"], rel=1e-15)
    # A number without a closed form: the root of its polynomial in its interval.
    r = zcheck.Method.from_file(os.path.join(RK_DIR, "RK44.toml")).region()["real_limit"]
    assert r["exact"].startswith("root of ")
    root = zcheck.to_sympy(r["exact"])
    assert root.has(sympy.CRootOf)
    assert float(root) == pytest.approx(r["value"], rel=1e-15)
    assert zcheck.to_sympy("1/4 - sqrt(3)/6") == sympy.Rational(1, 4) - sympy.sqrt(3) / 6
    assert zcheck.to_sympy("0.1") == sympy.Rational(1, 10)


def test_floats_are_their_shortest_decimals():
    a = zcheck.Method.from_tableau([[0, 0], [0.1, 0]], [0.5, 0.5])
    b = zcheck.Method.from_tableau([[0, 0], [Fraction(1, 10), 0]], [Fraction(1, 2)] * 2)
    assert a.region()["charpoly"] == b.region()["charpoly"]
    tiny = zcheck.Method.from_tableau([[0, 0], [1e-5, 0]], [0.5, 0.5])
    assert tiny.charpoly == zcheck.Method.from_tableau([[0, 0], ["1/100000", 0]], ["1/2", "1/2"]).charpoly


# -- errors on bad input ----------------------------------------------------


def test_error_is_a_value_error():
    assert issubclass(zcheck.Error, ValueError)


def test_ragged_a():
    with pytest.raises(zcheck.Error, match=r"row 2 of A has 1 entries: expected 2"):
        zcheck.Method.from_tableau([[0, 0], [1]], [1, 0])


def test_non_numeric_entry_names_its_index():
    with pytest.raises(zcheck.Error, match=r"^A\[2\]\[1\]: unexpected name `x`"):
        zcheck.Method.from_tableau([[0, 0], ["x", 0]], [1, 0])
    with pytest.raises(zcheck.Error, match=r"^b\[2\]"):
        zcheck.Method.from_tableau([[0, 0], [1, 0]], [1, "half"])
    with pytest.raises(zcheck.Error, match=r"^A\[1\]\[2\]: \[1\]: expected an int"):
        zcheck.Method.from_tableau([[0, [1]], [1, 0]], [1, 0])


def test_a_parameter_the_method_lacks():
    with pytest.raises(zcheck.Error, match=r"method tableau has no parameter D \(declared: none\)"):
        zcheck.Method.from_tableau(*GL2).stability(D=1)
    with pytest.raises(zcheck.Error, match=r"has no parameter E \(declared: D\)"):
        zcheck.Method.builtin("false_euler_damped").region(E=1)


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf")])
def test_nan_and_infinite_floats(bad):
    with pytest.raises(zcheck.Error, match=r"^A\[2\]\[1\]: .*expected a finite number"):
        zcheck.Method.from_tableau([[0, 0], [bad, 0]], [0.5, 0.5])
    with pytest.raises(zcheck.Error, match=r"expected a finite number"):
        zcheck.Method.builtin("false_euler_damped").stability(D=bad)
    with pytest.raises(zcheck.Error, match=r"^A\[2\]\[1\]"):
        zcheck.Method.from_tableau([[0, 0], [sympy.Float(bad), 0]], [0.5, 0.5])


def test_a_scene_path_that_does_not_exist():
    with pytest.raises(zcheck.Error, match=r"no-such-scene\.toml:0:0: cannot read the scene file"):
        zcheck.advise("/no-such-scene.toml")


def test_located_messages_as_the_cli():
    with pytest.raises(zcheck.Error, match=r"^mine\.zm:3:5: nonlinear term"):
        zcheck.Method.from_zm("method m\nstate v y\nv = v*y\n", name="mine.zm")
    with pytest.raises(zcheck.Error, match=r"^<scene>:\d+:\d+: "):
        zcheck.advise("tick_hz = -1\n")


def test_no_panic_reaches_the_interpreter():
    from zcheck import _native

    with pytest.raises(zcheck.Error, match="internal error"):
        _native._panic_for_test()
    # The interpreter and the engine carry on.
    assert zcheck.Method.builtin("verlet").stability()["phi_max_exact"] == "2"


def _without_timings(doc):
    """The document without the measured ns (the rest is deterministic)."""
    if isinstance(doc, dict):
        return {k: _without_timings(v) for k, v in doc.items() if not k.startswith("ns_per")}
    if isinstance(doc, list):
        return [_without_timings(v) for v in doc]
    return doc


def test_advise_with_a_solver_is_the_cli_document():
    path = os.path.join(REPO, "crates", "zcheck", "scenes", "quarter_car.toml")
    one = zcheck.advise(path, solver="xpbd", substeps=4, iterations=2)
    assert (one["solver"], one["substeps"], one["iterations"]) == ("xpbd", 4, 2)
    assert one["cost"] == 4 * 2 * one["constraints"]
    cli = zcheck_cli(
        "advise", "--scene", path, "--solver", "xpbd", "--substeps", "4", "--iterations", "2"
    )
    assert _without_timings(one) == _without_timings(cli)
    search = zcheck.advise(path, solver="soft_step")
    assert "candidates" in search and "recommended" in search
    table = zcheck.advise(path, solvers=["paper", "xpbd"])
    assert [r["family"] for r in table["families"]][0] == table["recommended"]["family"]
    with pytest.raises(zcheck.Error, match="substeps= and iterations= go together"):
        zcheck.advise(path, solver="xpbd", substeps=4)
    with pytest.raises(zcheck.Error, match="--solver nope: unknown solver"):
        zcheck.advise(path, solver="nope")
