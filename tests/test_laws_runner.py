"""The laws' corpus and runner (issue 109, benchmarks/laws/, docs/laws.md).

The corpus: every kind there (examples, the gallery at its defaults, slider ends and bools
flipped, the stdlib templates, the `aidl docs` examples, the model and maker runs, the test
fixtures), at least 1,000 programs, names unique and stable, a sample spread over the kinds
and the same each time; a gallery slider end that moves another param's range is settled as
the studio's form settles it.  The runner: a fake law that holds, is violated, crashes, is
not applicable (both ways), runs out of CPU time and kills its worker, each counted and named;
in this process and in a forked worker; `law_compiles` through the command line on a sample.
(~8 s CPU.)"""
import json
import os
import re

import pytest

from benchmarks.laws import corpus, law_compiles, run
from benchmarks.laws.common import NotApplicable
from benchmarks.laws.corpus import Entry

STATIC_KINDS = [k for k in corpus.KINDS if k != "generated"]


@pytest.fixture(scope="module")
def names():
    return corpus.names()


def test_the_corpus_has_every_kind_and_at_least_1000_programs(names):
    kinds = {k: [] for k in STATIC_KINDS}
    for e in corpus._all(tuple(STATIC_KINDS)):
        kinds[e.kind].append(e.name)
    assert all(kinds[k] for k in STATIC_KINDS), {k: len(v) for k, v in kinds.items()}
    assert sum(len(v) for v in kinds.values()) == len(names) >= 1000
    assert len(set(names)) == len(names)
    for n in ("examples/gear.aidl", "examples/generators/dovetail.aidl",
              "gallery/example/telephone", "gallery/example/bracket@bolts=10",
              "gallery/generator/washer@outer=2.5mm", "stdlib/joints.aidl#finger_box",
              "docs/topic/Circle", "model_runs/issue105/run/02_jar_lid.aidl",
              "maker_runs/issue103b/work/bolt_plate/bolt_plate.aidl",
              "tests/programs/hostile/nan_radius.aidl"):
        assert n in names, n
    assert any(re.fullmatch(r"README\.md:\d+", n) for n in kinds["docs"])
    assert sum(n.startswith("docs/language.md:") for n in kinds["docs"]) >= 20
    # the gallery: each design at its defaults and at both ends of every numeric slider
    gallery = kinds["gallery"]
    assert sum("@" not in n for n in gallery) >= 40
    assert sum("@" in n for n in gallery) >= 350
    assert [n for n in gallery if n.startswith("gallery/example/bracket@bolts=")] == \
        ["gallery/example/bracket@bolts=1", "gallery/example/bracket@bolts=10"]


def test_identical_programs_are_counted_once(names):
    entries = list(corpus._all(tuple(STATIC_KINDS)))
    assert len({corpus._key(e) for e in entries}) == len(entries)
    # a final program the model left as it first compiled is one entry, not two
    jar = "model_runs/issue105/run/02_jar_lid"
    a, b = [(corpus.DATA / (jar + s)).read_text() for s in (".aidl", ".first_valid.aidl")]
    assert (f"{jar}.aidl" in names) + (f"{jar}.first_valid.aidl" in names) == (2 if a != b else 1)


def test_a_sample_is_spread_over_the_kinds_and_the_same_each_time():
    a = [e.name for e in corpus.iter_corpus(sample=14)]
    assert a == [e.name for e in corpus.iter_corpus(sample=14)]
    assert len(a) == 14 and len(set(a)) == 14
    assert {n.split("/")[0] for n in a} >= {"examples", "gallery", "stdlib", "docs",
                                             "model_runs", "maker_runs", "tests"}
    assert corpus.spread(list(range(10)), 5, kind=lambda i: "x") == [0, 2, 4, 6, 8]
    assert corpus.spread(list(range(4)), 9, kind=lambda i: "x") == [0, 1, 2, 3]


def test_a_slider_end_that_moves_another_range_is_settled_as_the_form_does():
    """The washer's `inner` has `max = outer - ...`: at outer's slider minimum (2.5 mm) the
    studio moves inner into its range; the corpus entry carries that move and compiles."""
    name = "gallery/generator/washer@outer=2.5mm"
    e = next(x for x in corpus._all(tuple(STATIC_KINDS)) if x.name == name)
    assert e.overrides == {"outer": "2.5 mm"}
    bare = corpus.compile_entry(e)
    assert not bare.ok and "E0124" in {d.code for d in bare.errors}
    s = corpus.settled(e, corpus._TO_SETTLE[name])
    assert s.name == name and s.overrides["outer"] == "2.5 mm"
    inner = float(s.overrides["inner"].split()[0])
    assert 0 < inner < 2.5
    assert corpus.compile_entry(s).ok


# ------------------------------------------------------------------------ the runner
def _entries():
    src = "solid p {\n    r = Rectangle(center=(0, 0), width=10, height=5)\n}\n"
    return [Entry(f"fake/{w}", src, "/nonexistent/main.aidl", {}, "tests")
            for w in ("good", "bad", "boom", "skip", "refuse", "slow")]


class FakeLaw:
    NAME = "a fake law that sees each way a check can end"
    TOLERANCE = "none"

    @staticmethod
    def applies(entry):
        return not entry.name.endswith("skip")

    @staticmethod
    def check(entry):
        what = entry.name.rsplit("/", 1)[-1]
        if what == "bad":
            return ["the part is 3 mm too wide", "and one more"]
        if what == "boom":
            raise ValueError("boom at 4.5 mm")
        if what == "refuse":
            raise NotApplicable("no machine output")
        if what == "slow":
            while True:          # CPU until the runner's timer ends it
                pass
        if what == "die":
            os._exit(3)
        return []

    @staticmethod
    def generated(n):
        for i in range(n):
            yield Entry(f"generated/fake/{i}", "units mm\n", "/nonexistent/main.aidl", {},
                        "generated")


