"""One answer on every machine (issue 101): budgets are work units counted from the program,
not seconds.  The same program at the same budget spends the same work and gets the same
answer, the same message and the same output on a quiet machine, a busy one and a slower one
(``AIDL_CPU_SCALE=3`` counts every CPU reading three times, as a machine three times slower
would); CPU seconds are only the far backstop (``limits.BACKSTOP``).

Every figure here is a count: work units, points judged, bytes of a program; nothing reads a
clock."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from aidl_lang.base.limits import DEFAULT_BUDGET, Work, budget_factor_text

ROOT = Path(__file__).resolve().parent.parent
AIDL = [sys.executable, "-m", "aidl_lang.cli"]


def _aidl(args, cwd, scale: str | None = None, timeout: int = 600):
    env = dict(os.environ)
    env.pop("AIDL_CPU_SCALE", None)
    if scale is not None:
        env["AIDL_CPU_SCALE"] = scale
    return subprocess.run(AIDL + list(args), capture_output=True, text=True, cwd=cwd,
                          env=env, timeout=timeout)


def _hogs(n: int = 2):
    return [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(n)]


@pytest.mark.timing
def test_the_telephones_work_is_the_same_alone_beside_two_busy_loops_and_three_times_slower(
        tmp_path):
    """The issue's done-when: ``aidl check --json examples/telephone.aidl`` gives the same
    ``work``, stage by stage, alone, beside two busy loops and with ``AIDL_CPU_SCALE=3``."""
    tel = str(ROOT / "examples" / "telephone.aidl")
    alone = _aidl(["check", "--json", tel], tmp_path)
    assert alone.returncode == 0, alone.stderr
    work = json.loads(alone.stdout)["work"]
    assert work["budget"] == 2_000_000 and 0 < work["spent"] < work["budget"]
    assert set(work["stages"]) >= {"interpreting", "solving", "the booleans",
                                   "the shape checks"}
    assert sum(work["stages"].values()) <= work["spent"] <= sum(work["stages"].values()) + 4
    hogs = _hogs()
    try:
        busy = _aidl(["check", "--json", tel], tmp_path)
    finally:
        for h in hogs:
            h.kill()
            h.wait()
    slow = _aidl(["check", "--json", tel], tmp_path, scale="3")
    assert json.loads(busy.stdout)["work"] == work
    assert json.loads(slow.stdout)["work"] == work


MANY = """units mm
solid plate {
    body = Rectangle(center=(0, 0), width=400, height=400)
    for i in range(30) {
        for j in range(30) {
            hole h { c = Circle(center=(i * 12 + (j % 2) * 6 - 180, j * 7 - 100), radius=4) }
        }
    }
}
"""


def test_a_program_past_its_work_gets_the_same_e0304_every_run_naming_the_units(tmp_path):
    """900 holes at `--budget 0.03` (60,000 units): the booleans need more; the E0304 names the
    stage, the structure, the units needed, the budget and the `--budget` that would do, the
    same text in two runs and with the CPU readings tripled.  The holes are staggered: their
    boxes meet, so they unite in groups of 16, then the groups (issue 110: a hole's own face
    is no union, so the square grid of 900 holes apart of before fits in 48,401 units, and
    holes apart never run out of work in the booleans: their one union is priced by its
    vertices, which the vertex budget holds under 70 % of the work)."""
    f = tmp_path / "many.aidl"
    f.write_text(MANY)
    runs = [_aidl(["check", "--json", "--budget", "0.03", str(f)], tmp_path, scale=k)
            for k in (None, None, "3")]
    docs = [json.loads(r.stdout) for r in runs]
    texts = [[(d["code"], d["message"], d.get("hint")) for d in doc["diagnostics"]]
             for doc in docs]
    assert texts[0] == texts[1] == texts[2]
    [(code, message, hint)] = texts[0]
    assert code == "E0304"
    assert message.startswith("the program ran out of its evaluation budget in the booleans "
                              "of `plate`: it needs more than ")
    assert message.endswith("work units, past its budget of 60,000")
    need = int(message.split("more than ")[1].split(" work")[0].replace(",", ""))
    assert need > 60_000
    assert f"`{budget_factor_text(need, DEFAULT_BUDGET)}`" in hint
    # the factor it names covers what was needed when it ran out (what the next groups and
    # the stages after it need is not known yet: "or more"): following the hints, each
    # budget past the need said before, the program compiles
    k = budget_factor_text(need, DEFAULT_BUDGET).split()[1]
    for _ in range(8):
        assert float(k) * DEFAULT_BUDGET.work > need
        doc = json.loads(_aidl(["check", "--json", "--budget", k, str(f)], tmp_path).stdout)
        if doc["ok"]:
            break
        [d] = [d for d in doc["diagnostics"] if d["code"] == "E0304"]
        need = int(d["message"].split("more than ")[1].split(" work")[0].replace(",", ""))
        k = d["hint"].split("`--budget ")[1].split("`")[0]
    assert doc["ok"], doc
    assert docs[0]["work"] == docs[1]["work"] == docs[2]["work"]


def test_budget_factor_text_rounds_up_to_two_digits_with_room():
    w = DEFAULT_BUDGET.work
    assert budget_factor_text(72_145, DEFAULT_BUDGET) == "--budget 0.038"
    assert budget_factor_text(w + 1, DEFAULT_BUDGET) == "--budget 1.1"
    assert budget_factor_text(27 * w // 2, DEFAULT_BUDGET) == "--budget 15"
    for need in (1_000, 99_999, 2_000_000, 3_333_333, 123_456_789):
        k = float(budget_factor_text(need, DEFAULT_BUDGET).split()[1])
        assert need <= k * w <= need * 1.25


def test_a_work_meter_refuses_the_step_that_would_pass_it_and_spends_nothing_then():
    w = Work(100)
    w.spend(60, "the booleans")
    with pytest.raises(Exception) as e:
        w.spend(41, "the shape checks", "plate")
    assert e.value.stage == "the shape checks" and e.value.where == "plate"
    assert e.value.work == 101 and w.spent == 60
    w.add(50, "solving")                # counted, not refused: the next spend is
    with pytest.raises(Exception):
        w.spend(0, "the writers")
    assert w.to_json() == {"spent": 110, "budget": 100,
                           "stages": {"the booleans": 60, "solving": 50}}


def _panel(nx: int, ny: int) -> str:
    return f"""param pitch = 4 mm, min = 2 mm, max = 6 mm
