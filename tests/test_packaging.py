"""The release: ``python -m build`` makes a wheel and an sdist that pass ``twine check``, under
the Apache-2.0 licence (PEP 639 metadata); the wheel installs on its own into a fresh venv (no
system site-packages, no extras) and has what the compiler reads at run time: the grammar,
the standard library, the preview's static files and the example programs travel inside it
(`aidl_lang/grammar`, `aidl_lang/stdlib` and `aidl_lang/examples` are links to the top-level
folders in a checkout; the sdist and the wheel hold the files); ``aidl --version`` names it,
the core formats are written and the extras' formats name the extra to install.  From an
empty folder outside the checkout every subcommand answers (the smoke tests at the end:
``prompt``, ``generate``, ``docs``, ``explain``, ``render``, ``import``, ``check``, the MCP
server's ``prompts/get`` through the MCP client SDK, the studio's gallery over HTTP, ``lsp``
through an LSP client).

The module builds once and installs once (measured with
``pytest --durations=3 tests/test_packaging.py``: about 10 s to build, 25 s to install from
pip's local cache); it is marked ``slow``, so ``pytest -m "not slow"`` leaves it out.  The
wheel's venv is made without pip (this checkout's pip installs into it, ``pip --python``: the
venv's own pip took 3.5 s of CPU to install), and its commands run as a user's do, writing
their bytecode (``PYTHONDONTWRITEBYTECODE`` unset: the dependencies are installed without it,
and each of the module's 27 ``aidl`` runs compiled numpy and the rest from source again, 1.8 s
of CPU for a render of an STL where 0.45 s is its work)."""
import email
import json
import math
import os
import shutil
import subprocess
import sys
import tarfile
import tomllib
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
VERSION = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["version"]
# the environment of every command run from the wheel: without this checkout on PYTHONPATH, and
# writing bytecode as a user's Python does (see the module's docstring)
WHEEL_ENV = {k: v for k, v in os.environ.items()
             if k not in ("PYTHONPATH", "PYTHONDONTWRITEBYTECODE")}