class Holds:
    NAME = "a law that always holds"

    @staticmethod
    def check(entry):
        return []


def _judge(rep):
    r, h = rep.laws
    # the second law runs on every program, after the first timed out or killed its worker
    assert h.counts["held"] == sum(rep.corpus.values())
    assert h.checked == h.counts["held"] and not h.failed and not h.timed_out
    return r, {n: (s, line) for n, s, line in r.failed}


@pytest.mark.parametrize("jobs", [0, 1])
def test_the_runner_counts_and_names_each_way_a_check_ends(jobs):
    entries = _entries()
    if jobs:
        entries.insert(3, Entry("fake/die", "", "/nonexistent/main.aidl", {}, "tests"))
    rep = run.run([run.Law.of(FakeLaw, "fake"), run.Law.of(Holds, "holds")], entries,
                  jobs=jobs, timeout=0.3, generated=2)
    r, failed = _judge(rep)
    assert r.counts["held"] == 3                      # good + the two generated
    assert r.counts["not applicable"] == 2            # skip (applies) + refuse (raised)
    assert r.counts["timed out"] == 1 and r.timed_out[0][0] == "fake/slow"
    assert failed["fake/bad"] == ("violated", "the part is 3 mm too wide")
    assert failed["fake/boom"] == ("crashed", "ValueError: boom at 4.5 mm")
    assert r.generated == 2 and rep.generated == 2
    assert r.checked == r.counts["held"] + len(failed)
    if jobs:       # a worker that died: a crash of the law, the next program in a new worker
        assert failed["fake/die"] == ("crashed", "the worker process died (exit code 3)")
        assert list(failed) == ["fake/bad", "fake/boom", "fake/die"]
    else:
        assert list(failed) == ["fake/bad", "fake/boom"]
    assert not rep.ok
    text = rep.text()
    assert "FAILED fake/bad: the part is 3 mm too wide" in text
    assert "FAILED fake/boom: crashed: ValueError: boom at 4.5 mm" in text
    assert "timed out (skipped) fake/slow: more than 0.3 s of CPU" in text
    assert f"corpus: {len(entries)} programs (tests {len(entries)}) + 2 generated" in text
    j = rep.to_json()
    assert j["laws"][1]["held"] == len(entries)
    assert j["laws"][0]["held"] == 3 and j["laws"][0]["by_kind"]["generated"]["held"] == 2
    assert [f["program"] for f in j["laws"][0]["failed"]] == list(failed)


def test_law_compiles_from_the_command_line_on_a_sample(tmp_path, capsys):
    out = tmp_path / "report.json"
    code = run.main(["--law", "compiles", "--sample", "7", "--generated", "0", "--jobs", "0", "--quiet",
                     "--json", str(out)])
    text = capsys.readouterr().out
    rep = json.loads(out.read_text())
    (law,) = rep["laws"]
    assert rep["corpus"]["programs"] == 7 and len(rep["corpus"]["by_kind"]) == 7
    assert law["law"] == "compiles" and law["failed"] == [] and code == 0, text
    assert law["held"] + law["not_applicable"] == 7 and law["held"] >= 5
    assert "law compiles: every program in the corpus that the project ships compiles" in text
    with pytest.raises(SystemExit):
        run.main(["--law", "no_such_law"])


def test_law_compiles_names_the_error_and_skips_what_is_meant_to_fail():
    entries = {e.name: e for e in corpus._all(tuple(STATIC_KINDS))}
    hostile = entries["tests/programs/hostile/nan_radius.aidl"]
    assert "expects E" in corpus.meant_to_fail(hostile) and not law_compiles.applies(hostile)
    language = corpus.ROOT / "docs" / "language.md"
    marked = [n for n, _, x in corpus.aidl_blocks(language) if any(c[0] == "E" for c in x)]
    clean = [n for n, _, x in corpus.aidl_blocks(language) if not x]
    assert marked and len(clean) >= 20
    assert not law_compiles.applies(entries[f"docs/language.md:{marked[0]}"])
    assert law_compiles.applies(entries[f"docs/language.md:{clean[0]}"])
    assert law_compiles.applies(entries["model_runs/issue73/fixed/e04_cable_organiser.aidl"])
    assert not law_compiles.applies(entries["model_runs/issue73/programs/e04_cable_organiser.aidl"])
    attempt = Entry("model_runs/x/work/01_a.attempt1.aidl", "", "x.aidl", {}, "model_runs")
    assert not law_compiles.applies(attempt)
    bad = Entry("examples/bad.aidl", "solid p {\n    c = Circle(center=(0, 0), radius=w)\n}\n",
                str(corpus.ROOT / "examples" / "bad.aidl"), {}, "examples")
    assert law_compiles.applies(bad)
    (line,) = law_compiles.check(bad)
    assert line.startswith("E0") and " 2:" in line and "`w`" in line


def test_law_compiles_generates_the_same_gallery_combinations_each_run():
    a = list(law_compiles.generated(3))
    assert [e.name for e in a] == [e.name for e in law_compiles.generated(3)] == [
        "generated/gallery/000:example/bottle_opener", "generated/gallery/001:example/bracket",
        "generated/gallery/002:example/cake_topper"]
    assert [e.overrides for e in a] == [e.overrides for e in law_compiles.generated(3)]
    assert {e.kind for e in a} == {"generated"}
    assert set(a[1].overrides) == {"bolts", "pitch", "fillet"}
    assert law_compiles.check(a[1]) == []
