"""Issue 72, speed: a slider move reuses what it can and still draws exactly what a cold
compile of the same values draws; the fit check decides stacked and separated plates in 2D
with the same answers as the 3D booleans; gallery pictures are made once for every server of
one build (a disk cache), counted in compiles, not timed."""
from __future__ import annotations

import tempfile
from collections import OrderedDict

import pytest

from aidl_lang.studio import gallery
from aidl_lang.studio.compiler import handler



@pytest.fixture(scope="module")
def handle():
    return handler()


def _cold(handle, source, values):
    """The picture of ``values`` from a session that never drew anything before."""
    with tempfile.TemporaryDirectory() as folder:
        answer = handle(("view", "cold-" + folder, folder, source, values))
        handle.idle()               # as the worker does after each answer
        return answer


@pytest.mark.parametrize("eid,moves", [
    ("example/gear_pair", [{"pinion_teeth": "8"}]),
    ("generator/lid_box", [{"length": "150 mm"}, {"length": "150 mm", "outside": "true"}]),
])
def test_a_warm_slider_move_draws_what_a_cold_compile_draws(handle, eid, moves):
    e = gallery.entry(eid)
    with tempfile.TemporaryDirectory() as folder:
        first = handle(("view", "warm", folder, e.source, {}))
        handle.idle()
        assert first["ok"] and first["svg"]
        for values in moves:
            warm = handle(("view", "warm", folder, e.source, values))
            handle.idle()               # as the worker does after sending the answer
            cold = _cold(handle, e.source, values)
            assert warm["ok"] and cold["ok"], (values, warm["diagnostics"])
            assert warm["values"] == cold["values"] == values
            assert warm["svg"] == cold["svg"] != first["svg"]       # byte for byte
            assert [d["code"] for d in warm["diagnostics"]] == \
                [d["code"] for d in cold["diagnostics"]]
            assert [(p["name"], p["value"], p["default"]) for p in warm["params"]] == \
                [(p["name"], p["value"], p["default"]) for p in cold["params"]]


class _Counted:
    """A Manifold that counts the 3D intersections asked of it."""
    made = 0

    def __init__(self, m):
        self.m = m

    def __xor__(self, other):
        _Counted.made += 1
        return self.m ^ other.m

    def min_gap(self, other, limit):
        return self.m.min_gap(other.m, limit)

    def bounding_box(self):
        return self.m.bounding_box()

    def num_vert(self):
        return self.m.num_vert()


# plates stacked flush (moved, turned 30 deg, flipped over), a wall stood up (not parallel),
# one lifted 0.05 mm (not flush) and one sunk 2 mm into the base (a collision)
STACK = """units mm
thickness 3 mm
assembly kit {
    solid base { r = Rectangle(center=(0, 0), width=60, height=40) }
    solid lid { r = Rectangle(center=(100, 0), width=30, height=20) }
    solid turned { r = Rectangle(center=(200, 0), width=30, height=8) }
    solid flipped { c = Circle(center=(300, 0), radius=6) }
    solid wall { r = Rectangle(center=(400, 15), width=60, height=30) }
    solid lifted { c = Circle(center=(500, 0), radius=5) }
    solid sunk { c = Circle(center=(600, 0), radius=4) }
    Place(lid, position=(-100, 0, 3))
    Place(turned, rotation=(0, 0, 30 deg), position=(-173.20508075688772, -100, 3))
    Place(flipped, rotation=(180 deg, 0, 0), position=(-290, 5, 9))
    Place(wall, rotation=(90 deg, 0, 0), position=(-400, 20, 3))
    Place(lifted, position=(-520, 0, 3.05))
    Place(sunk, position=(-620, 0, 1))
}
"""