# ------------------------------------------------------------------ the release artefacts
@pytest.fixture(scope="module")
def dist(tmp_path_factory):
    """``python -m build`` (the sdist, then the wheel built from the sdist, as a release
    does) on a copy of the sources, so that the build writes nothing into the checkout."""
    tmp = tmp_path_factory.mktemp("dist")
    src = tmp / "src"
    src.mkdir()
    for name in ("pyproject.toml", "README.md", "LICENSE"):
        shutil.copy(ROOT / name, src / name)
    for name in ("grammar", "stdlib", "examples"):
        shutil.copytree(ROOT / name, src / name)
    (src / "docs").mkdir()
    for name in ("language.md", "api.md"):            # aidl_lang/docs links to these two
        shutil.copy(ROOT / "docs" / name, src / "docs" / name)
    shutil.copytree(ROOT / "aidl_lang", src / "aidl_lang", symlinks=True,
                    ignore=shutil.ignore_patterns("__pycache__"))
    r = subprocess.run([sys.executable, "-m", "build", "-o", str(tmp / "dist"), str(src)],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    (wheel,) = (tmp / "dist").glob("aidl_lang-*.whl")
    (sdist,) = (tmp / "dist").glob("aidl_lang-*.tar.gz")
    return wheel, sdist


@pytest.mark.slow
def test_the_wheel_carries_the_grammar_the_stdlib_and_the_static_files(dist):
    wheel, _ = dist
    names = set(zipfile.ZipFile(wheel).namelist())
    need = {"aidl_lang/grammar/aidl.lark", "aidl_lang/serve/static/index.html",
            *(f"aidl_lang/{p.relative_to(ROOT / 'aidl_lang')}"      # three.js, vendored
              for p in (ROOT / "aidl_lang/serve/static/vendor").rglob("*") if p.is_file()),
            *(f"aidl_lang/stdlib/{p.relative_to(ROOT / 'stdlib')}"
              for p in (ROOT / "stdlib").rglob("*.aidl"))}
    assert need <= names, need - names
    grammar = zipfile.ZipFile(wheel).read("aidl_lang/grammar/aidl.lark").decode()
    assert grammar == (ROOT / "grammar" / "aidl.lark").read_text()
    for name in ("language.md", "api.md"):          # the MCP server's two references
        assert zipfile.ZipFile(wheel).read(f"aidl_lang/docs/{name}").decode() == \
            (ROOT / "docs" / name).read_text()
    assert not [n for n in names if n.startswith("aidl_lang/docs/") and n.endswith(".py")]


@pytest.mark.slow
def test_the_wheel_carries_the_examples(dist):
    """``aidl_lang/examples`` (a link to ``examples/`` in a checkout) ships every example,
    every generator example and the files they read, and no Python module; the sdist holds
    them as regular files (no link), so a wheel built from it has them too."""
    wheel, sdist = dist
    names = set(zipfile.ZipFile(wheel).namelist())
    base = "aidl_lang/examples"
    assert {f"{base}/telephone.aidl", f"{base}/bottle_opener.aidl",
            f"{base}/generators/divider_tray.aidl",
            f"{base}/parts/gears.aidl", f"{base}/parts/logo.svg",
            f"{base}/parts/pcb_board.dxf", "aidl_lang/studio/gallery.py"} <= names
    shipped = {n[len(base) + 1:] for n in names if n.startswith(base + "/")}
    want = {p.relative_to(ROOT / "examples").as_posix()
            for p in (ROOT / "examples").rglob("*") if p.is_file() and p.suffix != ".py"
            and p.suffix in (".aidl", ".svg", ".dxf")}
    assert shipped == want, shipped ^ want
    assert not any(n.startswith(base) and n.endswith(".py") for n in names)
    assert not any(n.startswith("aidl_lang/studio/examples") for n in names)
    assert zipfile.ZipFile(wheel).read(f"{base}/generators/divider_tray.aidl").decode() == \
        (ROOT / "examples" / "generators" / "divider_tray.aidl").read_text()
    with tarfile.open(sdist) as tar:
        members = {m.name: m for m in tar.getmembers()}
        assert members[f"aidl_lang-{VERSION}/{base}/generators/divider_tray.aidl"].isfile()
        assert not [m for m in members.values() if m.issym() or m.islnk()]


@pytest.mark.slow
def test_the_release_metadata_is_complete_and_passes_twine_check(dist):
    """The wheel and the sdist pass ``twine check --strict`` (the README renders on a package
    index); the licence is the PEP 639 expression ``Apache-2.0`` with the Apache text inside
    both; the URLs, classifiers, keywords and author an index shows are there."""
    wheel, sdist = dist
    r = subprocess.run([sys.executable, "-m", "twine", "check", "--strict", str(wheel),
                        str(sdist)], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and r.stdout.count("PASSED") == 2, r.stdout + r.stderr
    whl = zipfile.ZipFile(wheel)
    info = next(n for n in whl.namelist() if n.endswith(".dist-info/METADATA"))
    meta = email.message_from_bytes(whl.read(info))
    assert meta["License-Expression"] == "Apache-2.0"
    assert meta.get_all("License-File") == ["LICENSE"]
    licence = whl.read(info.replace("METADATA", "licenses/LICENSE")).decode()
    assert licence == (ROOT / "LICENSE").read_text()
    assert "Apache License\n                           Version 2.0, January 2004" in licence
    urls = dict(u.split(", ", 1) for u in meta.get_all("Project-URL"))
    assert urls["Source"] == "https://github.com/aidl-lang/aidl"
    assert all(u.startswith("https://github.com/aidl-lang/aidl") for u in urls.values()), urls
    classifiers = meta.get_all("Classifier")
    assert "Programming Language :: Python :: 3.11" in classifiers
    assert not any(c.startswith("License ::") for c in classifiers)   # PEP 639: the expression
    assert meta["Author"] and meta["Keywords"] and meta["Summary"]
    assert meta["Version"] == VERSION
    with tarfile.open(sdist) as tar:
        top = f"aidl_lang-{VERSION}"
        assert tar.extractfile(f"{top}/LICENSE").read().decode() == licence
        assert f"{top}/aidl_lang/grammar/aidl.lark" in tar.getnames()


def test_the_editor_extension_is_under_the_same_licence():
    pkg = json.loads((ROOT / "editors" / "vscode" / "package.json").read_text())
    assert pkg["license"] == "Apache-2.0"
    assert pkg["repository"]["url"] == "https://github.com/aidl-lang/aidl.git"
    assert (ROOT / "editors" / "vscode" / "LICENSE").read_text() == (ROOT / "LICENSE").read_text()
    assert not (ROOT / "editors" / "vscode" / "LICENSE.txt").exists()


# ------------------------------------------------------------------ the wheel alone, no extras
PLATE = """solid plate {
    body = Rectangle(center=(0, 0), width=40, height=30)
    hole bore { c = Circle(center=(0, 0), diameter=22 mm) }
}
"""


@pytest.fixture(scope="module")
def plain_install(tmp_path_factory, dist):
    """A fresh venv (no system site-packages) with ``pip install aidl_lang-*.whl`` and no
    extras, as a user's first install: the wheel brings its dependencies itself (pip takes
    them from its local cache).  The venv has no pip of its own: this checkout's installs
    into it."""
    wheel, _ = dist
    root = tmp_path_factory.mktemp("plain")
    venv = root / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True,
                   timeout=120)
    # --no-compile: pip writes no bytecode for every module of every dependency (it took half
    # of this install); aidl_lang's own is compiled, as pip does by default, and the commands
    # below write the bytecode of the modules they import (WHEEL_ENV)
    r = subprocess.run([sys.executable, "-m", "pip", "--python", str(venv / "bin" / "python"),
                        "install", "-q", "--disable-pip-version-check", "--no-compile",
                        str(wheel)], capture_output=True, text=True, timeout=540)
    assert r.returncode == 0, r.stderr[-3000:]
    (package,) = venv.glob("lib/python*/site-packages/aidl_lang")
    subprocess.run([str(venv / "bin" / "python"), "-m", "compileall", "-q", str(package)],
                   check=True, capture_output=True, timeout=120)
    prog = root / "plate.aidl"
    prog.write_text(PLATE)
    return venv, prog


@pytest.mark.slow
def test_the_installed_wheel_knows_its_version_and_is_not_this_checkout(plain_install):
    """``aidl --version`` names the wheel's version, and ``aidl_lang`` is imported from the
    venv's site-packages, not from the repository."""
    venv, _ = plain_install
    r = subprocess.run([str(venv / "bin" / "aidl"), "--version"], capture_output=True,
                       text=True, timeout=60, cwd=venv, env=WHEEL_ENV)
    assert r.returncode == 0 and r.stdout == f"aidl {VERSION}\n", r.stdout + r.stderr
    r = subprocess.run([str(venv / "bin" / "python"), "-c",
                        "import aidl_lang; print(aidl_lang.__file__)"],
                       capture_output=True, text=True, timeout=60, cwd=venv, env=WHEEL_ENV)
    assert Path(r.stdout.strip()).is_relative_to(venv), r.stdout + r.stderr


def _probe(venv: Path, code: str, cwd: Path):
    """What the Python program ``code`` prints as JSON, run by the wheel's venv in ``cwd``."""
    r = subprocess.run([str(venv / "bin" / "python"), "-c", code], capture_output=True,
                       text=True, timeout=300, cwd=cwd, env=WHEEL_ENV)
    assert r.returncode == 0, r.stderr[-3000:]
    return json.loads(r.stdout)


@pytest.mark.slow
def test_the_installed_wheel_has_the_studio_gallery(plain_install, tmp_path):
    """The gallery reads the examples shipped inside the wheel: the same entries as in this
    checkout, and a generator's program compiles and draws its thumbnail there."""
    venv, _ = plain_install
    probe = ("import json\nfrom aidl_lang.studio import gallery as g\n"
             "e = g.entry('generator/divider_tray')\n"
             "print(json.dumps({'ids': [x.id for x in g.entries()], 'where': str(g.EXAMPLES),"
             " 'ok': g.compile_entry(e).ok, 'svg': '<path' in g.thumbnail(e),"
             " 'rows': [p['name'] for p in e.params],"
             " 'form': 'ring=sun + 2 * planet' in g.entry('generator/planetary').source}))")
    got = _probe(venv, probe, tmp_path)
    from aidl_lang.studio import gallery
    assert got["ids"] == [e.id for e in gallery.entries()]
    assert Path(got["where"]).is_relative_to(venv)
    assert got["ok"] and got["svg"] and {"rows", "cols", "thickness"} <= set(got["rows"])
    assert got["form"]                  # aidl_lang/studio/forms/ is in the wheel


@pytest.mark.slow
def test_the_installed_wheel_draws_text_in_the_default_fonts(plain_install, tmp_path):
    """`font="sans"` and `font="serif:Bold"` work on a fresh install (issue 112): the default
    families come with the wheel's dependencies from PyPI (fontpkg-noto-sans, -serif), found
    in the venv, not in this checkout or the system; "HAPPY" in a solid is 5 letters, 8 loops."""
    venv, _ = plain_install
    probe = ("import json, aidl_lang\nfrom aidl_lang.geometry.shapes import font as F\n"
             "out = {}\nfor f in ('sans', 'serif:Bold'):\n"
             "    r = aidl_lang.compile(source='solid w { t = Text(\"HAPPY\", position=(0, 0), "
             "size=20, font=\"' + f + '\") }')\n"
             "    [p] = r.output.parts\n"
             "    out[f] = [sum(lp.area > 0 for lp in p.loops), len(p.loops), "
             "F.resolve(f).path]\nprint(json.dumps(out))")
    got = _probe(venv, probe, tmp_path)
    for f in ("sans", "serif:Bold"):
        pieces, loops, path = got[f]
        assert (pieces, loops) == (5, 8)
        assert Path(path).is_relative_to(venv), path


@pytest.mark.slow
@pytest.mark.parametrize("ext", [".svg", ".dxf", ".stl"])
def test_the_installed_wheel_renders_an_example_that_imports_the_stdlib(plain_install, ext,
                                                                         tmp_path):
    """examples/mounting_plate.aidl imports ``std/shapes.aidl``, which must come from inside
    the installed wheel; the outputs are re-read by independent readers."""
    venv, _ = plain_install
    prog = tmp_path / "mounting_plate.aidl"
    shutil.copy(ROOT / "examples" / "mounting_plate.aidl", prog)
    out = tmp_path / f"plate{ext}"
    r = subprocess.run([str(venv / "bin" / "aidl"), "render", str(prog), "-o", str(out)],
                       capture_output=True, text=True, timeout=300, cwd=tmp_path, env=WHEEL_ENV)
    assert r.returncode == 0, r.stderr
    if ext == ".svg":
        import svgelements as se
        shapes = [e for e in se.SVG.parse(str(out)).elements() if isinstance(e, se.Shape)]
        assert len(shapes) >= 5, len(shapes)          # the plate and its four washers
    elif ext == ".dxf":
        import ezdxf
        circles = ezdxf.readfile(str(out)).modelspace().query("CIRCLE")
        assert len(circles) >= 8, len(circles)        # corner holes and washer bores
    else:
        import trimesh
        m = trimesh.load(str(out), force="mesh")
        assert m.is_watertight and len(m.split()) == 5, len(m.split())


def _read_back(path: Path) -> None:
    """Re-read an output with an independent reader; raises if it does not accept it."""
    ext = path.suffix
    if ext == ".svg":
        import svgelements as se
        shapes = [e for e in se.SVG.parse(str(path)).elements() if isinstance(e, se.Shape)]
        assert len(shapes) >= 1
    elif ext == ".dxf":
        import ezdxf
        doc = ezdxf.readfile(str(path))
        assert {e.dxftype() for e in doc.modelspace()} == {"LWPOLYLINE", "CIRCLE"}
    else:
        import trimesh
        m = trimesh.load(str(path), force="mesh")
        assert m.is_watertight and m.volume == pytest.approx((1200 - math.pi * 121) * 3, rel=1e-3)


EXTRA = {".png": "png", ".3mf": "mesh", ".step": "step", ".pdf": "pdf"}


@pytest.mark.slow
@pytest.mark.parametrize("ext", [".svg", ".dxf", ".stl", ".png", ".3mf", ".step", ".pdf"])
def test_every_format_on_a_plain_install_writes_or_names_its_extra(plain_install, ext):
    """On ``pip install aidl_lang-*.whl`` without extras SVG, DXF and STL are written and an
    independent reader accepts them; PNG, 3MF and STEP exit 2 with the
    ``pip install 'aidl-lang[EXTRA]'`` line and write nothing: never an internal error
    (exit 3) or a traceback."""
    venv, prog = plain_install
    out = prog.with_suffix(ext)
    r = subprocess.run([str(venv / "bin" / "aidl"), "render", str(prog), "-o", str(out)],
                       capture_output=True, text=True, timeout=300, env=WHEEL_ENV)
    assert "Traceback" not in r.stderr and "internal error" not in r.stderr, r.stderr
    if ext in EXTRA:
        assert r.returncode == 2, (r.returncode, r.stderr)
        assert f"pip install 'aidl-lang[{EXTRA[ext]}]'" in r.stderr, r.stderr
        assert not out.exists()
    else:
        assert r.returncode == 0, r.stderr
        _read_back(out)


def test_check_and_svg_do_not_import_trimesh(tmp_path):
    """trimesh is a core dependency but imported only to write STL or 3MF."""
    prog = tmp_path / "plate.aidl"
    prog.write_text(PLATE)
    probe = ("import sys, contextlib, io\nfrom aidl_lang.cli.main import main\n"
             "with contextlib.redirect_stdout(io.StringIO()):\n"
             f"    assert main(['check', {str(prog)!r}]) == 0\n"
             f"    assert main(['render', {str(prog)!r}, '-o', {str(tmp_path / 'p.svg')!r}]) == 0\n"
             "print('trimesh' in sys.modules)")
    r = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                       timeout=120, cwd=ROOT)
    assert r.stdout.strip() == "False", r.stderr


