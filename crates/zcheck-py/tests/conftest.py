"""Shared fixtures: NodePy's RK catalogue (live, from the installed NodePy),
its exported tableaux and the reference values NodePy 1.1.1 gave
(crates/zcheck/tests/data/nodepy, written by crates/zcheck/benches/peers)."""

import contextlib
import io
import json
import os
import warnings

import pytest

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
DATA = os.path.join(REPO, "crates", "zcheck", "tests", "data", "nodepy")
RK_DIR = os.path.join(DATA, "rk")


def rk_stems():
    return sorted(f[: -len(".toml")] for f in os.listdir(RK_DIR) if f.endswith(".toml"))


def same_document(x, y):
    """Two parsed documents alike down to the types: a str against an
    Exact differs (the tagging hooks are compared with it)."""
    if type(x) is not type(y):
        return False
    if isinstance(x, dict):
        return x.keys() == y.keys() and all(same_document(x[k], y[k]) for k in x)
    if isinstance(x, list):
        return len(x) == len(y) and all(map(same_document, x, y))
    return x == y


def inexact(stem):
    """The eleven files the exporter marked INEXACT (NodePy holds binary
    floats, or a value zcheck's entry syntax cannot write)."""
    with open(os.path.join(RK_DIR, stem + ".toml")) as f:
        return "INEXACT" in f.read()


@pytest.fixture(scope="session")
def reference():
    with open(os.path.join(DATA, "reference.json")) as f:
        return json.load(f)["rk"]


@pytest.fixture(scope="session")
def nodepy_rk():
    """{file stem: NodePy method}, as the exporter named them."""
    from nodepy import runge_kutta_method as rk

    from zcheck._entries import identifier

    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        d = rk.loadRKM("All")
    out = {}
    for key, m in d.items():
        if not key.isascii() and key.replace("ö", "o") in d:
            continue  # Söderlind43 is Soderlind43
        stem = "".join(c if (c.isascii() and (c.isalnum() or c == "_")) else "_" for c in key)
        out[stem if stem and not stem[0].isdigit() else identifier(key)] = m
    return out
