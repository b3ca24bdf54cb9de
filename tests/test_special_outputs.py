"""Outputs that are not regular files (issue 48, finding 2): a FIFO, a character device, a
socket or a directory at an output path is never renamed over (`aidl import x.dxf -o
/dev/null` run as root replaced the system's /dev/null).  Every writer refuses it, names the
path and what it is, exits non-zero and leaves the node as it was (same kind, same inode);
`aidl render -o -` writes to standard output instead.

Nothing here opens a FIFO (a reader or writer would block); every subprocess has a time-out.
"""
from __future__ import annotations

import os
import socket
import stat
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

AIDL = [sys.executable, "-m", "aidl_lang.cli"]
EXAMPLE = ROOT / "examples" / "bottle_opener.aidl"
BOARD = ROOT / "stdlib" / "drawings" / "pcb_board.dxf"
KINDS = ["fifo", "chardev", "socket", "directory"]
SAID = {"fifo": "is a FIFO", "chardev": "is a character device", "socket": "is a socket",
        "directory": "is a directory"}


def run(*args, cwd, timeout=120):
    return subprocess.run(AIDL + [str(a) for a in args], capture_output=True, cwd=cwd,
                          timeout=timeout, stdin=subprocess.DEVNULL)


@pytest.fixture
def make_node(tmp_path, monkeypatch):
    """``make_node(kind, name)``: a node of ``kind`` at ``tmp_path / name``; returns its
    ``lstat``.  Sockets are bound by a relative name (the path of a Unix socket is short)."""
    socks = []

    def make(kind: str, name: str) -> os.stat_result:
        p = tmp_path / name
        if kind == "fifo":
            os.mkfifo(p)
        elif kind == "chardev":
            try:
                os.mknod(p, 0o600 | stat.S_IFCHR, os.makedev(1, 3))     # as /dev/null
            except (PermissionError, OSError) as e:
                pytest.skip(f"cannot make a character device here: {e}")
        elif kind == "socket":
            monkeypatch.chdir(tmp_path)
            s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
            s.bind(name)
            socks.append(s)
            monkeypatch.undo()
        else:
            p.mkdir()
        return os.lstat(p)

    yield make
    for s in socks:
        s.close()


def same(before: os.stat_result, p: Path) -> bool:
    after = os.lstat(p)
    return (after.st_mode, after.st_ino, after.st_dev) == \
        (before.st_mode, before.st_ino, before.st_dev)


@pytest.mark.parametrize("kind", KINDS)
def test_render_refuses_an_output_that_is_not_a_regular_file(tmp_path, make_node, kind):
    before = make_node(kind, "n.svg")
    r = run("render", EXAMPLE, "-o", "n.svg", cwd=tmp_path)
    err = r.stderr.decode()
    assert r.returncode == 2, err
    assert "`n.svg`" in err and SAID[kind] in err, err
    assert "internal error" not in err
    assert same(before, tmp_path / "n.svg")
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".tmp")]


@pytest.mark.parametrize("kind", ["fifo", "chardev", "socket"])
def test_render_says_what_to_do(tmp_path, make_node, kind):
    make_node(kind, "n.svg")
    err = run("render", EXAMPLE, "-o", "n.svg", cwd=tmp_path).stderr.decode()
    assert "not a regular file" in err and "choose another path" in err and "-o -" in err, err


@pytest.mark.parametrize("kind", ["fifo", "chardev"])
def test_render_through_a_link_to_one_is_refused_too(tmp_path, make_node, kind):
    before = make_node(kind, "n.svg")
    (tmp_path / "link.svg").symlink_to("n.svg")
    r = run("render", EXAMPLE, "-o", "link.svg", "--follow-symlinks", cwd=tmp_path)
    err = r.stderr.decode()
    assert r.returncode == 2 and "`link.svg`" in err and SAID[kind].split()[-1] in err, err
    assert same(before, tmp_path / "n.svg") and (tmp_path / "link.svg").is_symlink()


@pytest.mark.parametrize("kind", KINDS)
def test_import_refuses_an_output_that_is_not_a_regular_file(tmp_path, make_node, kind):
    before = make_node(kind, "n.aidl")
    r = run("import", BOARD, "-o", "n.aidl", cwd=tmp_path)
    err = r.stderr.decode()
    assert r.returncode == 1, err
    assert "`n.aidl`" in err and SAID[kind] in err, err
    assert "internal error" not in err and "Traceback" not in err, err
    assert same(before, tmp_path / "n.aidl")
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".tmp")]


