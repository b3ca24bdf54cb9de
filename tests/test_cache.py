"""The user's cache folder (issue 15): nothing planted in the shared temporary folder is ever
loaded, the parse table and the font live in the user's own folder, owner-only, as plain data.

Each check runs the parser in a fresh interpreter (the cache is read once per process) with
``TMPDIR``, ``XDG_CACHE_HOME`` and ``HOME`` pointed into the test's own folder.
"""
from __future__ import annotations

import json
import os
import pickle
import stat
import subprocess
import sys
import tempfile

import lark
import pytest

from aidl_lang.parser import GRAMMAR
from aidl_lang.parsing.lexing import _PostLex

PROGRAM = "solid s {\n    a = Point(0, 0)\n    b = Point(3, 4)\n    Distance(a, b, 5)\n}\n"

CHILD = """
import sys
from aidl_lang.base.diagnostics import DiagnosticSink
from aidl_lang.parser import parse
sink = DiagnosticSink()
prog = parse(sys.argv[1], "t.aidl", sink)
assert not sink.has_errors, [d.message for d in sink.items]
print(type(prog.stmts[0]).__name__, prog.stmts[0].name)
"""


class _Plant:
    """Unpickling this writes the marker file: what an attacker's planted pickle would do."""

    def __init__(self, marker: str):
        self.marker = marker

    def __reduce__(self):
        return (open, (self.marker, "w"))


def _run(tmp_path, **env_extra) -> subprocess.CompletedProcess:
    env = dict(os.environ, TMPDIR=str(tmp_path / "tmp"), XDG_CACHE_HOME=str(tmp_path / "cache"),
               HOME=str(tmp_path / "home"))
    env.update(env_extra)
    return subprocess.run([sys.executable, "-c", CHILD, PROGRAM], env=env, capture_output=True,
                          text=True, timeout=120)


def _old_cache_file(tmpdir) -> str:
    """The exact file the old code (Lark ``cache=True``) read: let Lark write it once."""
    old = tempfile.tempdir
    tempfile.tempdir = str(tmpdir)
    try:
        lark.Lark(GRAMMAR.read_text(), parser="lalr", lexer="basic", postlex=_PostLex(),
                  propagate_positions=True, maybe_placeholders=True, start=["start", "expr"],
                  cache=True)
    finally:
        tempfile.tempdir = old
    (name,) = [p for p in os.listdir(tmpdir) if p.startswith(".lark_cache")]
    return os.path.join(tmpdir, name)


def test_a_pickle_planted_where_the_old_code_looked_is_never_loaded(tmp_path):
    (tmp_path / "tmp").mkdir()
    (tmp_path / "home").mkdir()
    path = _old_cache_file(tmp_path / "tmp")
    marker = tmp_path / "pwned"
    with open(path, "rb") as f:
        header = f.readline()                 # the grammar hash the old code compared
    with open(path, "wb") as f:
        f.write(header)
        pickle.dump(_Plant(str(marker)), f)
    os.chmod(path, 0o666)
    r = _run(tmp_path)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["StructDecl", "s"]
    assert not marker.exists()
    # and nothing new appears in the shared temporary folder
    assert os.listdir(tmp_path / "tmp") == [os.path.basename(path)]


def test_the_cache_is_owner_only_json_in_the_users_cache_folder(tmp_path):
    (tmp_path / "tmp").mkdir()
    (tmp_path / "home").mkdir()
    assert _run(tmp_path).returncode == 0
    d = tmp_path / "cache" / "aidl"
    st = os.lstat(d)
    assert stat.S_ISDIR(st.st_mode) and st.st_uid == os.getuid()
    assert stat.S_IMODE(st.st_mode) == 0o700
    files = list(d.iterdir())
    assert [p.name[:7] for p in files] == ["parser-"]
    fst = os.lstat(files[0])
    assert fst.st_uid == os.getuid() and stat.S_IMODE(fst.st_mode) == 0o600
    head, payload = files[0].read_text().split("\n", 1)  # plain data, not a pickle
    assert set(json.loads(head)) == {"key", "len", "crc"}
    assert set(json.loads(payload)) == {"lexer", "parser"}
    # a second run reads it and parses the same
    again = _run(tmp_path)
    assert again.returncode == 0 and again.stdout.split() == ["StructDecl", "s"]


def test_without_xdg_cache_home_the_cache_goes_under_home(tmp_path):
    (tmp_path / "tmp").mkdir()
    (tmp_path / "home").mkdir()
    assert _run(tmp_path, XDG_CACHE_HOME="").returncode == 0
    d = tmp_path / "home" / ".cache" / "aidl"
    assert stat.S_IMODE(os.lstat(d).st_mode) == 0o700
    assert [p.name[:7] for p in d.iterdir()] == ["parser-"]