def test_version_option_prints_the_installed_version(capsys):
    """``aidl --version`` (in this checkout's editable install): ``aidl X.Y.Z``, exit 0, even
    though a subcommand is otherwise required."""
    from aidl_lang.cli.main import main
    with pytest.raises(SystemExit) as e:
        main(["--version"])
    assert e.value.code == 0
    assert capsys.readouterr().out == f"aidl {VERSION}\n"


# ------------------------------------------------------------------ every subcommand, from the wheel
def _aidl(venv: Path, *args: str, cwd: Path, timeout: float = 120,
          env: dict | None = None) -> subprocess.CompletedProcess:
    """``venv/bin/aidl ARGS`` in ``cwd`` (an empty folder outside the checkout), without this
    checkout on PYTHONPATH."""
    return subprocess.run([str(venv / "bin" / "aidl"), *args], capture_output=True, text=True,
                          timeout=timeout, cwd=cwd, env={**WHEEL_ENV, **(env or {})})


def _clean(r: subprocess.CompletedProcess) -> None:
    assert "Traceback" not in r.stderr and "internal error" not in r.stderr, r.stderr[-3000:]


@pytest.fixture
def empty(tmp_path):
    """An empty folder outside the checkout (the current folder of every smoke test)."""
    d = tmp_path / "empty"
    d.mkdir()
    return d


