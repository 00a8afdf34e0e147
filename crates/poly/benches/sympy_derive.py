#!/usr/bin/env python3
"""Side-by-side timing of `poly::derive` (criterion) and SymPy doing the same
jobs on RK4 spring chains, in one run, reported as ratios.

    pip install sympy            # once; the tests never need it
    python3 crates/poly/benches/sympy_derive.py [--masses 6 8 16] [--timeout 120]

For each chain (benches/fixtures/rk4_chain_N.zm, written by
benches/common/programs.rs) the script

1. runs `cargo bench -p poly --bench derive -- chain/rk4_N/` (warm-up 1 s,
   measurement 3 s, as TEAM.md asks) and reads criterion's mean for
   `derive_both_routes`, `z_route` and `state_route`;
2. in SymPy, executes the step symbolically (exact rationals) for
   - the state route: P, then `P.charpoly(z)` (Berkowitz, SymPy's default),
   - the z route: the same forward substitution in the z domain (a start
     value carries w = 1/z), the state-sized matrix R(w, Phi), then
     `R.det(method="berkowitz")` and z^N det R(1/z);
   and checks that both agree;
3. prints one row per chain: zcheck's time, SymPy's time per route and for
   both, and SymPy / zcheck. A SymPy job beyond --timeout is reported as a
   lower bound (">").

The machine is shared: report the load average printed at the start and end
next to the figures.
"""

import argparse
import json
import multiprocessing as mp
import os
import re
import subprocess
import sys
import time
from fractions import Fraction
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent.parent


def parse_zm(text):
    """(state names, [(target, rhs)]) of a generated .zm program."""
    state, lines = None, []
    for raw in text.splitlines():
        line = raw.split("#", 1)[0].strip()
        if not line or line.startswith("method"):
            continue
        if line.startswith("state"):
            state = line.split()[1:]
            continue
        target, rhs = (s.strip() for s in line.split("=", 1))
        lines.append((target, rhs))
    return state, lines


def sympy_expr(rhs, env):
    import sympy

    # Decimals are exact in .zm: 0.5 is 1/2.
    rhs = re.sub(r"\d+\.\d+", lambda m: f"Rational('{Fraction(m.group(0))}')", rhs)
    rhs = rhs.replace("^", "**")
    return sympy.sympify(rhs, locals=dict(env, Rational=sympy.Rational))


def state_route(text):
    import sympy

    state, lines = parse_zm(text)
    phi, z = sympy.symbols("Phi z")
    start = sympy.symbols(" ".join(f"s_{v}" for v in state))
    env = {"Phi": phi, **dict(zip(state, start))}
    for target, rhs in lines:
        env[target] = sympy.expand(sympy_expr(rhs, env))
    p = sympy.Matrix(
        [[sympy.expand(env[v]).coeff(s) for s in start] for v in state]
    )
    return sympy.expand(p.charpoly(z).as_expr())


def z_route(text):
    import sympy

    state, lines = parse_zm(text)
    phi, z, w = sympy.symbols("Phi z w")
    unknown = sympy.symbols(" ".join(f"u_{v}" for v in state))
    final = {}
    for k, (target, _) in enumerate(lines):
        if target in state:
            final[target] = k
    # A start value is w times the state's unknown; a state's final
    # assignment is its unknown (read as such by later lines).
    env = {"Phi": phi, **{v: w * u for v, u in zip(state, unknown)}}
    rows = {}
    for k, (target, rhs) in enumerate(lines):
        value = sympy.expand(sympy_expr(rhs, env))
        if target in state and final[target] == k:
            i = state.index(target)
            rows[i] = [
                (1 if j == i else 0) - value.coeff(u) for j, u in enumerate(unknown)
            ]
            env[target] = unknown[i]
        else:
            env[target] = value
    n = len(state)
    r = sympy.Matrix([rows[i] for i in range(n)])
    det = sympy.expand(r.det(method="berkowitz"))
    return sympy.expand(z**n * det.subs(w, 1 / z))


def timed(job, text, queue):
    t = time.perf_counter()
    result = job(text)
    queue.put((time.perf_counter() - t, str(result)))


def run_with_timeout(job, text, timeout):
    """(seconds, result) or (None, None) beyond the timeout."""
    queue = mp.Queue()
    proc = mp.Process(target=timed, args=(job, text, queue))
    proc.start()
    proc.join(timeout)
    if proc.is_alive():
        proc.terminate()
        proc.join()
        return None, None
    return queue.get()


def criterion_mean(n, name):
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    path = target / "criterion" / "chain" / f"rk4_{n}_{name}" / "new" / "estimates.json"
    with open(path) as f:
        return json.load(f)["mean"]["point_estimate"] / 1e9


def fmt(seconds):
    if seconds is None:
        return "–"
    if seconds < 1e-3:
        return f"{seconds * 1e6:.0f} µs"
    if seconds < 1:
        return f"{seconds * 1e3:.1f} ms"
    return f"{seconds:.1f} s"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--masses", type=int, nargs="+", default=[6, 8, 16])
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("--skip-cargo", action="store_true", help="reuse criterion's last figures")
    args = ap.parse_args()
    print(f"load average at start: {os.getloadavg()}", flush=True)
    if not args.skip_cargo:
        filt = "|".join(f"chain/rk4_{n}/" for n in args.masses)
        subprocess.run(
            ["cargo", "bench", "-p", "poly", "--bench", "derive", "--", filt,
             "--warm-up-time", "1", "--measurement-time", "3"],
            cwd=ROOT, check=True, stdout=sys.stderr,
        )
    print("| masses | states | zcheck both routes | SymPy state route | SymPy z route | SymPy both | ratio | SymPy state route alone ÷ zcheck both |")
    print("|---|---|---|---|---|---|---|---|")
    for n in args.masses:
        text = (HERE / "fixtures" / f"rk4_chain_{n}.zm").read_text()
        ours = criterion_mean(n, "derive_both_routes")
        ts, a = run_with_timeout(state_route, text, args.timeout)
        tz, b = run_with_timeout(z_route, text, args.timeout)
        if a is not None and b is not None and a != b:
            import sympy

            if sympy.expand(sympy.sympify(a) - sympy.sympify(b)) != 0:
                sys.exit(f"SymPy's routes disagree on {n} masses")
        both = None if ts is None or tz is None else ts + tz
        if both is None:
            lower = (ts or args.timeout) + (tz or args.timeout)
            ratio = f"> {lower / ours:.0f}×"
            both_s = f"> {fmt(lower)}"
        else:
            ratio = f"{both / ours:.0f}×"
            both_s = fmt(both)
        ts_s = fmt(ts) if ts is not None else f"> {fmt(args.timeout)}"
        tz_s = fmt(tz) if tz is not None else f"> {fmt(args.timeout)}"
        alone = f"{ts / ours:.0f}×" if ts is not None else f"> {args.timeout / ours:.0f}×"
        print(f"| {n} | {2 * n} | {fmt(ours)} | {ts_s} | {tz_s} | {both_s} | {ratio} | {alone} |", flush=True)
    print(f"load average at end: {os.getloadavg()}")


if __name__ == "__main__":
    main()
