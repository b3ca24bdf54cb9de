"""A regular (not editable) install has what the compiler reads at run time: the grammar,
the standard library and the preview's static files travel inside the wheel
(`aidl_lang/grammar` and `aidl_lang/stdlib` are links to the top-level folders)."""
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

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