@pytest.mark.slow
def test_from_the_wheel_prompt_and_generate_read_the_shipped_examples(plain_install, empty):
    """``aidl prompt`` carries the example programs shipped in the wheel (the same text as this
    checkout's prompt), every one of them with ``--examples 4``; ``aidl generate`` builds its
    prompt and then says it cannot reach the model's server (exit 1, nothing written): never
    a FileNotFoundError."""
    from aidl_lang.llm.prompt import PROMPT_EXAMPLES, system_prompt
    venv, _ = plain_install
    r = _aidl(venv, "prompt", cwd=empty)
    _clean(r)
    assert r.returncode == 0 and r.stdout.strip() == system_prompt().strip()
    assert "opener" in r.stdout                      # examples/bottle_opener.aidl
    r = _aidl(venv, "prompt", "--examples", str(len(PROMPT_EXAMPLES)), cwd=empty)
    _clean(r)
    assert r.returncode == 0
    assert r.stdout.strip() == system_prompt(len(PROMPT_EXAMPLES)).strip()
    r = _aidl(venv, "generate", "a plate", "-o", "out.aidl", "--rounds", "1", "--api-key", "x",
              "--base-url", "http://127.0.0.1:9/v1", cwd=empty)
    _clean(r)
    assert r.returncode == 1 and "cannot reach http://127.0.0.1:9/v1" in r.stderr, r.stderr
    assert list(empty.iterdir()) == []


