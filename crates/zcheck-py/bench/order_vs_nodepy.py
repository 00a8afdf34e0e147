#!/usr/bin/env python3
"""Issue 35's speed target for ``zcheck order``, measured in one run (a
timing script, not a test; BENCHMARKS.md records its output).

NodePy 1.1.1's RK catalogue (``loadRKM('All')``: 51 keys, 50 distinct
methods; the same tableaux as crates/zcheck/tests/data/nodepy/rk, each file
naming its key on its first line). The same job on both sides:

- NodePy: ``m.order()``, ``m.stage_order()``,
  ``m.absolute_monotonicity_radius()`` and ``m.is_algebraically_stable()``
  on each method object (floats, tolerances);
- zcheck: ``zcheck order FILE --format json`` (exact: the classical order by
  rooted trees, the stage order, the SSP coefficient as an algebraic number,
  algebraic stability by an exact PSD test, and the rest of the report), as a
  process: one per method, and one process over all 50 files.

Every figure is the best of N (default 5); zcheck's process time includes
starting the process, reading the file and writing the JSON. Ratios are
NodePy ÷ zcheck. Targets: at least 100x in total (NodePy's sum over the
methods against the one ``zcheck order`` process) and at least 20x as the
median per method (NodePy against one process per method).

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

    rows = []
    for k in keys:
        n = best(lambda: nodepy_job(methods[k]), args.repeat)
        z = best(lambda: zcheck_job(args.zcheck, [files[k]]), args.repeat)
        rows.append((k, n, z, n / z))
    whole = best(lambda: zcheck_job(args.zcheck, [files[k] for k in keys]), args.repeat)

    n_total = sum(r[1] for r in rows)
    z_sum = sum(r[2] for r in rows)
    ratios = [r[3] for r in rows]
    print(f"NodePy {version('nodepy')}, SymPy {sympy.__version__}, NumPy {numpy.__version__}, "
          f"Python {sys.version.split()[0]}; {len(rows)} methods; best of {args.repeat} each")
    print()
    print("| method | NodePy (ms) | `zcheck order`, one process (ms) | ratio |")
    print("|---|---:|---:|---:|")
    for k, n, z, r in rows:
        print(f"| {k} | {n * 1e3:.1f} | {z * 1e3:.2f} | {r:.0f}× |")
    print()
    print(f"NodePy, all {len(rows)}: {n_total * 1e3:.0f} ms; one `zcheck order` process over all "
          f"{len(rows)} files: {whole * 1e3:.1f} ms; total ratio {n_total / whole:.0f}× "
          f"(target: at least 100×)")
    print(f"one process per method, summed: {z_sum * 1e3:.0f} ms ({n_total / z_sum:.0f}×)")
    print(f"per method: median ratio {statistics.median(ratios):.0f}× (target: at least 20×), "
          f"min {min(ratios):.1f}×, max {max(ratios):.0f}×")
    print("slowest for NodePy: " + ", ".join(
        f"{k} {n * 1e3:.0f} ms ({z * 1e3:.1f} ms, {r:.0f}×)"
        for k, n, z, r in sorted(rows, key=lambda r: -r[1])[:5]))
    print("slowest for zcheck: " + ", ".join(
        f"{k} {z * 1e3:.1f} ms (NodePy {n * 1e3:.0f} ms, {r:.0f}×)"
        for k, n, z, r in sorted(rows, key=lambda r: -r[2])[:5]))


if __name__ == "__main__":
    main()
