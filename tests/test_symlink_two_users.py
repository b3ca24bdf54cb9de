"""Outputs and planted links, played by two real users (issue 26): an attacker plants
``out.svg`` -> the victim's private 0600 file in a shared sticky folder (like ``/tmp/shared``);
the victim's real ``aidl render -o`` into that folder must not touch the private file, with or
without ``--follow-symlinks``; the victim's own link in a folder of their own is written
through when asked; a read-only output is refused unless ``--force``.

Needs root (to make the two users with ``useradd`` and run commands as them with
``runuser``) and a Python the users can run (``/usr/bin/python3`` of the same minor version as
this one, given this checkout and this environment's packages on ``PYTHONPATH``); skipped,
saying why, elsewhere.  The users are removed afterwards, also when a check fails.  Run with
``-s`` to see each command and what it printed (the note of issue 26 quotes it)."""
from __future__ import annotations

import os
import pwd
import shutil
import subprocess
import sys
import sysconfig
import uuid
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PY = f"/usr/bin/python3.{sys.version_info.minor}"
PROGRAM = "solid plate {\n    c = Circle(center=(0, 0), radius=5)\n}\n"
SECRET = b"victim's private notes\n"

pytestmark = [
    pytest.mark.skipif(not hasattr(os, "geteuid") or os.geteuid() != 0,
                       reason="needs root to make two users"),
    pytest.mark.skipif(not (shutil.which("useradd") and shutil.which("runuser")),
                       reason="needs useradd and runuser"),
    pytest.mark.skipif(not os.access(PY, os.X_OK), reason=f"needs {PY} for the users"),
]


def run_as(user: str, *cmd: str) -> subprocess.CompletedProcess:
    env = {"PATH": "/usr/bin:/bin", "HOME": f"/home/{user}", "LANG": "C.UTF-8",
           "PYTHONPATH": os.pathsep.join([str(ROOT), sysconfig.get_paths()["purelib"],
                                          sysconfig.get_paths()["platlib"]])}
    r = subprocess.run([shutil.which("runuser"), "-u", user, "--", *cmd], capture_output=True,
                       text=True, env=env, timeout=120)
    print(f"$ ({user}) {' '.join(cmd)}\n  exit {r.returncode}"
          + "".join(f"\n  {line}" for line in (r.stdout + r.stderr).strip().splitlines()))
    return r


def render_as(user: str, program: Path, out: Path, *flags: str):
    return run_as(user, PY, "-m", "aidl_lang.cli", "render", str(program), "-o", str(out),
                  *flags)


@pytest.fixture
def users(tmp_path_factory):
    tag = uuid.uuid4().hex[:6]
    made = []
    try:
        for role in ("attacker", "victim"):
            name = f"aidl{role[:3]}{tag}"
            subprocess.run(["useradd", "-m", "-s", "/bin/sh", name], check=True,
                           capture_output=True)
            made.append(name)
        attacker, victim = made
        probe = run_as(victim, PY, "-c", "import aidl_lang.cli, numpy, manifold3d")
        if probe.returncode != 0:
            pytest.skip(f"the test users cannot import aidl from {ROOT}: "
                        f"{probe.stderr.strip()[-200:]}")
        shared = Path(f"/tmp/aidl-shared-{tag}")
        shared.mkdir(mode=0o777)
        os.chmod(shared, 0o1777)                     # like /tmp: sticky, world-writable
        yield attacker, victim, shared
        shutil.rmtree(shared, ignore_errors=True)
    finally:
        for name in made:
            subprocess.run(["userdel", "-r", name], capture_output=True)


def test_a_link_planted_by_another_user_never_aims_a_render_at_a_private_file(users):
    attacker, victim, shared = users
    home = Path(f"/home/{victim}")
    private = home / "private.txt"
    private.write_bytes(SECRET)
    prog = home / "plate.aidl"
    prog.write_text(PROGRAM)
    for p in (private, prog):
        shutil.chown(p, victim, victim)
    os.chmod(private, 0o600)
    out = shared / "out.svg"

    # the attacker plants shared/out.svg -> the victim's private file
    assert run_as(attacker, "ln", "-s", str(private), str(out)).returncode == 0
    r = render_as(victim, prog, out)
    assert r.returncode == 2 and "is a symbolic link" in r.stderr
    assert private.read_bytes() == SECRET and os.path.islink(out)
    # even when the victim asks to follow links: refused (fs.protected_symlinks' rule)
    r = render_as(victim, prog, out, "--follow-symlinks")
    assert r.returncode == 1 and "another user" in r.stderr and "shared folder" in r.stderr
    assert private.read_bytes() == SECRET and os.path.islink(out)

    # the victim's own link in a folder of their own: written through when asked
    mine = home / "out"
    mine.mkdir()
    target = mine / "real.svg"
    target.write_text("old")
    link = mine / "link.svg"
    link.symlink_to(target)
    for p in (mine, target):
        shutil.chown(p, victim, victim)
    owner = pwd.getpwnam(victim)
    os.lchown(link, owner.pw_uid, owner.pw_gid)
    assert render_as(victim, prog, link).returncode == 2
    assert target.read_text() == "old"
    r = render_as(victim, prog, link, "--follow-symlinks")
    assert r.returncode == 0 and target.read_text().startswith("<svg") and link.is_symlink()

    # a read-only output of the victim's: refused, then replaced with --force (mode kept)
    ro = home / "ro.svg"
    ro.write_text("keep")
    shutil.chown(ro, victim, victim)
    os.chmod(ro, 0o444)
    r = render_as(victim, prog, ro)
    assert r.returncode == 1 and "read-only (mode 0444)" in r.stderr and ro.read_text() == "keep"
    r = render_as(victim, prog, ro, "--force")
    assert r.returncode == 0 and ro.read_text().startswith("<svg")
    assert oct(ro.stat().st_mode & 0o777) == "0o444"