@pytest.mark.slow
def test_from_the_wheel_docs_explain_check_render_and_import(plain_install, empty):
    """``docs``, ``explain``, ``check``, ``render`` and ``import`` from an empty folder: the
    import of the board drawing (a DXF of KiCad's layers) writes a program that checks, and
    the rendered DXF is re-read by ezdxf with its four mounting holes."""
    venv, prog = plain_install
    r = _aidl(venv, "docs", "Circle", cwd=empty)
    _clean(r)
    assert r.returncode == 0 and "diameter" in r.stdout
    r = _aidl(venv, "docs", "spur_gear", cwd=empty)            # a stdlib template
    assert r.returncode == 0 and "teeth" in r.stdout, r.stdout + r.stderr
    r = _aidl(venv, "explain", "E0103", cwd=empty)
    _clean(r)
    assert r.returncode == 0 and "E0103" in r.stdout
    r = _aidl(venv, "check", str(prog), cwd=empty)
    _clean(r)
    assert r.returncode == 0, r.stdout + r.stderr
    shutil.copy(ROOT / "examples" / "parts" / "pcb_board.dxf", empty / "board.dxf")
    r = _aidl(venv, "import", "board.dxf", "-o", "board.aidl", "--layer", "Edge.Cuts",
              cwd=empty)
    _clean(r)
    assert r.returncode == 0 and (empty / "board.aidl").is_file(), r.stderr
    r = _aidl(venv, "check", "board.aidl", cwd=empty)
    _clean(r)
    assert r.returncode == 0, r.stdout + r.stderr
    r = _aidl(venv, "render", "board.aidl", "-o", "out.dxf", cwd=empty)
    _clean(r)
    assert r.returncode == 0, r.stderr
    import ezdxf
    circles = ezdxf.readfile(str(empty / "out.dxf")).modelspace().query("CIRCLE")
    assert sorted(round(c.dxf.radius, 6) for c in circles) == [1.6] * 4   # M3 holes


