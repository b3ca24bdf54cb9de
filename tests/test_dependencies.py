"""A test may use only what the extras it runs under declare (README: the test command is
``pip install -e ".[test]"`` then pytest).  Every ``tests/*.py`` file, and every local module
they import (``benchmarks/...``, ``docs/...``), is parsed with :mod:`ast`; each module it
imports (at any depth: inside functions too) must be

* in the standard library (:data:`sys.stdlib_module_names`), ``aidl_lang``, or a local file;
* or installed by a distribution in the dependency closure of ``aidl-lang[test]`` *as declared
  in pyproject.toml* (the core dependencies and the ``test`` extra, its ``aidl-lang[...]``
  self-references expanded, then every requirement followed through the installed
  distributions' metadata, markers evaluated) -- not merely installed, since another extra
  (the ``step`` extra's VTK brought matplotlib) can mask a missing declaration;
* or guarded: the import comes after ``pytest.importorskip("NAME")`` in the same function
  (or at module level), or inside ``try: ... except ImportError`` (the test then skips
  cleanly, naming what it lacks).

Modules map to distributions through :func:`importlib.metadata.packages_distributions`."""
from __future__ import annotations

import ast
import re
import sys
import tomllib
from importlib import metadata as md
from pathlib import Path

from packaging.markers import default_environment
from packaging.requirements import Requirement

from conftest import ROOT

TESTS = ROOT / "tests"
SELF = "aidl-lang"


def _key(name: str) -> str:
    return re.sub(r"[-_.]+", "-", name).lower()


