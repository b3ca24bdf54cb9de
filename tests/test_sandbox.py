"""The import sandbox (docs/language.md §8.2): one resolver (aidl_lang/library/sources.py) for the
checker, the interpreter and the language server; nothing outside the importing file's folder
tree or the standard library is read, and no diagnostic reveals anything about a refused
target (names defined in it, its contents, its absolute path)."""
import os
import time

import pytest

from aidl_lang.editor.lsp import analysis as an
from aidl_lang.pipeline import compile_source

pytestmark = pytest.mark.timing          # the refusals are timed (CPU seconds)

SECRET = "def secret_w(a = 1) -> solid { c = Circle((0, 0), a) }\nsecret_k = 4\n"


def run(proj, src, name="main.aidl"):
    p = proj / name
    p.write_text(src)
    t0 = time.process_time()      # CPU seconds: reading /dev/zero whole would spend them;
    c = compile_source(src, str(p))   # the wall clock of a loaded machine is no measure
    return c, time.process_time() - t0


def everything(c) -> str:
    return "\n".join(f"{d.code} {d.message} {d.hint} {d.suggestions}" for d in c.sink.items)


@pytest.fixture
def layout(tmp_path):
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "secret.aidl").write_text(SECRET)
    (outside / "notes.txt").write_text("TOP-SECRET first line\nmore\n")
    proj = tmp_path / "proj"
    proj.mkdir()
    return proj, outside


def the_e0114(c, line=1):
    errs = [d for d in c.sink.items if d.severity == "error"]
    assert [d.code for d in errs] == ["E0114"], everything(c)
    d = errs[0]
    assert d.span is not None and d.span.line == line and d.span.col == 8
    return d


@pytest.mark.parametrize("path", ["../outside/secret.aidl", "../outside/secret", "{abs}",
                                  "sub/../../outside/secret.aidl", "std/../../outside/secret.aidl"])
def test_outside_paths_are_refused_without_reading(layout, path):
    proj, outside = layout
    path = path.replace("{abs}", str(outside / "secret.aidl"))
    c, dt = run(proj, f'import "{path}"\nsolid s {{ a = secret_v(a=2) }}\n')
    d = the_e0114(c)
    text = everything(c)
    assert "secret_w" not in text and "secret_k" not in text
    assert text.count(str(outside)) == path.count(str(outside))   # only the path as written
    assert dt < 5


def test_alias_outside_is_refused(layout):
    proj, outside = layout
    c, _ = run(proj, 'import "../outside/secret.aidl" as s\nsolid t { a = s.secret_v() }\n')
    the_e0114(c)
    assert "secret_w" not in everything(c)


def test_symlink_to_text_file_is_not_read(layout):
    proj, outside = layout
    os.symlink(outside / "notes.txt", proj / "notes.aidl")
    c, _ = run(proj, 'import "notes.aidl"\nsolid s { c = Circle((0, 0), 1) }\n')
    the_e0114(c)
    assert "TOP-SECRET" not in everything(c)


def test_symlink_out_of_the_tree_is_refused(layout):
    proj, outside = layout
    os.symlink(outside / "secret.aidl", proj / "lib.aidl")
    c, _ = run(proj, 'import "lib.aidl"\nsolid s { a = secret_v(a=2) }\n')
    the_e0114(c)
    assert "secret_w" not in everything(c)


def test_symlink_inside_the_tree_is_followed(layout):
    proj, _ = layout
    (proj / "real.aidl").write_text("def peg(r = 2) -> solid { c = Circle((0, 0), r) }\n")
    os.symlink(proj / "real.aidl", proj / "link.aidl")
    c, _ = run(proj, 'import "link.aidl"\nsolid s { a = peg(r=3) }\n')
    assert c.ok, everything(c)


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="needs /dev/zero")
def test_symlink_to_dev_zero_is_refused_quickly(layout):
    proj, _ = layout
    os.symlink("/dev/zero", proj / "zero.aidl")
    c, dt = run(proj, 'import "zero.aidl"\nsolid s { c = Circle((0, 0), 1) }\n')
    the_e0114(c)
    assert dt < 5


def test_fifo_does_not_block(layout):
    proj, _ = layout
    os.mkfifo(proj / "x.aidl")
    c, dt = run(proj, 'import "x.aidl"\nsolid s { c = Circle((0, 0), 1) }\n')
    the_e0114(c)
    assert dt < 5
    # the language server's analysis follows imports too: it must not block either
    t0 = time.process_time()
    an.hover('import "x.aidl"\nsolid s { c = Circle((0, 0), 1) }\n', 2, 10,
             path=str(proj / "main.aidl"))
    assert time.process_time() - t0 < 5


def test_directory_and_oversized_file(layout):
    proj, _ = layout
    (proj / "dir.aidl").mkdir()
    c, _ = run(proj, 'import "dir.aidl"\nsolid s { c = Circle((0, 0), 1) }\n')
    the_e0114(c)
    (proj / "big.aidl").write_text("# x\n" * 300_000)
    c, _ = run(proj, 'import "big.aidl"\nsolid s { c = Circle((0, 0), 1) }\n')
    assert "larger than" in the_e0114(c).message


def test_overlong_import_path_is_located(layout):
    proj, _ = layout
    c, _ = run(proj, 'import "' + "a" * 300 + '"\nsolid s { c = Circle((0, 0), 1) }\n')
    d = the_e0114(c)
    assert "too long" in d.message
    assert d.span.end_col == 8 + 302


def test_missing_file_suggests_only_neighbours(layout):
    proj, _ = layout
    (proj / "parts.aidl").write_text("def peg(r = 2) -> solid { c = Circle((0, 0), r) }\n")
    c, _ = run(proj, 'import "part.aidl"\nsolid s { a = peg() }\n')
    d = the_e0114(c)
    assert d.suggestions[0] == "parts.aidl"
    assert set(d.suggestions) <= {p.name for p in proj.iterdir()}
    c, _ = run(proj, 'import "../outside/secre.aidl"\nsolid s { a = peg() }\n')
    d = the_e0114(c)
    assert d.suggestions == [] and "secret" not in everything(c)


def test_transitive_imports(layout):
    """top imports mid imports base: base's names reach top (docs/language.md §2.2)."""
    proj, _ = layout
    (proj / "base.aidl").write_text("BASE_R = 3\ndef peg(r = 2) -> solid { c = Circle((0, 0), r) }\n")
    (proj / "mid.aidl").write_text('import "base.aidl"\nMID = 1\n')
    c, _ = run(proj, 'import "mid.aidl"\nsolid s {\n    a = peg(r=BASE_R + MID)\n}\n')
    assert c.ok, everything(c)
    g = next(iter(c.model.all_geometry()))
    assert c.model.x[g.scalars["radius"].index] == pytest.approx(4.0)


def test_language_server_does_not_follow_outside_imports(layout):
    proj, outside = layout
    src = 'import "../outside/secret.aidl"\nsolid s { a = secret_w(a=2) }\n'
    path = str(proj / "main.aidl")
    line, ch = 1, src.splitlines()[1].index("secret_w") + 1
    h = an.hover(src, line, ch, path=path)
    assert h is None or "secret_w(a" not in h.contents.value
    assert an.definition(src, line, ch, "file:///main.aidl", path=path) is None
    labels = {c.label for c in an.completions(src, line, ch, path=path)}
    assert "secret_w" not in labels and "secret_k" not in labels
    diags = an.diagnostics(src, path, solve=False)
    assert any(d.code == "E0114" for d in diags)
    assert not any("secret_k" in d.message for d in diags)