def test_import_to_a_device_named_like_dev_null_leaves_it(tmp_path, make_node):
    """The finding itself, on a copy of /dev/null's node (never the system's own)."""
    before = make_node("chardev", "null")
    r = run("import", BOARD, "-o", tmp_path / "null", cwd=tmp_path)
    assert r.returncode == 1 and "is a character device" in r.stderr.decode()
    assert same(before, tmp_path / "null")
    assert stat.S_ISCHR(os.lstat(tmp_path / "null").st_mode)


def test_fmt_refuses_a_fifo_source(tmp_path, make_node):
    before = make_node("fifo", "f.aidl")
    r = run("fmt", "f.aidl", cwd=tmp_path, timeout=60)
    err = r.stderr.decode()
    assert r.returncode == 1 and "f.aidl" in err and "not formatted" in err, err
    assert same(before, tmp_path / "f.aidl")


def test_fmt_leaves_a_file_swapped_for_a_fifo_after_it_was_read(tmp_path, monkeypatch, capsys):
    """The write of `aidl fmt` checks the file again: one replaced by a FIFO between the read
    and the write is left as it is (it used to be renamed over)."""
    import aidl_lang.library.sources as sources
    from aidl_lang.editor.fmt import main as fmt_main
    p = tmp_path / "x.aidl"
    p.write_text("units mm\nsolid  plate {\n    body = Rectangle(center=(0,0), width=4, height=2)\n}\n")
    read, fifo = sources.read_program, []

    def read_then_swap(path, *a, **k):
        text = read(path, *a, **k)
        os.unlink(path)
        os.mkfifo(path)
        fifo.append(os.lstat(path))
        return text
    monkeypatch.setattr(sources, "read_program", read_then_swap)
    assert fmt_main([str(p)]) == 1
    assert same(fifo[0], p) and stat.S_ISFIFO(os.lstat(p).st_mode)
    assert "is a FIFO" in capsys.readouterr().err


@pytest.mark.parametrize("kind", ["fifo", "chardev", "socket"])
def test_write_atomic_and_the_api_refuse(tmp_path, make_node, kind):
    import aidl_lang
    from aidl_lang.output.writers.write import NotRegularFile, WriteError, write_atomic
    before = make_node(kind, "n.svg")
    with pytest.raises(NotRegularFile) as e:
        write_atomic(tmp_path / "n.svg", b"<svg/>")
    assert e.value.kind == SAID[kind][3:] and "n.svg" in str(e.value)
    res = aidl_lang.compile(path=EXAMPLE)
    with pytest.raises(WriteError):
        res.write(tmp_path / "n.svg")
    assert same(before, tmp_path / "n.svg")


def test_a_fifo_put_there_after_staging_is_not_renamed_over(tmp_path, monkeypatch):
    """The race: the target is a regular file when the data is staged and a FIFO when the
    rename comes; the kind is read again just before the rename."""
    from aidl_lang.output.writers import write as W
    p = tmp_path / "n.svg"
    p.write_text("old")
    stage = W.stage

    def stage_then_swap(out, data, *a, **k):
        staged = stage(out, data, *a, **k)
        os.unlink(p)
        os.mkfifo(p)
        return staged
    monkeypatch.setattr(W, "stage", stage_then_swap)
    with pytest.raises(W.WriteError) as e:
        W.write_atomic(p, b"new")
    assert "is a FIFO" in str(e.value)
    assert stat.S_ISFIFO(os.lstat(p).st_mode)
    assert [q.name for q in tmp_path.iterdir()] == ["n.svg"]       # the staged file removed


def test_write_in_dir_refuses_a_device(tmp_path, make_node):
    from aidl_lang.output.writers.write import NotRegularFile, write_in_dir
    before = make_node("chardev", "null")
    dfd = os.open(tmp_path, os.O_RDONLY)
    try:
        with pytest.raises(NotRegularFile):
            write_in_dir(dfd, "null", b"x", "null")
    finally:
        os.close(dfd)
    assert same(before, tmp_path / "null") and os.listdir(tmp_path) == ["null"]


