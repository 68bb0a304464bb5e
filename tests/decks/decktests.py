#!/usr/bin/env python3
"""Finds and runs the deck tests. A deck test is a top-level function `test_NAME(ctx)` of a
module `test_*.py` in this folder; its CTest name is deck.NAME. Discovery is the only list:
CMake asks `--list` at configure time and adds one CTest per name, so a new test function is
registered by being written. Standard library only.

  decktests.py --list               every test name, one a line (fails on a test that could
                                    never run: see lint())
  decktests.py --check NAME...      fails unless NAME... (the names CMake registered) are
                                    exactly the tests discovered now
  decktests.py NAME --exe LIGGGHTS_TRI --work DIR [--vtkdump PATH] [--stats-columns PATH]
                    [--liggghts PATH] [--style-matrix PATH]
"""
import argparse
import ast
import glob
import importlib
import inspect
import os
import shutil
import sys
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import decklib  # noqa: E402

# The modules here that hold no tests. Any other .py must be a test module, test_*.py: a
# script in the old style (main() and its own CTest line) would otherwise never run.
HELPERS = ("decklib", "decktests", "style_decks")


def modules():
    return sorted(os.path.basename(p)[:-3] for p in glob.glob(os.path.join(HERE, "test_*.py")))


def lint():
    """Tests that discovery would miss, found in the source rather than by import: a .py that
    is neither a test module nor one of HELPERS; `def test_*` in a module that is not a test
    module, nested inside a function or class, defined twice in one module (the second silently
    replaces the first), or not taking exactly one argument."""
    problems = []
    for path in sorted(glob.glob(os.path.join(HERE, "*.py"))):
        module = os.path.basename(path)[:-3]
        if not module.startswith("test_") and module not in HELPERS:
            problems.append(f"{module}.py is neither a test module (test_*.py) nor a helper "
                            f"({', '.join(h + '.py' for h in HELPERS)}): its tests would never "
                            "run; make them test_* functions of a test_*.py")
        with open(path) as f:
            tree = ast.parse(f.read(), path)
        top = {id(n) for n in tree.body}
        seen = {}
        functions = (ast.FunctionDef, ast.AsyncFunctionDef)
        defs = [n for n in ast.walk(tree) if isinstance(n, functions)]
        for node in sorted(defs, key=lambda n: n.lineno):
            if not node.name.startswith("test_"):
                continue
            where = f"{os.path.basename(path)}:{node.lineno}: {node.name}"
            if not module.startswith("test_"):
                problems.append(f"{where} is in {module}.py, which is not a test module "
                                "(test_*.py)")
            elif id(node) not in top:
                problems.append(f"{where} is not at the top level of its module")
            elif node.name in seen:
                problems.append(f"{where} is defined again (first at line {seen[node.name]}): "
                                "the first one would never run")
            else:
                seen[node.name] = node.lineno
                args = node.args
                if len(args.args) != 1 or args.vararg or args.kwonlyargs:
                    problems.append(f"{where} must take exactly one argument, ctx")
    return problems


def discover():
    """{name: function} of every test_NAME of every test module."""
    tests = {}
    for module in modules():
        m = importlib.import_module(module)
        for attr, fn in vars(m).items():
            if attr.startswith("test_") and inspect.isfunction(fn) and fn.__module__ == module:
                name = attr[len("test_"):]
                if name in tests:
                    raise SystemExit(f"test {name} is defined in {tests[name].__module__}.py "
                                     f"and in {module}.py")
                tests[name] = fn
    return tests


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("test", nargs="?")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--check", nargs="*", metavar="NAME")
    ap.add_argument("--exe")
    ap.add_argument("--work")
    ap.add_argument("--vtkdump")
    ap.add_argument("--stats-columns", help="tri-stats-columns: the columns of compute tri/stats")
    ap.add_argument("--liggghts", help="LIGGGHTS's own executable")
    ap.add_argument("--style-matrix", help="tri-style-matrix: every LIGGGHTS style, classified")
    ctx = ap.parse_args()
    problems = lint()
    if problems:
        print("deck tests that would never run:\n  " + "\n  ".join(problems), file=sys.stderr)
        return 1
    tests = discover()
    if not tests:
        print(f"no test_* function in any test_*.py of {HERE}", file=sys.stderr)
        return 1
    if ctx.list:
        print("\n".join(sorted(tests)))
        return 0
    if ctx.check is not None:
        registered, found = set(ctx.check), set(tests)
        missing, stale = sorted(found - registered), sorted(registered - found)
        for name in missing:
            print(f"deck test {name} ({tests[name].__module__}.py) is not registered with "
                  "CTest: re-run cmake")
        for name in stale:
            print(f"CTest deck.{name} has no test_{name} any more: re-run cmake")
        if missing or stale:
            return 1
        print(f"PASS discovery: {len(found)} deck tests, all registered "
              f"({', '.join(sorted(found))})")
        return 0
    if ctx.test not in tests:
        ap.error(f"unknown test {ctx.test!r}; the tests are {', '.join(sorted(tests))}")
    if not ctx.exe or not ctx.work:
        ap.error("a test needs --exe and --work")
    decklib.configure(ctx.stats_columns)
    shutil.rmtree(ctx.work, ignore_errors=True)
    os.makedirs(ctx.work)
    try:
        tests[ctx.test](ctx)
        decklib.check(decklib.checks_made() > 0, "the test made no check")
    except decklib.Failure as e:
        print(f"FAIL {ctx.test}: {e}")
        return 1
    except Exception:
        traceback.print_exc()
        print(f"FAIL {ctx.test}: the checker itself failed (see the traceback above)")
        return 1
    print(f"PASS {ctx.test} ({decklib.checks_made()} checks)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
