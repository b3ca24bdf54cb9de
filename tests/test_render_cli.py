"""`aidl render`: the format by extension, several -o, and file safety (docs/outputs.md,
"Writing files"): never the program itself, no directory, symlinks and read-only files refused unless asked, no
default name for /dev/stdin, the umask's permissions, an existing file's mode kept."""
import io
import os
import stat
import sys

import pytest

from aidl_lang.cli.main import main

GOOD = """solid s {
    body = Rectangle(center=(0, 0), width=40, height=30)
    hole h { c = Circle(center=(0, 0), diameter=22 mm) }
}
"""
BAD = "solid s { c = Circel(center=(0, 0), radius=5) }\n"


@pytest.fixture
def good(tmp_path):
    p = tmp_path / "good.aidl"
    p.write_text(GOOD)
    return p


def listing(d):
    return sorted(os.listdir(d))


def test_several_outputs_by_extension(good, tmp_path, capsys):
    import ezdxf
    outs = [tmp_path / f"part.{e}" for e in ("svg", "dxf", "png", "stl", "3mf")]
    args = ["render", str(good)]
    for o in outs:
        args += ["-o", str(o)]
    assert main(args) == 0
    assert all(o.stat().st_size > 0 for o in outs)
    assert outs[0].read_text().startswith("<svg")
    doc = ezdxf.readfile(outs[1])
    (c,) = doc.modelspace().query("CIRCLE")
    assert c.dxf.radius == pytest.approx(11.0, abs=1e-9)
    assert outs[2].read_bytes()[:4] == b"\x89PNG"
    assert len(outs[3].read_bytes()) == 84 + 50 * int.from_bytes(outs[3].read_bytes()[80:84], "little")
    assert capsys.readouterr().out.count("wrote ") == 5


def test_unknown_extension_is_a_usage_error_and_writes_nothing(good, tmp_path, capsys):
    before = listing(tmp_path)
    assert main(["render", str(good), "-o", str(tmp_path / "a.svg"),
                 "-o", str(tmp_path / "b.ps")]) == 2
    assert "cannot tell the format of" in capsys.readouterr().err
    assert listing(tmp_path) == before


def test_failed_compile_writes_none_of_the_outputs(good, tmp_path):
    a, b = tmp_path / "a.svg", tmp_path / "a.dxf"
    assert main(["render", str(good), "-o", str(a), "-o", str(b)]) == 0
    old = a.read_bytes(), b.read_bytes()
    bad = tmp_path / "bad.aidl"
    bad.write_text(BAD)
    assert main(["render", str(bad), "-o", str(a), "-o", str(b)]) == 1
    assert (a.read_bytes(), b.read_bytes()) == old


def test_never_overwrites_the_program(tmp_path, capsys):
    prog = tmp_path / "prog.svg"               # a program that happens to be named .svg
    prog.write_text(GOOD)
    assert main(["render", str(prog)]) == 2
    assert "is the program itself" in capsys.readouterr().err
    assert prog.read_text() == GOOD
    assert main(["render", str(prog), "-o", str(prog)]) == 2
    assert "refusing to overwrite" in capsys.readouterr().err
    assert prog.read_text() == GOOD and listing(tmp_path) == ["prog.svg"]
    p2 = tmp_path / "x.aidl"
    p2.write_text(GOOD)
    assert main(["render", str(p2), "-o", str(p2)]) == 2
    assert p2.read_text() == GOOD


def test_directory_output_is_a_clear_error_and_leaves_no_tmp_file(good, tmp_path, capsys):
    d = tmp_path / "out"
    d.mkdir()
    assert main(["render", str(good), "-o", str(d)]) == 2
    assert "is a directory" in capsys.readouterr().err
    assert listing(d) == [] and listing(tmp_path) == ["good.aidl", "out"]


def test_symlink_is_refused_unless_followed(good, tmp_path, capsys):
    """An output that is a symbolic link (planted to make the render overwrite another file)
    is refused, exit 2, its target untouched; with --follow-symlinks the target is written
    and the link kept."""
    target = tmp_path / "real.svg"
    target.write_text("old")
    link = tmp_path / "link.svg"
    link.symlink_to(target.name)
    assert main(["render", str(good), "-o", str(link)]) == 2
    err = capsys.readouterr().err
    assert "is a symbolic link" in err and "--follow-symlinks" in err
    assert target.read_text() == "old" and link.is_symlink()
    dangling = tmp_path / "dangling.svg"
    dangling.symlink_to("nowhere/x.svg")
    assert main(["render", str(good), "-o", str(dangling)]) == 2
    assert main(["render", str(good), "-o", str(link), "--follow-symlinks"]) == 0
    assert link.is_symlink() and os.readlink(link) == "real.svg"
    assert target.read_text().startswith("<svg")
    assert listing(tmp_path) == ["dangling.svg", "good.aidl", "link.svg", "real.svg"]


def test_a_link_planted_after_the_check_is_replaced_not_followed(good, tmp_path, monkeypatch):
    """The write replaces the output path itself (temp file + os.replace): a link that
    appears between the check and the write is replaced; the file it points to stays."""
    M = sys.modules["aidl_lang.cli.main"]
    victim = tmp_path / "victim.txt"
    victim.write_text("precious")
    out = tmp_path / "o.svg"
    real = M._write_all

    def plant(items, follow=False):
        out.symlink_to(victim.name)
        return real(items, follow)
    monkeypatch.setattr(M, "_write_all", plant)
    assert main(["render", str(good), "-o", str(out)]) == 0
    assert victim.read_text() == "precious"
    assert not out.is_symlink() and out.read_text().startswith("<svg")