def test_mcp_render_refuses_a_fifo_output(tmp_path, make_node):
    from aidl_lang.mcp import tools as T
    before = make_node("fifo", "n.svg")
    with pytest.raises(T.Refused) as e:
        T.render(T.Workspace(tmp_path), source="units mm\nsolid p {\n    b = Rectangle("
                 "center=(0, 0), width=4, height=2)\n}\n", output="n.svg", width=64)
    assert "is a FIFO" in str(e.value)
    assert same(before, tmp_path / "n.svg")


def test_batch_refuses_a_fifo_result_before_compiling(tmp_path, make_node):
    before = make_node("fifo", "rows.jsonl")
    r = run("batch", EXAMPLE, "-o", "rows.jsonl", cwd=tmp_path)
    err = r.stderr.decode()
    assert r.returncode == 2 and "`rows.jsonl` is a FIFO" in err, err
    assert same(before, tmp_path / "rows.jsonl")


# ------------------------------------------------------------------ -o -
def test_render_to_standard_output(tmp_path):
    r = run("render", EXAMPLE, "-o", "-", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith(b"<svg") and r.stdout.rstrip().endswith(b"</svg>")
    assert os.listdir(tmp_path) == []
    r = run("render", EXAMPLE, "-o", "-", "--format", "dxf", "-o", "x.svg", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert b"ENTITIES" in r.stdout and b"wrote" not in r.stdout
    assert b"wrote x.svg" in r.stderr and (tmp_path / "x.svg").read_bytes().startswith(b"<svg")
    r = run("render", EXAMPLE, "-o", "-", "--format", "png", cwd=tmp_path)     # a pipe
    assert r.returncode == 0 and r.stdout.startswith(b"\x89PNG\r\n"), r.stderr


def test_render_to_standard_output_from_standard_input(tmp_path):
    r = subprocess.run(AIDL + ["render", "-", "-o", "-"], input=EXAMPLE.read_bytes(),
                       capture_output=True, cwd=tmp_path, timeout=120)
    assert r.returncode == 0 and r.stdout.startswith(b"<svg"), r.stderr


def test_standard_output_usage_errors(tmp_path):
    for args, said in [(["-o", "-", "--json"], "--json"),
                       (["-o", "x.svg", "--format", "dxf"], "--format is the format of `-o -`"),
                       (["-o", "-", "--format", "ps"], "--format takes one of"),
                       (["-o", "-", "-o", "-"], "given twice")]:
        r = run("render", EXAMPLE, *args, cwd=tmp_path)
        assert r.returncode == 2 and said in r.stderr.decode(), (args, r.stderr)
    assert os.listdir(tmp_path) == []


def test_binary_output_is_not_written_to_a_terminal(tmp_path):
    import pty
    master, slave = pty.openpty()
    try:
        r = subprocess.run(AIDL + ["render", str(EXAMPLE), "-o", "-", "--format", "png"],
                           stdout=slave, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                           cwd=tmp_path, timeout=120)
    finally:
        os.close(slave)
        os.close(master)
    assert r.returncode == 2 and b"refusing to write binary PNG to a terminal" in r.stderr


def test_a_fifo_put_there_after_the_last_check_is_swapped_back(tmp_path, monkeypatch):
    """The window a check leaves: a FIFO made after every check, just before the rename.
    The rename is an atomic exchange (renameat2 RENAME_EXCHANGE) and the node it took out is
    looked at: the FIFO goes back, the same node (inode), and the write is refused."""
    from aidl_lang.output.writers import write as W
    if W._libc_renameat2() is None:
        pytest.skip("no renameat2 here")
    p = tmp_path / "n.svg"
    p.write_text("old")
    check = W.check_replaceable
    made = {}

    def check_then_swap(path, *a, **k):
        check(path, *a, **k)
        if not made:
            os.unlink(p)
            os.mkfifo(p)
            made["ino"] = os.lstat(p).st_ino
    monkeypatch.setattr(W, "check_replaceable", check_then_swap)
    with pytest.raises(W.NotRegularFile) as e:
        W.write_atomic(p, b"new")
    assert "is a FIFO" in str(e.value)
    st = os.lstat(p)
    assert stat.S_ISFIFO(st.st_mode) and st.st_ino == made["ino"]
    assert [q.name for q in tmp_path.iterdir()] == ["n.svg"]       # the staged file removed


def test_without_renameat2_the_check_comes_just_before_the_rename(tmp_path, monkeypatch):
    """Another kernel or libc: a plain rename after a second check (both paths tested)."""
    from aidl_lang.output.writers import write as W
    monkeypatch.setattr(W, "_libc_renameat2", lambda: None)
    p = tmp_path / "n.svg"
    p.write_text("old")
    W.write_atomic(p, b"new")
    assert p.read_bytes() == b"new"
    os.unlink(p)
    os.mkfifo(p)
    with pytest.raises(W.NotRegularFile):
        W.write_atomic(p, b"new")
    assert stat.S_ISFIFO(os.lstat(p).st_mode)


_RACER = r"""
import os, stat, sys, time
p = sys.argv[1]
lost = 0
end = time.monotonic() + float(sys.argv[2])
while time.monotonic() < end:
    try:
        os.unlink(p)
    except FileNotFoundError:
        pass
    try:
        os.mkfifo(p)
    except FileExistsError:
        continue
    fd = os.open(p, os.O_RDONLY | os.O_NONBLOCK)   # holds the node: its link count tells
    try:
        if not stat.S_ISFIFO(os.fstat(fd).st_mode) or not os.path.samestat(os.fstat(fd), os.lstat(p)):
            continue                               # the writer's file came first (opened
                                                   # its staged file, not our FIFO)
        time.sleep(0.0005)
        if os.fstat(fd).st_nlink == 0:             # renamed over: the FIFO has no name left
            lost += 1
    except FileNotFoundError:
        pass
    finally:
        os.close(fd)
print(lost)
"""


def test_a_target_that_keeps_coming_and_going_is_never_renamed_over(tmp_path, monkeypatch):
    """Another process removes the output name before each exchange and puts a file there
    before each no-replace rename, RETRIES times: the write gives up with nothing written
    and never falls back to a plain rename, which could go over whatever came last (a FIFO
    made between its check and the rename: the race test below lost 3 FIFOs that way on a
    loaded machine, after 3 tries)."""
    import errno
    import os
    from aidl_lang.output.writers import write as W
    if W._libc_renameat2() is None:
        pytest.skip("no renameat2 here")
    p = tmp_path / "n.svg"
    p.write_bytes(b"old")
    tmp, target = W.stage(p, b"new")
    calls = []

    def racing(src, dst, dir_fd, flags):
        calls.append(flags)
        if flags == W._RENAME_EXCHANGE:
            os.unlink(dst)
            raise FileNotFoundError(errno.ENOENT, "gone", dst)
        Path(dst).write_bytes(b"someone else's")
        raise FileExistsError(errno.EEXIST, "there", dst)

    def no_plain_rename(*a, **k):
        raise AssertionError("a plain rename while renameat2 is there")
    monkeypatch.setattr(W, "_renameat2", racing)
    monkeypatch.setattr(W.os, "replace", no_plain_rename)
    with pytest.raises(OSError) as e:
        W.replace(tmp, target)
    assert e.value.errno == errno.EAGAIN and "nothing was written" in str(e.value)
    assert len(calls) == 2 * W.RETRIES
    assert p.read_bytes() == b"someone else's"


def test_two_processes_race_and_no_fifo_is_ever_renamed_over(tmp_path):
    """A second process keeps putting a FIFO at the output path while this one writes it
    again and again: every FIFO keeps its name (link count never 0), each write either
    lands or is refused."""
    import subprocess
    import sys
    import time
    from aidl_lang.output.writers import write as W
    if W._libc_renameat2() is None:
        pytest.skip("no renameat2 here")
    p = tmp_path / "n.svg"
    racer = subprocess.Popen([sys.executable, "-c", _RACER, str(p), "2"],
                             stdout=subprocess.PIPE, text=True)
    wrote = refused = 0
    end = time.monotonic() + 2
    while time.monotonic() < end:
        try:
            W.write_atomic(p, b"new")
            wrote += 1
        except W.WriteError:
            refused += 1
    out, _ = racer.communicate(timeout=30)
    assert racer.returncode == 0 and int(out) == 0, out
    assert wrote and refused, (wrote, refused)
    # no staged file is left behind; a FIFO the racer made while an exchange was being put
    # back may end at a temporary name (write.py _put_back): moved, never removed
    assert not [q for q in tmp_path.iterdir() if q.name.endswith(".tmp")
                and stat.S_ISREG(q.lstat().st_mode)]