def test_the_fit_check_decides_stacked_plates_in_2d_with_the_3d_answer():
    from aidl_lang import api
    from aidl_lang.output.fabrication import assembly as A
    r = api.compile(source=STACK)
    assert r.ok
    said = sorted((d.code, d.message.split(":")[0]) for d in r.diagnostics)
    assert said == [("W0517", "assembled, parts `kit.base` and `kit.sunk` collide"),
                    ("W0517", "assembled, parts `kit.lid` and `kit.turned` collide"),
                    ("W0517", "assembled, parts `kit.lifted` and `kit.sunk` collide")]
    d = r.output.drawing
    parts = [(p.name, p.kind, p.shape, d.thickness.get(p.name)) for p in d.parts]
    bodies = A.extrude(parts, d.placement)
    normals = A.normals_of(d.placement)
    _Counted.made = 0
    old = A.fit([(n, _Counted(m)) for n, m in bodies], None, normals)
    in_3d = _Counted.made
    counts: dict = {}
    new = A.fit(bodies, None, normals, A.plates_of(parts, d.placement), counts=counts)
    # the same collisions (a plate cut to a pair's box: the same volume to the last digits)
    assert [(c.a, c.b) for c in new[0]] == [(c.a, c.b) for c in old[0]] and len(old[0]) == 3
    for c, o in zip(new[0], old[0]):
        assert (c.volume, c.depth) == pytest.approx((o.volume, o.depth), rel=1e-12, abs=1e-12)
        assert c.box == pytest.approx(o.box, abs=1e-9)
    assert new[1] == old[1] == []
    assert [c.depth for c in old[0]] == pytest.approx([2.0, 3.0, 0.95], abs=1e-6)
    # 11 pairs of boxes; base-lid, base-turned, lid-flipped and turned-flipped are flush
    # faces over a common area: decided in 2D; the other 7 in 3D, as before (each pair of
    # plates cut to its common box first when that is a small part of a plate)
    assert (in_3d, counts["booleans"]) == (11, 7)


# ---------------------------------------------------------------- gallery pictures, once
CHEAP = ["generator/washer", "generator/rounded_plate"]


def _server(tmp_path, made):
    pytest.importorskip("starlette")
    pytest.importorskip("limits")
    from aidl_lang.studio import compiler
    from aidl_lang.studio.app import Settings, create_app
    app = create_app(Settings(data=str(tmp_path / "data"), compilers=1))

    def request(req, seconds, wait=None, prefer=None):      # the worker's answer, in process
        assert req[0] == "thumb"
        made.append(req[1])
        return compiler.thumbnail(*req[1:]), None
    app.state.studio.pool.request = request
    return app


def test_gallery_pictures_are_made_once_for_every_server_of_a_build(tmp_path, monkeypatch):
    from starlette.testclient import TestClient
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    pictures = []
    for round_ in range(3):
        if round_ == 2:         # another build (a new version or an edited checkout)
            monkeypatch.setattr(gallery, "code_fingerprint", lambda: "another build")
        made: list = []
        with TestClient(_server(tmp_path, made)) as c:      # a fresh server each round
            got = []
            for eid in CHEAP + CHEAP:                       # each asked twice
                r = c.get(f"/api/thumb/{eid}.svg")
                assert r.status_code == 200 and r.text.startswith("<svg"), r.text[:200]
                got.append(r.text)
        pictures.append(got)
        # first server: each picture compiled once; the second: none (read from the disk);
        # another build: compiled again
        assert made == ([] if round_ == 1 else CHEAP), (round_, made)
    assert pictures[0] == pictures[1] == pictures[2]
    assert pictures[0][:2] == [gallery.thumbnail(gallery.entry(e)) for e in CHEAP]
    kept = sorted((tmp_path / "cache" / "aidl" / "gallery").iterdir())
    assert len(kept) == 4 and all(p.stat().st_mode & 0o077 == 0 for p in kept)
    # a kept file that was changed (or planted) is not shown: it is made again
    now = gallery._thumb_path(gallery.thumbnail_key(gallery.entry(CHEAP[0])))
    now.write_text(now.read_text().replace("<svg", "<svg data-x='1'", 1))
    made = []
    with TestClient(_server(tmp_path, made)) as c:
        for eid in CHEAP:
            assert "data-x" not in c.get(f"/api/thumb/{eid}.svg").text
    assert made == CHEAP[:1]


def test_a_view_walks_no_old_objects_and_collects_after_its_answer(handle):
    """The cycle collector's older generations wait until the answer is sent (the worker's
    ``idle``): during a lid box move no collection of generation 1 or 2 (with CPython's
    defaults, 700/10/10: several), after it the defaults are back."""
    import gc
    e = gallery.entry("generator/lid_box")
    seen = []

    def note(phase, info):
        if phase == "start":
            seen.append(info["generation"])
    normal = gc.get_threshold()
    with tempfile.TemporaryDirectory() as folder:
        handle(("view", "gc", folder, e.source, {}))
        handle.idle()
        gc.callbacks.append(note)
        try:
            answer = handle(("view", "gc", folder, e.source, {"length": "150 mm"}))
            during = list(seen)
            handle.idle()
        finally:
            gc.callbacks.remove(note)
    assert answer["ok"] and answer["svg"]
    assert [g for g in during if g >= 1] == [] and len(during) <= 3, during
    assert seen[len(during):][:1] == [1]        # the request's survivors, after the answer
    assert gc.get_threshold() == normal