def test_a_cache_file_others_can_write_is_not_read_but_replaced(tmp_path):
    # a valid table with mode 0666: read, it would be kept as it is; refused, it is rebuilt
    # and rewritten owner-only
    (tmp_path / "tmp").mkdir()
    (tmp_path / "home").mkdir()
    assert _run(tmp_path).returncode == 0
    (f,) = (tmp_path / "cache" / "aidl").iterdir()
    os.chmod(f, 0o666)
    ino = os.lstat(f).st_ino
    r = _run(tmp_path)
    assert r.returncode == 0 and r.stdout.split() == ["StructDecl", "s"], r.stderr
    st = os.lstat(f)
    assert stat.S_IMODE(st.st_mode) == 0o600 and st.st_ino != ino


def test_a_symbolic_link_in_the_cache_is_not_followed(tmp_path):
    (tmp_path / "tmp").mkdir()
    (tmp_path / "home").mkdir()
    assert _run(tmp_path).returncode == 0
    (f,) = (tmp_path / "cache" / "aidl").iterdir()
    elsewhere = tmp_path / "elsewhere.json"
    os.replace(f, elsewhere)
    os.symlink(elsewhere, f)
    r = _run(tmp_path)
    assert r.returncode == 0 and r.stdout.split() == ["StructDecl", "s"], r.stderr
    assert not os.path.islink(f)                      # replaced by a real file of ours


@pytest.mark.skipif(os.getuid() != 0, reason="needs root to give a file to another user")
def test_a_cache_folder_or_file_owned_by_someone_else_is_not_used(tmp_path):
    (tmp_path / "tmp").mkdir()
    (tmp_path / "home").mkdir()
    assert _run(tmp_path).returncode == 0
    d = tmp_path / "cache" / "aidl"
    (f,) = d.iterdir()
    os.chown(f, 12345, 12345)                         # a valid table, planted by another user
    r = _run(tmp_path)
    assert r.returncode == 0 and r.stdout.split() == ["StructDecl", "s"], r.stderr
    assert os.lstat(f).st_uid == os.getuid()          # refused, rebuilt and replaced
    os.chown(d, 12345, 12345)                         # the whole folder belongs to another user
    os.chown(f, 12345, 12345)
    r = _run(tmp_path)
    assert r.returncode == 0 and r.stdout.split() == ["StructDecl", "s"], r.stderr
    assert os.lstat(f).st_uid == 12345                # nothing written into it
    assert [p.name for p in d.iterdir()] == [f.name]


FONT_CHILD = """
import sys
from aidl_lang.geometry.shapes.text import text_extent
print(*(round(v, 9) for v in text_extent("AIDL 42", 5.0)))
print("package-imported" if "HersheyFonts" in sys.modules else "package-not-imported")
"""


