#!/usr/bin/env python3
"""Export NodePy's Runge-Kutta and linear multistep catalogues as zcheck
input files:

  crates/zcheck/tests/data/nodepy/rk/STEM.toml   Butcher tableaux (A, b, c)
  crates/zcheck/tests/data/nodepy/lmm/STEM.toml  alpha = [...], beta = [...]

Entries are exact where NodePy holds exact SymPy values (integers, rationals,
sqrt/cbrt of integers). Where NodePy holds only binary floats, the entry is
the shortest decimal string that reads back as the same float, and the file
says so in a comment. Every exact entry is checked by a SymPy round trip.

Usage: python export_catalogue.py [--check ZCHECK]
  --check ZCHECK: afterwards run `ZCHECK derive FILE` on each RK file.
"""

import argparse
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import exact  # noqa: E402


def fmt_list(items, indent):
    return "[" + (",\n" + " " * indent).join(items) + "]" if len(items) > 4 else "[" + ", ".join(items) + "]"


def q(s):
    return '"' + s + '"' if not (s.lstrip("-").isdigit()) else s


def export_rk(stem, key, m, outdir):
    s = len(m)
    notes = []
    inexact = []

    def conv(v, where):
        text, ok = exact.entry(v)
        if not ok:
            inexact.append(where)
        return q(text)

    A = [[conv(m.A[i, j], f"A[{i+1}][{j+1}]") for j in range(s)] for i in range(s)]
    b = [conv(m.b[i], f"b[{i+1}]") for i in range(s)]
    c = [conv(m.c[i], f"c[{i+1}]") for i in range(s)]
    kind = type(m).__name__
    if kind == "ExplicitRungeKuttaPair":
        notes.append("An embedded pair in NodePy: this is its main method (A, b); bhat is not exported.")
    lines = [
        f"# NodePy {exact.versions()['nodepy']}: runge_kutta_method.loadRKM('All')[{key!r}] ({kind}).",
        f"# {m.name}",
    ]
    for n in notes:
        lines.append("# " + n)
    symbolic = any(
        getattr(v, "is_Float", None) is False and not getattr(v, "is_Rational", True)
        for v in list(m.A.flat) + list(m.b)
        if hasattr(v, "free_symbols")
    )
    if inexact and symbolic and not any(getattr(v, "is_Float", False) for v in list(m.A.flat) + list(m.b)):
        lines.append(
            "# INEXACT: NodePy holds this method exactly in SymPy (e.g. A[1][1] = %s), but that number "
            "(a trigonometric/casus-irreducibilis value) has no form in zcheck's entry syntax; the entries %s "
            "are the shortest decimals that read back as its float64 value." % (m.A[0, 0], ", ".join(inexact))
        )
    elif inexact:
        if len(inexact) == 3 * s + s * s or len(inexact) > 12:
            lines.append(
                f"# INEXACT: NodePy holds this method in binary floats; {len(inexact)} entries are the shortest "
                "decimal strings that read back as NodePy's float64 values (not the published exact values)."
            )
        else:
            lines.append(
                "# INEXACT: NodePy holds these entries as binary floats, written as the shortest round-trip "
                "decimals: " + ", ".join(inexact)
            )
    rows = ",\n     ".join("[" + ", ".join(r) + "]" for r in A)
    lines.append(f"A = [{rows}]")
    lines.append(f"b = [{', '.join(b)}]")
    lines.append(f"c = [{', '.join(c)}]")
    path = os.path.join(outdir, stem + ".toml")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path, inexact


def export_lmm(stem, label, m, outdir):
    al, be = [], []
    inexact = []
    for j, v in enumerate(m.alpha):
        t, ok = exact.entry(v)
        al.append(q(t))
        if not ok:
            inexact.append(f"alpha[{j}]")
    for j, v in enumerate(m.beta):
        t, ok = exact.entry(v)
        be.append(q(t))
        if not ok:
            inexact.append(f"beta[{j}]")
    lines = [
        f"# NodePy {exact.versions()['nodepy']}: linear_multistep_method.{label}: {m.name}.",
        "# alpha[j], beta[j]: the coefficients of y_{n+j} and h f_{n+j}, j = 0..k, lowest j first",
        "# (NodePy's LinearMultistepMethod(alpha, beta)); k = %d steps, %s." % (len(m), "explicit" if m.is_explicit() else "implicit"),
    ]
    if inexact:
        lines.append("# INEXACT (NodePy floats, shortest round-trip decimals): " + ", ".join(inexact))
    lines.append(f"alpha = [{', '.join(al)}]")
    lines.append(f"beta = [{', '.join(be)}]")
    path = os.path.join(outdir, stem + ".toml")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path, inexact


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", metavar="ZCHECK", help="run `ZCHECK derive` on every RK file written")
    args = ap.parse_args()
    rkdir = os.path.join(exact.DATA, "rk")
    lmdir = os.path.join(exact.DATA, "lmm")
    os.makedirs(rkdir, exist_ok=True)
    os.makedirs(lmdir, exist_ok=True)

    rk = exact.rk_catalogue()
    written = []
    for stem, (key, m) in sorted(rk.items()):
        path, inexact = export_rk(stem, key, m, rkdir)
        written.append(path)
        print(f"rk  {stem:14s} s={len(m):2d} {'exact' if not inexact else 'INEXACT (%d float entries)' % len(inexact)}")
    lm = exact.lmm_catalogue()
    for stem, (label, m) in sorted(lm.items()):
        path, inexact = export_lmm(stem, label, m, lmdir)
        print(f"lmm {stem:14s} k={len(m):2d} {'exact' if not inexact else 'INEXACT'}")
    print(f"{len(rk)} RK methods in {rkdir}, {len(lm)} LMMs in {lmdir}")

    if args.check:
        bad = 0
        for path in written:
            r = subprocess.run([args.check, "derive", path], capture_output=True, text=True)
            if r.returncode != 0:
                bad += 1
                print(f"zcheck derive failed on {path}:\n{r.stderr}")
        print(f"zcheck derive: {len(written) - bad}/{len(written)} RK files accepted")
        sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
