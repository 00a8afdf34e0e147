#!/usr/bin/env python3
"""Time NodePy against `zcheck region` on the same catalogue, in one run.

Mode `region` (default; issue 24's speed target):
  NodePy: for every catalogue method, real_stability_interval() +
  imaginary_stability_interval() + order() (RK: explicit methods through the
  methods of ExplicitRungeKuttaMethod; implicit methods, which NodePy gives no
  such methods, through nodepy.stability_function on rkm.stability_function();
  LMM: order() and, as NodePy has no intervals for LMMs, A_alpha_stability()).
  zcheck: `ZCHECK region FILE... --format json`, all files in one process,
  repeated --repeat times; per-method time = wall time / number of files.

Mode `stability-function` (issue 26's target): NodePy's
  rkm.stability_function() alone over the RK catalogue.

Prints a markdown table. zcheck's path: --zcheck, else $ZCHECK, else
target/release/zcheck (relative to the repository root). When zcheck has no
`region` command (or fails), its column says so and NodePy is still timed.

Usage:
  python region_vs_nodepy.py [--mode region|stability-function] [--zcheck PATH]
                             [--repeat N] [--set rk|lmm|all] [--per-method]
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
import warnings

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import exact  # noqa: E402

REPO = os.path.normpath(os.path.join(exact.CRATE, "..", ".."))


def nodepy_region(m, kind):
    import nodepy.stability_function as sf

    if kind == "lmm":
        return (m.order(), m.A_alpha_stability())
    if hasattr(m, "real_stability_interval"):
        return (m.real_stability_interval(), m.imaginary_stability_interval(), m.order())
    p, q = m.stability_function()
    out = []
    for f in (sf.real_stability_interval, sf.imaginary_stability_interval):
        try:
            out.append(f(p, q))
        except Exception as e:  # NodePy's real_stability_interval fails on A-stable methods
            out.append(repr(e))
    out.append(m.order())
    return tuple(out)


def time_call(f, repeat):
    ts = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t)
    return ts


def catalogue(which):
    items = []
    if which in ("rk", "all"):
        for stem, (key, m) in sorted(exact.rk_catalogue().items()):
            items.append(("rk", stem, m, os.path.join(exact.DATA, "rk", stem + ".toml")))
    if which in ("lmm", "all"):
        for stem, (label, m) in sorted(exact.lmm_catalogue().items()):
            items.append(("lmm", stem, m, os.path.join(exact.DATA, "lmm", stem + ".toml")))
    return items


def run_zcheck(zcheck, files, repeat, subcommand):
    """Wall time of one process over all files, best and median of `repeat`;
    (None, reason) when it does not run."""
    if not os.path.exists(zcheck):
        return None, f"no binary at {zcheck}"
    cmd = [zcheck] + subcommand + files + ["--format", "json"]
    walls = []
    for _ in range(repeat):
        t = time.perf_counter()
        try:
            r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        except subprocess.TimeoutExpired:
            return None, "timed out after 600 s"
        walls.append(time.perf_counter() - t)
        if r.returncode != 0:
            msg = (r.stderr or r.stdout).strip().splitlines()
            return None, f"exit {r.returncode}: {msg[0] if msg else ''}"[:200]
    try:
        parsed = json.loads(r.stdout)
    except ValueError:
        parsed = None
    return {"best": min(walls), "median": statistics.median(walls), "json": parsed}, None


def fmt_ms(s):
    return "—" if s is None else f"{1e3 * s:.3f}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mode", choices=["region", "stability-function"], default="region")
    ap.add_argument("--zcheck", default=os.environ.get("ZCHECK", os.path.join(REPO, "target", "release", "zcheck")))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--set", choices=["rk", "lmm", "all"], default=None)
    ap.add_argument("--per-method", action="store_true", help="one table row per method")
    args = ap.parse_args()
    which = args.set or ("all" if args.mode == "region" else "rk")
    if args.mode == "stability-function" and which != "rk":
        sys.exit("stability-function mode is for the RK catalogue only")
    warnings.simplefilter("ignore")
    items = catalogue(which)
    v = exact.versions()
    print(f"# {args.mode}: NodePy {v['nodepy']}, SymPy {v['sympy']}, NumPy {v['numpy']}, Python {v['python']}; "
          f"{len(items)} methods; {args.repeat} repeats (mean of repeats per method)\n")

    per = []
    import io
    import contextlib

    for kind, stem, m, path in items:
        if args.mode == "region":
            f = lambda: nodepy_region(m, kind)  # noqa: E731
        else:
            f = lambda: m.stability_function()  # noqa: E731
        with contextlib.redirect_stdout(io.StringIO()):  # NodePy prints round-off warnings
            ts = time_call(f, args.repeat)
        per.append((kind, stem, statistics.mean(ts)))
    total_nodepy = sum(t for _, _, t in per)

    sub = ["region"]  # zcheck has no other scalar command; issue 26's target is timed in-process by the binding
    n = len(items)
    groups = [("rk", "RK"), ("lmm", "LMM")] if which == "all" else [(which, which.upper())]
    if args.per_method:
        print("| kind | method | NodePy (ms) |")
        print("|---|---|---:|")
        for kind, stem, t in per:
            print(f"| {kind} | {stem} | {fmt_ms(t)} |")
        print()
    print("| set | methods | NodePy total (ms) | NodePy mean/method (ms) | zcheck total (ms) | zcheck mean/method (ms) | ratio NodePy/zcheck |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    notes = []
    rows = groups + ([("all", "all")] if len(groups) > 1 else [])
    for kind, label in rows:
        sel = [(k, st, p) for (k, st, _, p), (_, _, t) in zip(items, per) if kind in ("all", k)]
        ts = [t for k, _, t in per if kind in ("all", k)]
        files = [p for _, _, p in sel]
        z, why = run_zcheck(args.zcheck, files, args.repeat, sub)
        tn = sum(ts)
        if z is None:
            print(f"| {label} | {len(ts)} | {fmt_ms(tn)} | {fmt_ms(tn / len(ts))} | n/a | n/a | n/a |")
            notes.append(f"zcheck on {label}: {why}")
        else:
            zt = z["median"]
            print(f"| {label} | {len(ts)} | {fmt_ms(tn)} | {fmt_ms(tn / len(ts))} | {fmt_ms(zt)} | "
                  f"{fmt_ms(zt / len(ts))} | {tn / zt:.1f}× |")
            notes.append(f"zcheck on {label}: one process `{os.path.basename(args.zcheck)} {' '.join(sub)} "
                         f"<{len(files)} files> --format json`, median of {args.repeat} (best {fmt_ms(z['best'])} ms), "
                         "process start included")
    print()
    for line in notes:
        print("- " + line)
    if which in ("lmm", "all") and args.mode == "region":
        print("- NodePy LMM: order() + A_alpha_stability() only (NodePy has no LMM stability intervals)")
    if args.mode == "stability-function":
        print("- NodePy column: rkm.stability_function() alone (mode='exact').")


if __name__ == "__main__":
    main()