def declared_closure(extras: tuple[str, ...] = ("test",)) -> set[str]:
    """Normalised names of the distributions ``aidl-lang[EXTRAS]`` needs, as declared."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    optional = project["optional-dependencies"]
    todo = [Requirement(r) for r in project["dependencies"]]
    seen_extras: set[str] = set()
    stack = list(extras)
    while stack:                       # aidl-lang[x] inside an extra: its requirements too
        e = stack.pop()
        if e in seen_extras:
            continue
        seen_extras.add(e)
        for r in map(Requirement, optional[e]):
            if _key(r.name) == SELF:
                stack.extend(r.extras)
            else:
                todo.append(r)
    env = default_environment()
    closure: set[str] = set()
    missing: list[str] = []
    while todo:
        r = todo.pop()
        name = _key(r.name)
        if name in closure:
            continue
        closure.add(name)
        try:
            dist = md.distribution(r.name)
        except md.PackageNotFoundError:
            missing.append(r.name)
            continue
        for s in map(Requirement, dist.requires or []):
            if s.marker is None or any(s.marker.evaluate({**env, "extra": e})
                                       for e in ("", *r.extras)):
                todo.append(s)
    assert not missing, (f"declared but not installed: {sorted(missing)}; install the test "
                         "extra: pip install -e '.[test]'")
    return closure


def _guards(tree: ast.AST) -> dict[int, list[tuple[int, str]]]:
    """For each scope (by id of its function or module node): (line, module) of the
    ``pytest.importorskip("module")`` calls in it."""
    out: dict[int, list[tuple[int, str]]] = {}

    def visit(node, scope):
        for child in ast.iter_child_nodes(node):
            inner = child if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)) \
                else scope
            if (isinstance(child, ast.Call) and isinstance(child.func, ast.Attribute)
                    and child.func.attr == "importorskip" and child.args
                    and isinstance(child.args[0], ast.Constant)):
                out.setdefault(id(scope), []).append(
                    (child.lineno, str(child.args[0].value).split(".")[0]))
            visit(child, inner)
    visit(tree, tree)
    return out


def imports_of(path: Path) -> list[tuple[str, int, bool, bool]]:
    """(top-level module, line, guarded, at import time) of every absolute import in ``path``
    (at import time: not inside a function)."""
    text = path.read_text(encoding="utf-8")
    tree = ast.parse(text, str(path))
    guards = _guards(tree) if "importorskip" in text else {}
    out: list[tuple[str, int, bool, bool]] = []

    def names(node) -> list[str]:
        if isinstance(node, ast.Import):
            return [a.name for a in node.names]
        if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            return [node.module]
        return []

    def catches_import_error(t: ast.Try) -> bool:
        return any(h.type is not None and any(
            isinstance(n, ast.Name) and n.id in ("ImportError", "ModuleNotFoundError")
            for n in ast.walk(h.type)) for h in t.handlers)

    def visit(node, scopes, in_try):
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.expr):
                continue                   # an import is a statement: no need to look inside
            for name in names(child):
                top = name.split(".")[0]
                skipped = any(mod == top and line < child.lineno
                              for s in scopes for line, mod in guards.get(id(s), []))
                out.append((top, child.lineno, in_try or skipped, len(scopes) == 1))
            inner = scopes + [child] if isinstance(
                child, (ast.FunctionDef, ast.AsyncFunctionDef)) else scopes
            if isinstance(child, ast.Try) and catches_import_error(child):
                for b in child.body:
                    visit(ast.Module(body=[b], type_ignores=[]), inner, True)
                for part in (child.handlers, child.orelse, child.finalbody):
                    for b in part:
                        visit(ast.Module(body=[b], type_ignores=[]), inner, in_try)
            else:
                visit(child, inner, in_try)

    visit(tree, [tree], False)
    return out


def _local(top: str) -> Path | None:
    """The file or package of a local module (tests/NAME.py, ROOT/NAME), or None."""
    for p in (TESTS / f"{top}.py", ROOT / f"{top}.py", ROOT / top):
        if p.exists() and top != "aidl_lang":
            return p
    return None


def module_owners(among: set[str]) -> dict[str, set[str]]:
    """Top-level module name -> normalised names of the installed distributions providing it:
    :func:`importlib.metadata.packages_distributions`, plus, for the distributions ``among``,
    the top-level extension modules it misses (it infers names from ``.py`` files only:
    ``manifold3d`` is a single ``.so``)."""
    owners: dict[str, set[str]] = {m: {_key(d) for d in ds}
                                   for m, ds in md.packages_distributions().items()}
    for name in among:
        try:
            files = md.distribution(name).files or []
        except md.PackageNotFoundError:
            continue
        for f in files:
            if len(f.parts) == 1 and f.suffix in (".so", ".pyd"):
                owners.setdefault(f.parts[0].split(".")[0], set()).add(name)
    return owners


def test_every_test_imports_only_what_the_test_extra_declares():
    """Local modules outside tests/ (benchmarks/, docs/) are held to what importing them
    needs (their module-level imports): their functions' imports belong to the benchmarks
    (the ``bench`` extra) unless a test calls them, which the test's own run shows."""
    allowed = declared_closure()
    dists = module_owners(allowed)
    files = sorted(TESTS.glob("*.py"))
    seen: set[Path] = set()
    problems: list[str] = []
    while files:
        path = files.pop()
        if path in seen:
            continue
        seen.add(path)
        for top, line, guarded, at_import in imports_of(path):
            if path.parent != TESTS and not at_import:
                continue
            if top in sys.stdlib_module_names or top in ("aidl_lang", "__future__"):
                continue
            local = _local(top)
            if local is not None:
                # a local module: check what it imports in turn (benchmarks/x.py, ...)
                text = (path.read_text().splitlines()[line - 1])
                for sub in re.findall(rf"\b{top}\.([\w.]+)", text) or [""]:
                    cand = local / Path(*sub.split(".")) if local.is_dir() else local
                    for p in (cand.with_suffix(".py"), cand / "__init__.py", cand):
                        if p.is_file() and p.suffix == ".py":
                            files.append(p)
                            break
                continue
            owners = dists.get(top, set())
            if owners & allowed or guarded:
                continue
            where = path.relative_to(ROOT)
            owner = ", ".join(sorted(owners)) or "no installed distribution"
            problems.append(f"{where}:{line}: `{top}` ({owner}) is not declared by "
                            "aidl-lang[test]: add it to the test extra in pyproject.toml, "
                            "or pytest.importorskip it")
    assert not problems, "\n".join(problems)


