"""The type stubs name every public function with the keywords it takes,
so that an editor's completion and a type checker see the module as it is."""

import ast
import inspect
from pathlib import Path

import pendulum_theory as pt

STUBS = Path(__file__).parents[1] / "python" / "pendulum_theory" / "__init__.pyi"


def stubbed():
    tree = ast.parse(STUBS.read_text())
    functions = {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}
    others = {t.id for n in tree.body if isinstance(n, ast.AnnAssign)
              for t in [n.target]} | {n.name for n in tree.body if isinstance(n, ast.ClassDef)}
    return functions, others


def test_every_public_name_has_a_stub():
    functions, others = stubbed()
    missing = [n for n in pt.__all__ if n not in functions and n not in others]
    assert missing == []


def test_stubs_take_the_keywords_the_functions_take():
    functions, _ = stubbed()
    for name, node in functions.items():
        real = [p.name for p in inspect.signature(getattr(pt, name)).parameters.values()]
        args = node.args
        stub = [a.arg for a in args.posonlyargs + args.args + args.kwonlyargs]
        stub += [a.arg for a in (args.vararg, args.kwarg) if a is not None]
        assert stub == real, name
