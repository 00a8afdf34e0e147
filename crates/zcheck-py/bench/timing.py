#!/usr/bin/env python3
"""Issue 26's speed targets, measured in one process (a timing script, not a
test; BENCHMARKS.md records its output).

1. ``Method.from_tableau(A, b).stability()`` over NodePy's RK catalogue
   (NodePy 1.1.1's ``loadRKM('All')``: 50 distinct methods; the same tableaux
   as crates/zcheck/tests/data/nodepy/rk) against NodePy's
   ``rkm.stability_function()`` alone on the same method objects. Target:
   zcheck at least 50 times faster. zcheck's tableaux are NodePy's entries
   (``Method.from_nodepy`` writes them as exact text; SDIRK34's
   cos(pi/18) cannot be, so its exported decimals are read from its file);
   the text is prepared before timing, so both columns time the engine.
2. ``import zcheck`` in a fresh interpreter, best of N (``python -X
   importtime`` gives the breakdown). Target: under 50 ms.

Usage: python bench/timing.py [--repeat N]   (needs nodepy, sympy, six, numpy)
"""

import argparse
import contextlib
import io
import os
import statistics
import subprocess
import sys
import time
import warnings

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests"))
from conftest import RK_DIR  # noqa: E402


def catalogue():
    from nodepy import runge_kutta_method as rk

    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        d = rk.loadRKM("All")
    return {k: m for k, m in d.items() if k.isascii() or k.replace("ö", "o") not in d}


def tableau_text(key, m):
    """The tableau as exact text, prepared outside the timed region."""
    import zcheck
    from zcheck import _entries, _entry

    try:
        A = [[_entry(x, "A") for x in row] for row in m.A]
        b = [_entry(x, "b") for x in m.b]
        return A, b, None
    except zcheck.Error:
        return None, None, os.path.join(RK_DIR, _entries.identifier(key) + ".toml")


def best_and_median(f, repeat):
    ts = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t)
    return min(ts), statistics.median(ts)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()

    import sympy

    import zcheck

    methods = catalogue()
    prepared = {k: tableau_text(k, m) for k, m in methods.items()}

    def run_nodepy():
        with contextlib.redirect_stdout(io.StringIO()):
            for m in methods.values():
                m.stability_function()

    def run_zcheck():
        for A, b, path in prepared.values():
            m = zcheck.Method.from_tableau(A, b) if path is None else zcheck.Method.from_file(path)
            m.stability()

    zb, zm = best_and_median(run_zcheck, args.repeat)
    nb, nm = best_and_median(run_nodepy, args.repeat)
    n = len(methods)
    from importlib.metadata import version

    print(f"NodePy {version('nodepy')}, SymPy {sympy.__version__}, "
          f"Python {sys.version.split()[0]}; {n} methods; best / median of {args.repeat}")
    print()
    print("| job | total best (ms) | total median (ms) | per method, median (ms) |")
    print("|---|---:|---:|---:|")
    print(f"| NodePy `rkm.stability_function()` | {nb * 1e3:.1f} | {nm * 1e3:.1f} | {nm * 1e3 / n:.2f} |")
    print(f"| zcheck `Method.from_tableau(A, b).stability()` | {zb * 1e3:.1f} | {zm * 1e3:.1f} | {zm * 1e3 / n:.3f} |")
    print(f"\nratio (medians): {nm / zm:.0f}x (target: at least 50x)")

    code = "import time; t = time.perf_counter(); import zcheck; print(time.perf_counter() - t)"
    ts = [float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout)
          for _ in range(10)]
    print(f"import zcheck: best {min(ts) * 1e3:.1f} ms, median {statistics.median(ts) * 1e3:.1f} ms "
          "of 10 fresh interpreters (target: under 50 ms)")


if __name__ == "__main__":
    main()
