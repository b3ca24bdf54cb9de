"""Races with a second process (issue 37, "Security: races and links"): while a swapper process
turns a file or a folder inside the allowed folder into a symbolic link to something outside
it and back, many calls of the MCP tools and of the batch journal must never read or write
outside.  Each loop is bounded (a few hundred calls, a few seconds); before the fix each
leaked within it (about 3% of the calls)."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from aidl_lang.host.files import FileRefused

SWAPPER = r'''
import os, sys, time
path, link_to, kind, seconds, text = sys.argv[1:6]
tmp_link, tmp_real = path + ".swap-link", path + ".swap-real"
end = time.monotonic() + float(seconds)
open(path + ".ready", "w").close()
while time.monotonic() < end:
    if os.path.lexists(tmp_link):
        os.unlink(tmp_link)
    os.symlink(link_to, tmp_link)
    if kind == "file":
        os.replace(tmp_link, path)              # the file becomes a link ...
        time.sleep(0.0002)
        with open(tmp_real, "w") as f:
            f.write(text)
        os.replace(tmp_real, path)              # ... and a file again
    else:
        os.rename(path, tmp_real)               # the folder becomes a link ...
        os.rename(tmp_link, path)
        time.sleep(0.0002)
        os.unlink(path)                         # ... and the folder again
        os.rename(tmp_real, path)
    time.sleep(0.0002)
'''


class Swapper:
    """A second process that swaps ``path`` between a real file (or folder) and a symbolic
    link to ``link_to`` for at most ``seconds``."""

    def __init__(self, path: Path, link_to: Path, kind: str, seconds: float = 8.0,
                 text: str = "") -> None:
        self.proc = subprocess.Popen([sys.executable, "-c", SWAPPER, str(path), str(link_to),
                                      kind, str(seconds), text])
        ready = Path(str(path) + ".ready")
        t0 = time.monotonic()
        while not ready.exists() and time.monotonic() - t0 < 10:
            time.sleep(0.01)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.proc.kill()
        self.proc.wait()


def calls(n: int, went_through, seconds: float = 30.0):
    """``n`` rounds, and more while ``went_through()`` is false, for at most ``seconds``: on a
    loaded machine the swapper can sit in one state (the link) for all of ``n`` quick calls,
    and the check that some call went through then failed (the leak checks held)."""
    end = time.monotonic() + seconds
    k = 0
    while k < n or (not went_through() and time.monotonic() < end):
        yield k
        k += 1
        if k >= n and not went_through():
            time.sleep(0.001)             # let the swapper run


SECRET = "solid leak { SECRET_TOKEN_5f3a = 1 }\n"
MINE = "solid s { c = Circel(center=(0, 0), radius=1) }\n"
GOOD = "solid plate { body = Rectangle(center=(0, 0), width=40, height=20) }\n"


def test_mcp_check_by_path_never_reads_a_file_swapped_for_a_link(tmp_path):
    from aidl_lang.mcp import tools as T
    root = tmp_path / "root"
    root.mkdir()
    secret = tmp_path / "secret.aidl"
    secret.write_text(SECRET)
    (root / "a.aidl").write_text(MINE)
    ws = T.Workspace(root)
    leaked = mine = refused = 0
    with Swapper(root / "a.aidl", secret, "file", text=MINE):
        for _ in calls(300, lambda: mine > 0):
            try:
                doc = T.check(ws, path="a.aidl")
            except T.Refused:
                refused += 1
                continue
            text = json.dumps(doc)
            leaked += "SECRET_TOKEN" in text
            mine += "Circel" in text
    assert leaked == 0
    assert mine > 0                       # the swaps did not stop every call


def test_mcp_render_never_writes_through_a_folder_swapped_for_a_link(tmp_path):
    from aidl_lang.mcp import tools as T
    root = tmp_path / "root"
    (root / "sub").mkdir(parents=True)
    outside = tmp_path / "outside"
    outside.mkdir()
    ws = T.Workspace(root)
    written = 0
    with Swapper(root / "sub", outside, "dir"):
        for _ in calls(300, lambda: written > 0):
            try:
                doc, _png = T.render(ws, source=GOOD, output="sub/x.svg", width=16)
            except T.Refused:
                continue
            written += doc.get("written") == "sub/x.svg"
    assert sorted(os.listdir(outside)) == []
    assert written > 0


def test_mcp_render_refuses_a_folder_swapped_for_a_link_during_the_compile(tmp_path,
                                                                           monkeypatch):
    """The issue's window, made certain: `R/sub` becomes a link to a folder outside while the
    program compiles; nothing is written outside and the reply is a refusal."""
    from aidl_lang.mcp import tools as T
    root = tmp_path / "root"
    (root / "sub").mkdir(parents=True)
    outside = tmp_path / "outside"
    outside.mkdir()
    ws = T.Workspace(root)
    compile_ = ws.compile

    def swapping(*a, **k):
        r = compile_(*a, **k)
        os.rmdir(root / "sub")
        os.symlink(outside, root / "sub")
        return r

    monkeypatch.setattr(ws, "compile", swapping)
    with pytest.raises(T.Refused, match="symbolic link"):
        T.render(ws, source=GOOD, output="sub/x.svg", width=16)
    assert os.listdir(outside) == []


@pytest.mark.parametrize("suffix", [".jsonl", ".parquet"])
def test_batch_journal_never_appends_through_a_link_swapped_in(tmp_path, suffix):
    """The journal (``OUT.jsonl`` itself, or ``OUT.parquet.journal.jsonl``) swapped between a
    file and a link to a victim file: no row ever reaches the victim."""
    from aidl_lang.batch.store import Store
    victim = tmp_path / "victim.txt"
    victim.write_text("victim's notes\n")
    store = Store(tmp_path / f"out{suffix}")
    opened = 0
    with Swapper(store.journal, victim, "file", text=""):
        for i in calls(300, lambda: opened > 0):
            try:
                store.open()
            except FileRefused:
                continue
            store.append({"id": f"row{i}"})
            store.close()
            opened += 1
    assert victim.read_text() == "victim's notes\n"
    assert opened > 0


def test_an_import_never_passes_through_a_folder_swapped_for_a_link(tmp_path):
    """Item 2: the import's path was checked with realpath, then opened by name with
    O_NOFOLLOW on the last component only: `sub`, swapped for a link to a folder outside
    between the two, let the outside file be read.  Now every folder is opened relative to
    the previous one's descriptor without following links."""
    from aidl_lang.pipeline import compile_source
    root = tmp_path / "root"
    (root / "sub").mkdir(parents=True)
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "lib.aidl").write_text("secret = ]\n")      # each says `x` closes nothing
    (root / "sub" / "lib.aidl").write_text("mine = )\n")
    main = root / "main.aidl"
    src = 'import "sub/lib.aidl"\n' + GOOD
    main.write_text(src)
    leaked = mine = 0
    with Swapper(root / "sub", outside, "dir"):
        for _ in calls(300, lambda: mine > 0):
            res = compile_source(src, str(main))
            text = " ".join(f"{d.message} {d.hint}" for d in res.sink.items)
            leaked += "`]`" in text
            mine += "`)`" in text
    assert leaked == 0
    assert mine > 0                       # the swaps did not stop every import


def test_read_import_refuses_a_folder_that_became_a_link_after_the_check(tmp_path):
    """The window made certain: resolved while `sub` is a folder, read once it is a link."""
    from aidl_lang.library.sources import ImportRefused, read_import, resolve_import
    root = tmp_path / "root"
    (root / "sub").mkdir(parents=True)
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "lib.aidl").write_text(SECRET)
    (root / "sub" / "lib.aidl").write_text(MINE)
    real = resolve_import("sub/lib.aidl", str(root / "main.aidl"))
    assert read_import(real, "sub/lib.aidl") == MINE
    os.rename(root / "sub", root / "sub-real")
    os.symlink(outside, root / "sub")
    with pytest.raises(ImportRefused) as e:
        read_import(real, "sub/lib.aidl")
    assert "symbolic link" in str(e.value.args[0]) and "SECRET" not in str(e.value.args)