def test_read_only_output_is_refused_unless_forced(good, tmp_path, capsys):
    out = tmp_path / "ro.svg"
    out.write_text("old")
    os.chmod(out, 0o444)
    assert main(["render", str(good), "-o", str(out)]) == 1
    err = capsys.readouterr().err
    assert "is read-only (mode 0444)" in err and "--force" in err
    assert out.read_text() == "old"
    assert main(["render", str(good), "-o", str(out), "--force"]) == 0
    assert out.read_text().startswith("<svg")
    assert stat.S_IMODE(out.stat().st_mode) == 0o444          # replaced, its mode kept
    assert listing(tmp_path) == ["good.aidl", "ro.svg"]


def test_dev_stdin_needs_an_output_name(good, tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(sys, "stdin", io.StringIO(GOOD))
    assert main(["render", "/dev/stdin"]) == 2
    assert "no default output name" in capsys.readouterr().err
    assert not os.path.exists("/dev/stdin.svg")
    out = tmp_path / "s.svg"
    assert main(["render", "-", "-o", str(out)]) == 0 and out.exists()


def test_new_files_follow_the_umask_and_existing_files_keep_their_mode(good, tmp_path):
    old = os.umask(0o022)
    try:
        a = tmp_path / "a.svg"
        assert main(["render", str(good), "-o", str(a)]) == 0
        assert stat.S_IMODE(a.stat().st_mode) == 0o644
        os.umask(0o077)
        b = tmp_path / "b.dxf"
        assert main(["render", str(good), "-o", str(b)]) == 0
        assert stat.S_IMODE(b.stat().st_mode) == 0o600
        os.chmod(a, 0o664)
        assert main(["render", str(good), "-o", str(a)]) == 0
        assert stat.S_IMODE(a.stat().st_mode) == 0o664
    finally:
        os.umask(old)


def test_show_and_thickness_options(good, tmp_path, capsys):
    import trimesh
    svg, stl = tmp_path / "d.svg", tmp_path / "t.stl"
    assert main(["render", str(good), "-o", str(svg), "--show", "holes,bboxes",
                 "-o", str(stl), "--thickness", "0.25in"]) == 0
    assert 'id="holes"' in svg.read_text() and 'id="bboxes"' in svg.read_text()
    m = trimesh.load(stl)
    assert m.bounds[1][2] == pytest.approx(6.35)
    assert main(["render", str(good), "-o", str(svg), "--show", "nope"]) == 2
    assert main(["render", str(good), "-o", str(stl), "--thickness", "-1"]) == 2


def test_margin_option(good, tmp_path, capsys):
    import svgelements as se
    svg = tmp_path / "m.svg"
    assert main(["render", str(good), "-o", str(svg), "--margin", "0"]) == 0
    mm = float(se.Length("1mm").value(ppi=96))          # svgelements' pixels per mm
    doc = se.SVG.parse(str(svg))
    assert (doc.width / mm, doc.height / mm) == pytest.approx((40, 30), abs=1e-6)
    assert main(["render", str(good), "-o", str(svg), "--margin", "3.5"]) == 0
    assert se.SVG.parse(str(svg)).width / mm == pytest.approx(47, abs=1e-6)
    capsys.readouterr()
    for bad in ("-1", "nan", "1e9"):
        assert main(["render", str(good), "-o", str(tmp_path / "n.svg"), "--margin", bad]) == 2
        assert "--margin expects a length in mm" in capsys.readouterr().err
    assert not (tmp_path / "n.svg").exists()


@pytest.mark.parametrize("opt,msg", [(["--dpi", "-3"], "positive --dpi"),
                                     (["--png-width", "0"], "positive --png-width"),
                                     (["--dpi", "100000"], "more than 32767 a side"),
                                     (["--png-width", "50000"], "more than 32767 a side")])
def test_impossible_png_size_is_a_clear_error_and_writes_nothing(good, tmp_path, capsys, opt, msg):
    pytest.importorskip("cairosvg")
    out, svg = tmp_path / "p.png", tmp_path / "p.svg"
    assert main(["render", str(good), "-o", str(svg), "-o", str(out), *opt]) == 1
    err = capsys.readouterr().err
    assert msg in err and "internal error" not in err
    assert not out.exists() and not svg.exists()


def test_out_of_range_port_and_thickness_are_usage_errors(good, tmp_path, capsys):
    with pytest.raises(SystemExit) as e:
        main(["serve", str(good), "--port", "99999"])
    assert e.value.code == 2 and "--port expects a number from 0 to 65535" in capsys.readouterr().err
    assert main(["render", str(good), "-o", str(tmp_path / "p.stl"), "--thickness", "1e9mm"]) == 2
    assert "--thickness expects a positive length up to 1 km" in capsys.readouterr().err


@pytest.mark.parametrize("module,ext,extra", [("networkx", ".3mf", "mesh"),
                                              ("lxml.etree", ".3mf", "mesh"),
                                              ("cairosvg", ".png", "png"), ("OCP", ".step", "step")])
def test_a_missing_optional_library_exits_2_with_the_install_line(good, tmp_path, capsys,
                                                                  monkeypatch, module, ext, extra):
    monkeypatch.setitem(sys.modules, module, None)        # `import module` raises ImportError
    out, svg = tmp_path / ("p" + ext), tmp_path / "p.svg"
    assert main(["render", str(good), "-o", str(svg), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert f"pip install 'aidl-lang[{extra}]'" in err and "internal error" not in err
    assert not out.exists() and not svg.exists()
