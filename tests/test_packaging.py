"""A regular (not editable) install has what the compiler reads at run time: the grammar,
the standard library and the preview's static files travel inside the wheel
(`aidl_lang/grammar` and `aidl_lang/stdlib` are links to the top-level folders); and a plain
install without extras writes every format or names the extra to install."""
import math
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def test_the_wheel_carries_the_grammar_the_stdlib_and_the_static_files(tmp_path):
    src = tmp_path / "src"
    src.mkdir()
    for name in ("pyproject.toml", "README.md"):
        shutil.copy(ROOT / name, src / name)
    for name in ("grammar", "stdlib"):
        shutil.copytree(ROOT / name, src / name)
    shutil.copytree(ROOT / "aidl_lang", src / "aidl_lang", symlinks=True,
                    ignore=shutil.ignore_patterns("__pycache__"))
    r = subprocess.run([sys.executable, "-m", "pip", "wheel", "-q", "--no-deps",
                        str(src), "-w", str(tmp_path / "dist")],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    (wheel,) = (tmp_path / "dist").glob("aidl_lang-*.whl")
    names = set(zipfile.ZipFile(wheel).namelist())
    need = {"aidl_lang/grammar/aidl.lark", "aidl_lang/serve/static/index.html",
            *(f"aidl_lang/stdlib/{p.relative_to(ROOT / 'stdlib')}"
              for p in (ROOT / "stdlib").rglob("*.aidl"))}
    assert need <= names, need - names
    grammar = zipfile.ZipFile(wheel).read("aidl_lang/grammar/aidl.lark").decode()
    assert grammar == (ROOT / "grammar" / "aidl.lark").read_text()


# ------------------------------------------------------------------ a plain install, no extras
PLATE = """solid plate {
    body = Rectangle(center=(0, 0), width=40, height=30)
    hole bore { c = Circle(center=(0, 0), diameter=22 mm) }
}
"""


@pytest.fixture(scope="module")
def plain_install(tmp_path_factory):
    """A fresh venv (no system site-packages) with `pip install -e <repo>` and no extras, as a
    user's first install: built once for the module (~35 s with pip's cache)."""
    root = tmp_path_factory.mktemp("plain")
    venv = root / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True, timeout=120)
    r = subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "install", "-q",
                        "--disable-pip-version-check", "-e", str(ROOT)],
                       capture_output=True, text=True, timeout=540)
    assert r.returncode == 0, r.stderr[-3000:]
    prog = root / "plate.aidl"
    prog.write_text(PLATE)
    return venv, prog


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
    elif ext == ".png":
        from PIL import Image
        with Image.open(path) as im:
            assert im.format == "PNG" and im.size[0] > 0
    elif ext in (".stl", ".3mf"):
        import trimesh
        m = trimesh.load(str(path), force="mesh")
        assert m.is_watertight and m.volume == pytest.approx((1200 - math.pi * 121) * 3, rel=1e-3)
    else:
        from OCP.IFSelect import IFSelect_RetDone
        from OCP.STEPControl import STEPControl_Reader
        assert STEPControl_Reader().ReadFile(str(path)) == IFSelect_RetDone


@pytest.mark.parametrize("ext", [".svg", ".dxf", ".png", ".stl", ".3mf", ".step"])
def test_every_format_on_a_plain_install_writes_or_names_its_extra(plain_install, ext):
    """On `pip install aidl-lang` without extras every format either writes a file an
    independent reader accepts, or exits 2 with the `pip install 'aidl-lang[...]'` line:
    never an internal error (exit 3) or a traceback.  SVG, DXF and STL need no extra."""
    venv, prog = plain_install
    out = prog.with_suffix(ext)
    r = subprocess.run([str(venv / "bin" / "aidl"), "render", str(prog), "-o", str(out)],
                       capture_output=True, text=True, timeout=300)
    assert "Traceback" not in r.stderr and "internal error" not in r.stderr, r.stderr
    if r.returncode == 0:
        _read_back(out)
    else:
        assert ext not in (".svg", ".dxf", ".stl"), r.stderr
        assert r.returncode == 2 and "pip install 'aidl-lang[" in r.stderr, r.stderr
        assert not out.exists()


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