def test_the_check_sees_an_undeclared_import_and_accepts_a_guarded_one(tmp_path):
    """The parser above on a small file: a bare ``import matplotlib`` is unguarded; after
    ``pytest.importorskip`` in the same function, or inside ``try/except ImportError``, it is
    guarded; one importorskip does not guard another function."""
    f = tmp_path / "t.py"
    f.write_text("import pytest\n"
                 "def a():\n    from matplotlib.path import Path\n"
                 "def b():\n    pytest.importorskip('matplotlib')\n    import matplotlib\n"
                 "def c():\n    import matplotlib\n"
                 "try:\n    import OCP\nexcept ImportError:\n    OCP = None\n")
    got = {(m, line): g for m, line, g, _ in imports_of(f)}
    assert got == {("pytest", 1): False, ("matplotlib", 3): False, ("matplotlib", 6): True,
                   ("matplotlib", 8): False, ("OCP", 10): True}
    closure = declared_closure()
    assert {"shapely", "pytest", "numpy", "mcp", "pillow"} <= closure   # pillow: cairosvg's
    assert "matplotlib" not in closure and "cadquery-ocp" not in closure


def test_every_test_that_needs_ocp_is_marked_step():
    """A test that needs OCP (``pytest.importorskip("OCP")`` in it, or a call to a helper that
    does) skips under the README's command and carries ``@pytest.mark.step``: .ci/run runs
    ``-m step`` again in a venv with the ``step`` extra, so it cannot stay skipped for ever."""
    texts = {p: p.read_text(encoding="utf-8") for p in TESTS.glob("*.py")}

    def skips_ocp(fn) -> bool:
        return any(isinstance(n, ast.Call) and isinstance(n.func, ast.Attribute)
                   and n.func.attr == "importorskip" and n.args
                   and isinstance(n.args[0], ast.Constant) and n.args[0].value == "OCP"
                   for n in ast.walk(fn))

    def functions_of(paths):
        return [(p, f) for p in paths for f in ast.walk(ast.parse(texts[p]))
                if isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef))]
    # only a file that names OCP can skip on it, and only a file that names such a helper
    # can call it (parsing every test file took 15 s of the suite)
    helpers = {f.name for _, f in functions_of([p for p, t in texts.items() if "OCP" in t])
               if not f.name.startswith("test_") and skips_ocp(f)}
    assert {"step_faces", "step_edge_points"} <= helpers
    functions = functions_of([p for p, t in texts.items()
                              if "OCP" in t or any(h in t for h in helpers)])
    unmarked = []
    for p, f in functions:
        if not f.name.startswith("test_"):
            continue
        needs = skips_ocp(f) or any(isinstance(n, ast.Call) and isinstance(n.func, ast.Name)
                                    and n.func.id in helpers for n in ast.walk(f))
        marked = any("mark.step" in ast.unparse(d) for d in f.decorator_list)
        if needs and not marked:
            unmarked.append(f"{p.name}::{f.name}")
    assert not unmarked, f"needs OCP, add @pytest.mark.step: {unmarked}"


def test_every_pytest_plugin_a_test_imports_is_declared_by_name():
    """A pytest plugin a test imports (``import pytest_asyncio`` in test_mcp.py) is named in
    the test extra itself, not only reached through another plugin's requirements
    (pytest-lsp's): its API is the test's (``loop_scope`` needs pytest-asyncio 0.24), and a
    plugin that drops the requirement would take it away.  A regex over the files' text
    (cheap: no parse)."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    named = {_key(Requirement(r).name) for r in project["optional-dependencies"]["test"]}
    used = {(_key(m), p.name) for p in TESTS.glob("*.py")
            for m in re.findall(r"^\s*(?:from|import) (pytest_\w+)",
                                p.read_text(encoding="utf-8"), re.M)}
    assert ("pytest-asyncio", "test_mcp.py") in used
    assert [u for u in sorted(used) if u[0] not in named] == []