def _beside(requirement: str, target: Path) -> list[str]:
    """Links in ``target`` to the installed files of ``requirement`` and of every distribution
    it needs (markers and extras followed), as ``pip install --target`` would unpack them,
    taken from this test's own environment; each one's version satisfies what asks for it.
    Returns the distributions' names."""
    from importlib.metadata import distribution

    from packaging.requirements import Requirement
    from packaging.utils import canonicalize_name
    seen: set[tuple[str, str]] = set()
    names: list[str] = []
    todo = [(Requirement(requirement), "")]
    while todo:
        req, extra = todo.pop()
        if req.marker is not None and not req.marker.evaluate({"extra": extra}):
            continue
        dist = distribution(req.name)
        assert req.specifier.contains(dist.version, prereleases=True), (req, dist.version)
        for e in ("", *sorted(req.extras)):
            if (canonicalize_name(req.name), e) in seen:
                continue
            seen.add((canonicalize_name(req.name), e))
            todo += [(Requirement(r), e) for r in dist.requires or ()]
        if dist.metadata["Name"] in names:
            continue
        names.append(dist.metadata["Name"])
        for top in {f.parts[0] for f in dist.files or ()} - {"..", "__pycache__"}:
            if not (target / top).exists():
                (target / top).symlink_to(dist.locate_file(top))
    return names


@pytest.fixture(scope="module")
def mcp_path(plain_install, tmp_path_factory):
    """The ``mcp`` extra's SDK for the wheel's venv, beside it (on PYTHONPATH for the server
    only), so the plain venv stays without extras.  The requirement is read from the wheel's
    own metadata; the SDK and what it needs are linked from this test's environment, whose
    versions satisfy it (a ``pip install --target`` of them took 6 s of CPU)."""
    venv, _ = plain_install
    r = subprocess.run([str(venv / "bin" / "python"), "-c",
                        "from importlib.metadata import requires\n"
                        "print(next(r.split(';')[0] for r in requires('aidl-lang')"
                        " if 'extra == \"mcp\"' in r))"],
                       capture_output=True, text=True, timeout=60, cwd=venv, env=WHEEL_ENV)
    assert r.returncode == 0 and r.stdout.strip().startswith("mcp"), r.stderr
    target = tmp_path_factory.mktemp("mcp")
    names = _beside(r.stdout.strip(), target)
    assert {"mcp", "pydantic", "anyio"} <= {n.lower() for n in names}, names
    return target