param cols = {nx}
param rows = {ny}

solid panel {{
    body = Rectangle(center=(0, 0), width=cols * pitch + 2 mm, height=rows * pitch + 2 mm)
    for i in range(cols) {{
        for j in range(rows) {{
            hole h {{ c = Circle(center=((1 - cols) / 2 * pitch + i * pitch,
                                        (1 - rows) / 2 * pitch + j * pitch), diameter=2.4 mm) }}
        }}
    }}
}}
"""


def test_a_panels_sweep_calls_no_param_clean_that_it_did_not_judge(tmp_path):
    """The issue's 8,000-hole panel in small (2,000 holes at `--budget 0.15`: the same ratio
    of a point's work to the sweep's; 0.25 before issue 110 made a hole's own face no union,
    79,757 units a point now): its first points cost more than the sweep's work, so
    no param is judged off its written value; none is called clean, none bisected, each said
    not judged; the same lines with the CPU readings tripled."""
    import aidl_lang
    f = tmp_path / "panel.aidl"
    f.write_text(_panel(50, 40))
    rep = aidl_lang.compile(path=str(f), budget=0.15).sweep(budget=0.15)
    sw = rep.to_json()
    assert sw["swept"] == ["pitch", "cols", "rows"]
    unjudged = [n for n in sw["swept"] if not sw["judged"].get(n)]
    assert unjudged, sw                                   # the budget ran out before any
    for n in unjudged:
        assert any(line.startswith(f"`{n}`") and "no value but the written one judged" in line
                   for line in sw["not_judged"]), sw["not_judged"]
    text = rep.text()
    first = text.split("\n")[0]
    assert "clean" not in first and "no finding in the points judged" in first, text
    for line in text.split("\n")[1:]:
        assert not any(line.startswith(f"sweep: `{n}` (no declared range") and "clean" in line
                       for n in unjudged), text
    if not sw["bisections"]:
        assert "bisected" not in text, text
    # the sweep's work is what stopped it: at most its budget and one point's compile past it
    assert sw["work"] <= 0.15 * (600_000 + 2_000_000), sw["work"]
    slow = _aidl(["check", "--sweep", "--json", "--budget", "0.15", str(f)], tmp_path,
                 scale="3")
    assert json.loads(slow.stdout)["sweep"] == json.loads(json.dumps(sw))


def _board_svg(n: int) -> str:
    """A board of ``n`` x ``n`` square pieces 10 mm wide, each with a round hole and a
    wavy hole of ten quadratic curves: irregular, curved, side by side."""
    import math
    out = []
    for i in range(n):
        for j in range(n):
            x, y = i * 12, j * 12
            out.append(f'<rect x="{x}" y="{y}" width="10" height="10" fill="none" '
                       'stroke="black"/>')
            out.append(f'<circle cx="{x + 3}" cy="{y + 3}" r="1.2" fill="none" stroke="black"/>')
            cx, cy = x + 6.5, y + 6.5
            d = f"M {cx + 2} {cy} " + " ".join(
                f"Q {cx + 1.5 * math.cos(a + 0.3):.3f} {cy + 1.5 * math.sin(a + 0.3):.3f} "
                f"{cx + 2 * math.cos(a + 0.6):.3f} {cy + 2 * math.sin(a + 0.6):.3f}"
                for a in (k * 0.6 for k in range(10))) + " Z"
            out.append(f'<path d="{d}" fill="none" stroke="black"/>')
    side = n * 12
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{side}mm" height="{side}mm" '
            f'viewBox="0 0 {side} {side}">' + "".join(out) + "</svg>")


def test_a_drawing_imports_three_times_to_the_same_program_and_work_three_times_slower(
        tmp_path):
    """The issue's RoyalGame done-when, on a board of 12 x 12 pieces made here: imported as
    parts three times with ``AIDL_CPU_SCALE=3``, the same program and the same work each time,
    and at a budget too small the same E0304 naming its work units."""
    (tmp_path / "board.svg").write_text(_board_svg(12))
    outs, works = [], []
    for k in range(3):
        r = _aidl(["import", "--json", "--parts", "--roles", "laser", "board.svg", "-o",
                   f"b{k}.aidl"], tmp_path, scale="3")
        doc = json.loads(r.stdout)
        assert doc["ok"], (r.stdout, r.stderr)
        outs.append((tmp_path / f"b{k}.aidl").read_text())
        works.append(doc["work"])
    assert outs[0] == outs[1] == outs[2] and works[0] == works[1] == works[2]
    assert {"reading the drawing", "finding where the loops cross themselves"} <= set(
        works[0]["stages"]), works[0]
    small = [_aidl(["import", "--json", "--parts", "--budget", "0.005", "board.svg", "-o",
                    "s.aidl"], tmp_path, scale=k) for k in (None, "3")]
    docs = [json.loads(r.stdout) for r in small]
    assert docs[0] == docs[1]
    [d] = docs[0]["diagnostics"]
    assert d["code"] == "E0304" and "work units, past its budget of 10,000" in d["message"]
    assert "--budget" in d["hint"] and not (tmp_path / "s.aidl").exists()
