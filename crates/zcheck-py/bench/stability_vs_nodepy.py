#!/usr/bin/env python3
"""Issue 35's per-method stability figure, measured in one process (a timing
script, not a test; BENCHMARKS.md records its output).

For ten common methods of NodePy 1.1.1's catalogue, side by side:

- NodePy: ``m.stability_function()`` on its own method object, after one
  call (NodePy's first call on a method costs about twice its later ones);
- zcheck: ``zcheck.Method.from_nodepy(m).stability()``, the whole job from
  NodePy's object: its SymPy entries written as exact text, the method
  made (program, derivation) and the full ``zcheck stability`` document
  read back as a dict. Nothing is cached between calls (``api::stability``
  empties the render cache; every call makes a new method).

Each figure is the best of ``--repeat`` runs; the ratio is NodePy's over
zcheck's, and the median of the ten ratios is the issue's target (>= 10x).

Usage: python bench/stability_vs_nodepy.py [--repeat N]   (needs nodepy, sympy)
"""

import argparse
import contextlib
import io
import statistics
import warnings

from order_vs_nodepy import best  # the same best-of-N timer, one definition

METHODS = ["RK44", "SSP33", "SSP104", "Mid22", "Heun33", "BS5", "DP5", "CK5", "Merson43", "Fehlberg45"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()

    from nodepy import runge_kutta_method as rk

    import zcheck

    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        catalogue = rk.loadRKM("All")
    rows = []
    for key in METHODS:
        m = catalogue[key]
        with contextlib.redirect_stdout(io.StringIO()):
            m.stability_function()
            t_nodepy = best(m.stability_function, args.repeat)
        zcheck.Method.from_nodepy(m).stability()
        t_zcheck = best(lambda: zcheck.Method.from_nodepy(m).stability(), args.repeat)
        t_make = best(lambda: zcheck.Method.from_nodepy(m), args.repeat)
        rows.append((key, t_nodepy, t_zcheck, t_make))
    print("| method | NodePy `stability_function()` | zcheck `from_nodepy(m).stability()` | of which making the method | ratio |")
    print("|---|---:|---:|---:|---:|")
    for key, n, z, mk in rows:
        print(f"| {key} | {n * 1e3:.2f} ms | {z * 1e3:.2f} ms | {mk * 1e3:.2f} ms | {n / z:.1f}x |")
    ratios = [n / z for _, n, z, _ in rows]
    print(f"\nmedian ratio {statistics.median(ratios):.1f}x (target >= 10x); "
          f"min {min(ratios):.1f}x, max {max(ratios):.1f}x")


if __name__ == "__main__":
    main()
