#!/usr/bin/env python3
"""Issue 35's speed target for ``zcheck order``, measured in one run (a
timing script, not a test; BENCHMARKS.md records its output).

NodePy 1.1.1's RK catalogue (``loadRKM('All')``: 51 keys, 50 distinct
methods; the same tableaux as crates/zcheck/tests/data/nodepy/rk, each file
naming its key on its first line). The same job on both sides:

- NodePy: ``m.order()``, ``m.stage_order()``,
  ``m.absolute_monotonicity_radius()`` and ``m.is_algebraically_stable()``
  on each method object (floats, tolerances);
- zcheck, in process: ``m.order()`` on a ``zcheck.Method`` made before the
  clock from the same entries as exact text, as NodePy's object is made
  before its clock (exact: the classical order by rooted trees, the stage
  order, the SSP coefficient as an algebraic number, algebraic stability by
  an exact PSD test, and the rest of the report, parsed from JSON); and
  ``Method.from_tableau(A, b).order()``, making the method inside the clock;
- zcheck as a process: ``zcheck order FILE --format json``, one per method,
  and one process over all 50 files (start, read, report, JSON).

Every figure is the best of N (default 5), nothing cached between calls.
Ratios are NodePy ÷ zcheck. Targets: at least 100x in total and at least 20x
as the median per method. SDIRK34's entry cos(pi/18) has no exact text, so
in process it is read from the exported file's decimals.

Usage: python bench/order_vs_nodepy.py [--repeat N] [--zcheck PATH]
(needs nodepy, sympy, six, numpy, and the release binary:
``cargo build --release --bin zcheck``)
"""

import argparse
import contextlib
import io
import os
import re
import statistics
import subprocess
import sys
import time
import warnings

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
RK_DIR = os.path.join(ROOT, "crates", "zcheck", "tests", "data", "nodepy", "rk")


def catalogue():
    from nodepy import runge_kutta_method as rk

    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        d = rk.loadRKM("All")
    return {k: m for k, m in d.items() if k.isascii() or k.replace("ö", "o") not in d}


def files_by_key():
    """NodePy's key of each exported file, read from its first line."""
    out = {}
    for name in sorted(os.listdir(RK_DIR)):
        if name.endswith(".toml"):
            path = os.path.join(RK_DIR, name)
            with open(path, encoding="utf-8") as f:
                key = re.search(r"loadRKM\('All'\)\['([^']+)'\]", f.readline()).group(1)
            out[key] = path
    return out


def best(f, repeat):
    ts = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t)
    return min(ts)


def nodepy_job(m):
    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        m.order()
        m.stage_order()
        m.absolute_monotonicity_radius()
        m.is_algebraically_stable()


def exact_entries(m):
    """NodePy's entries as the exact text ``zcheck`` reads (outside the
    clock); ``None`` when an entry has no exact form."""
    import zcheck

    try:
        return ([[zcheck._entry(x, "A") for x in row] for row in m.A],
                [zcheck._entry(x, "b") for x in m.b])
    except zcheck.Error:
        return None


def zcheck_job(exe, paths):
    subprocess.run([exe, "order", *paths, "--format", "json"], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--zcheck", default=os.path.join(ROOT, "target", "release", "zcheck"))
    args = ap.parse_args()

    import numpy
    import sympy
    from importlib.metadata import version

    methods = catalogue()
    files = files_by_key()
    missing = sorted(set(methods) - set(files))
    assert not missing, f"no exported file for {missing}"
    keys = sorted(methods, key=str.lower)

    import zcheck

    rows = []
    for k in keys:
        n = best(lambda: nodepy_job(methods[k]), args.repeat)
        entries = exact_entries(methods[k])
        if entries is None:
            made = zcheck.Method.from_file(files[k])
            make = lambda: zcheck.Method.from_file(files[k])
        else:
            made = zcheck.Method.from_tableau(*entries)
            make = lambda: zcheck.Method.from_tableau(*entries)
        z = best(lambda: made.order(), args.repeat)
        zm = best(lambda: make().order(), args.repeat)
        zp = best(lambda: zcheck_job(args.zcheck, [files[k]]), args.repeat)
        rows.append((k, n, z, zm, zp))
    whole = best(lambda: zcheck_job(args.zcheck, [files[k] for k in keys]), args.repeat)

    def summary(label, col, total=None):
        ratios = [r[1] / r[col] for r in rows]
        n_total = sum(r[1] for r in rows)
        z_total = total if total is not None else sum(r[col] for r in rows)
        if total is not None:
            print(f"| {label} | {z_total * 1e3:.1f} ms | {n_total / z_total:.0f}× | – | – | – |")
            return
        print(f"| {label} | {z_total * 1e3:.1f} ms | {n_total / z_total:.0f}× | "
              f"{statistics.median(r[col] for r in rows) * 1e3:.3f} ms | "
              f"{statistics.median(ratios):.0f}× | {min(ratios):.1f}× – {max(ratios):.0f}× |")

    print(f"NodePy {version('nodepy')}, SymPy {sympy.__version__}, NumPy {numpy.__version__}, "
          f"Python {sys.version.split()[0]}; {len(rows)} methods; best of {args.repeat} each")
    print()
    print("| method | NodePy (ms) | `m.order()` (ms) | ratio | made in the clock (ms) | "
          "one process (ms) |")
    print("|---|---:|---:|---:|---:|---:|")
    for k, n, z, zm, zp in rows:
        print(f"| {k} | {n * 1e3:.2f} | {z * 1e3:.3f} | {n / z:.0f}× | {zm * 1e3:.3f} | "
              f"{zp * 1e3:.2f} |")
    print()
    print(f"NodePy: {sum(r[1] for r in rows) * 1e3:.0f} ms in total, "
          f"{statistics.median(r[1] for r in rows) * 1e3:.2f} ms median per method")
    print()
    print("| zcheck | total | total ratio | median | median ratio | ratio range |")
    print("|---|---:|---:|---:|---:|---|")
    summary("`m.order()`, method made before the clock", 2)
    summary("`Method.from_tableau(A, b).order()`", 3)
    summary("`zcheck order FILE`, one process per method", 4)
    summary(f"`zcheck order` on all {len(rows)} files, one process", 4, whole)
    print()
    print("slowest for NodePy: " + ", ".join(
        f"{r[0]} {r[1] * 1e3:.0f} ms (zcheck {r[2] * 1e3:.2f} ms)"
        for r in sorted(rows, key=lambda r: -r[1])[:5]))
    print("slowest for zcheck: " + ", ".join(
        f"{r[0]} {r[2] * 1e3:.2f} ms (NodePy {r[1] * 1e3:.0f} ms)"
        for r in sorted(rows, key=lambda r: -r[2])[:5]))


if __name__ == "__main__":
    main()