@pytest.mark.slow
@pytest.mark.asyncio
async def test_from_the_wheel_the_mcp_server_gives_its_prompt_and_examples(plain_install,
                                                                           mcp_path, empty):
    """``aidl mcp`` of the wheel, driven by the MCP client SDK over stdio from an empty
    folder: ``prompts/get aidl`` returns the system prompt with the shipped examples (and the
    request appended), ``aidl://examples/bottle_opener.aidl`` is the example's text and
    ``aidl://docs/language`` the language reference."""
    from mcp.client.session import ClientSession
    from mcp.client.stdio import StdioServerParameters, stdio_client
    venv, _ = plain_install
    params = StdioServerParameters(command=str(venv / "bin" / "aidl"),
                                   args=["mcp", "--root", str(empty)], cwd=str(empty),
                                   env={**WHEEL_ENV, "PYTHONPATH": str(mcp_path)})
    async with stdio_client(params) as (read, write):
        async with ClientSession(read, write) as session:
            await session.initialize()
            got = await session.get_prompt("aidl", {"request": "a plate with two holes"})
            text = "\n".join(m.content.text for m in got.messages)
            assert "```aidl" in text and "Design this part: a plate with two holes" in text
            assert "bottle_opener" in text or "opener" in text
            res = await session.read_resource("aidl://examples/bottle_opener.aidl")
            assert res.contents[0].text == (ROOT / "examples" / "bottle_opener.aidl").read_text()
            res = await session.read_resource("aidl://docs/language")
            assert res.contents[0].text == (ROOT / "docs" / "language.md").read_text()


@pytest.mark.slow
def test_from_the_wheel_the_studio_serves_its_gallery(plain_install, empty):
    """``aidl studio --port 0`` of the wheel, started in an empty folder: the page and the
    gallery's list (the same entries as this checkout's) and one thumbnail are served; the
    studio stops on SIGTERM."""
    import json
    import urllib.request

    from aidl_lang.studio import gallery
    from benchmarks.serve.serve_latency import launched
    venv, _ = plain_install
    with launched([str(venv / "bin" / "aidl"), "studio", "--port", "0", "--compilers", "1"],
                  cwd=empty, env={**WHEEL_ENV, "AIDL_STUDIO_AHEAD": "none"},
                  timeout=120) as (url, proc):
        with urllib.request.urlopen(url, timeout=60) as r:
            assert r.status == 200 and b"<html" in r.read().lower()
        with urllib.request.urlopen(url + "api/gallery", timeout=120) as r:
            doc = json.loads(r.read())
        items = doc["entries"] if isinstance(doc, dict) else doc
        assert sorted(e["id"] for e in items) == sorted(e.id for e in gallery.entries())
        with urllib.request.urlopen(url + "api/thumb/example/bottle_opener.svg",
                                    timeout=120) as r:
            assert b"<path" in r.read()
    assert proc.wait(timeout=30) is not None


@pytest.mark.slow
@pytest.mark.asyncio
async def test_from_the_wheel_the_language_server_initializes_and_diagnoses(plain_install,
                                                                           empty):
    """``aidl lsp`` of the wheel with an LSP client (pytest-lsp's, over stdio): ``initialize``
    answers with the server's name, a document with an unknown shape gets its E0103
    diagnostic, and ``shutdown`` + ``exit`` end the server."""
    from lsprotocol import types as T
    from pytest_lsp import client_capabilities, make_test_lsp_client
    venv, _ = plain_install
    from lsp_published import keep, published
    client = make_test_lsp_client()
    keep(client)
    await client.start_io(str(venv / "bin" / "aidl"), "lsp", cwd=str(empty), env=WHEEL_ENV)
    try:
        init = await client.initialize_session(T.InitializeParams(
            capabilities=client_capabilities("visual-studio-code"),
            root_uri=empty.as_uri()))
        assert init.server_info is not None and init.server_info.name
        uri = (empty / "t.aidl").as_uri()
        client.text_document_did_open(T.DidOpenTextDocumentParams(T.TextDocumentItem(
            uri=uri, language_id="aidl", version=1,
            text="solid s {\n    c = Circel(center=(0, 0), radius=5)\n}\n")))
        diags = await published(client, uri, since=0, where=lambda p: bool(p.diagnostics))
        assert "E0103" in {d.code for d in diags}, client.published
        await client.shutdown_session()
    finally:
        await client.stop()