def _run_font(tmp_path) -> list[float]:
    env = dict(os.environ, TMPDIR=str(tmp_path / "tmp"), XDG_CACHE_HOME=str(tmp_path / "cache"),
               HOME=str(tmp_path / "home"))
    r = subprocess.run([sys.executable, "-c", FONT_CHILD], env=env, capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    *numbers, imported = r.stdout.split()
    _run_font.imported = imported == "package-imported"
    return [float(v) for v in numbers]


def test_the_font_is_cached_owner_only_and_gives_the_same_strokes(tmp_path):
    from HersheyFonts import HersheyFonts
    (tmp_path / "tmp").mkdir()
    (tmp_path / "home").mkdir()
    first = _run_font(tmp_path)
    assert _run_font.imported                                 # the first run made the cache
    f = tmp_path / "cache" / "aidl" / "hershey-futural.json"
    st = os.lstat(f)
    assert st.st_uid == os.getuid() and stat.S_IMODE(st.st_mode) == 0o600
    assert _run_font(tmp_path) == first                       # read back from the cache,
    assert not _run_font.imported                             # without the package
    # the same segments as the package's own renderer, bit for bit, from the cached table
    ref = HersheyFonts()
    ref.load_default_font("futural")
    ref.normalize_rendering(1.0)
    from aidl_lang.geometry.shapes import text
    env_cache = os.environ.get("XDG_CACHE_HOME")
    os.environ["XDG_CACHE_HOME"] = str(tmp_path / "cache")
    try:
        text._glyphs.cache_clear()
        text._raw.cache_clear()
        for s in [*map(chr, range(32, 127)), "AIDL 42", "x = 3.5 mm\n(ok)"]:
            want = tuple((tuple(a), tuple(b)) for a, b in ref.lines_for_text(s))
            assert text._raw(s) == want, s
    finally:
        if env_cache is None:
            os.environ.pop("XDG_CACHE_HOME")
        else:
            os.environ["XDG_CACHE_HOME"] = env_cache
        text._glyphs.cache_clear()
        text._raw.cache_clear()
    # width 5 mm cap height: "AIDL 42" is wider than tall, and sits on the baseline
    x0, x1, y0, y1 = first
    assert x1 - x0 > 3 * (y1 - y0) > 0 and abs(y0) < 1e-9 and abs(y1 - 5.0) < 0.01


def test_a_font_file_others_can_write_is_not_read(tmp_path):
    (tmp_path / "tmp").mkdir()
    (tmp_path / "home").mkdir()
    good = _run_font(tmp_path)
    f = tmp_path / "cache" / "aidl" / "hershey-futural.json"
    f.write_text('{"font": "futural", "format": 1, "glyphs": {}}')     # no glyphs: no strokes
    os.chmod(f, 0o666)
    assert _run_font(tmp_path) == good
    assert stat.S_IMODE(os.lstat(f).st_mode) == 0o600



# ------------------------------------------------------------------ damaged entries (issue 26)
def _table(tmp_path):
    (tmp_path / "tmp").mkdir(exist_ok=True)
    (tmp_path / "home").mkdir(exist_ok=True)
    assert _run(tmp_path).returncode == 0
    (f,) = (tmp_path / "cache" / "aidl").iterdir()
    return f


def _rebuilt(tmp_path, f):
    """A run answers right within its time limit, and leaves a valid table behind."""
    r = _run(tmp_path)
    assert r.returncode == 0 and r.stdout.split() == ["StructDecl", "s"], r.stderr
    assert stat.S_ISREG(os.lstat(f).st_mode)
    from aidl_lang.host.cache import read_checked
    head = json.loads(f.read_text().split("\n", 1)[0])
    assert read_checked(f, head["key"]) is not None


def test_a_fifo_at_the_cache_path_does_not_hang(tmp_path):
    """A FIFO where the table should be hung every run (opened for reading, it waits for a
    writer): opened non-blocking and refused by its fstat, then replaced by a real table."""
    f = _table(tmp_path)
    os.unlink(f)
    os.mkfifo(f, 0o600)
    _rebuilt(tmp_path, f)                 # _run's timeout bounds it


@pytest.mark.parametrize("damage", ["truncated", "payload", "key-kept", "consistent-bad-state"])
def test_a_damaged_table_is_ignored_and_rebuilt(tmp_path, damage):
    """A table cut short, with bytes changed, or with the right key but another body (once
    an E0001 on a valid program or an IndexError): the header's length and CRC-32 fail, and
    a body that passes them but names a state that does not exist fails the table check."""
    import zlib
    f = _table(tmp_path)
    text = f.read_text()
    head, payload = text.split("\n", 1)
    if damage == "truncated":
        f.write_text(text[: len(text) // 2])
    elif damage == "payload":
        i = payload.index('"states"') + 20
        f.write_text(head + "\n" + payload[:i] + ("7" if payload[i] != "7" else "8")
                     + payload[i + 1:])
    else:
        data = json.loads(payload)
        states = data["parser"]["states"]
        if damage == "key-kept":           # the old format's damage: the right key, rows cut
            data["parser"]["states"] = states[: len(states) // 2]
        else:
            row = next(r for r in states if r)
            row[next(iter(row))] = len(states) + 5
        body = json.dumps(data)
        h = json.loads(head)
        if damage == "consistent-bad-state":
            h.update(len=len(body), crc=zlib.crc32(body.encode()))
        f.write_text(json.dumps(h) + "\n" + body)
    os.chmod(f, 0o600)
    _rebuilt(tmp_path, f)


def test_a_damaged_font_file_is_ignored(tmp_path):
    (tmp_path / "tmp").mkdir()
    (tmp_path / "home").mkdir()
    good = _run_font(tmp_path)
    f = tmp_path / "cache" / "aidl" / "hershey-futural.json"
    head, payload = f.read_text().split("\n", 1)
    f.write_text(head + "\n" + payload.replace("[", "[[", 3))       # the right key, a bad body
    assert _run_font(tmp_path) == good
    os.unlink(f)
    os.mkfifo(f, 0o600)
    assert _run_font(tmp_path) == good
