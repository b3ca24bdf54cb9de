"""A router's second operation: the countersinks and counterbores (issue 102; docs/machines.md,
"Countersinks and counterbores").

After every through-cut of the job the router stops for a tool change (``M5``, a comment
naming the tool, ``M0``: GRBL pauses until resumed) and sinks each head:

* a countersink: the profile's V-bit (``v_bit_angle``, 90 deg unless given) plunged at the
  hole's centre to ``D / 2 / tan(v / 2)`` below the top, which leaves a cone of the head's
  diameter ``D`` at the top (of the countersink's own angle when the bit's is the same; a
  note says when not); a cone deeper than the part (W0529) has the tip at the part's
  thickness ``t``, led round a circle of radius ``D / 2 - t tan(v / 2)`` about the centre,
  which leaves the same ``D`` at the top (and the frustum the meshes cut);
* a counterbore: pocketed with the profile's ``pocket_tool`` (its ``tool_diameter`` when 0):
  down ``cut_inner.depth_per_pass`` at a time to the depth, at each depth rings about the
  centre from the middle out, ``0.4`` of the tool's diameter apart, the last with the
  tool's edge on the recess's edge (a whole circle as two half-circles).

The heads come from the strokes of the two styles (the head's circle, moved with its part by
a layout) and their sizes from the booleans' records (:func:`~..part.part.sink_heads`).
"""
from __future__ import annotations

import math

from ..part.part import Arc, Line, Output, sink_heads

SINKS = ("countersink", "counterbore")
STEPOVER = 0.4          # of the pocket tool's diameter: the rings' spacing


def split(output) -> tuple[list, list]:
    """``output``'s engrave strokes: (the others, the heads of countersinks and
    counterbores)."""
    rest, heads = [], []
    for st in output.engrave:
        (heads if st.style in SINKS else rest).append(st)
    return rest, heads


def write(w, m, heads: list, output, thick: dict, default_t: float) -> list[str]:
    """The countersinks and counterbores of ``heads`` (strokes) as router profile ``m``
    sinks them, written through ``w`` (the G-code writer); ``thick``: part name -> mm.
    Returns the notes (what the tools do, what cannot be sunk)."""
    got = sink_heads(Output([], list(heads), output.title, output.drawing))
    notes: list[str] = []
    op = m.operation("cut_inner")
    for kind in SINKS:
        todo = [(c, r) for c, r in got if r.kind == kind]
        if not todo:
            continue
        if kind == "countersink":
            tool = f"a {m.v_bit_angle:g} deg V-bit"
        else:
            tool = f"a {m.pocket_tool or m.tool_diameter:g} mm end mill"
        w.rapid(z=m.safe_height)
        w.out("M5")
        # a new tool sticks out of the collet by another length: the depths below are from
        # the material's top, so Z zero is set again with the new tool (issue 110)
        w.out(f"; tool change: {tool} for the {len(todo)} {kind}{'s' * (len(todo) != 1)}: "
              "put it in, set Z zero on the material's top with it, then resume")
        w.out("M0")
        w.out(f"M3 S{_num(op.spindle)}")
        n_done = 0
        for c, r in todo:
            t = thick.get(r.part) or default_t
            if kind == "countersink":
                v = math.radians(m.v_bit_angle)
                depth = r.diameter / 2 / math.tan(v / 2)
                w.rapid(*c)
                if depth >= t:
                    # the tip at the bottom face, led round a circle: the cone's top is the
                    # head's diameter, as the drawings' circle and the meshes' cone (W0529)
                    rho = r.diameter / 2 - t * math.tan(v / 2)
                    notes.append(f"the {r.diameter:g} mm countersink of `{r.hole}` needs the "
                                 f"V-bit {depth:.3g} mm deep, past the part's {t:g} mm: its "
                                 f"tip led at the part's thickness round a {2 * rho:.4g} mm "
                                 "circle, which leaves the head's diameter at the top")
                    w.plunge(-t, op.plunge)
                    if rho > 1e-9:
                        w.setting(op.speed)
                        w.segment(Line((w.x, w.y), (c[0] + rho, c[1])))
                        w.segment(Arc(c, rho, 0.0, math.pi))
                        w.segment(Arc(c, rho, math.pi, math.pi))
                        w.segment(Line((w.x, w.y), c))
                else:
                    w.plunge(-depth, op.plunge)
                w.rapid(z=m.safe_height)
            else:
                rt = (m.pocket_tool or m.tool_diameter) / 2
                R = r.diameter / 2 - rt
                if R < 0:
                    notes.append(f"the {r.diameter:g} mm counterbore of `{r.hole}` is "
                                 f"narrower than the pocket tool ({2 * rt:g} mm): not cut")
                    continue
                _pocket(w, m, op, c, R, min(r.depth, t), rt)
            n_done += 1
        if n_done:
            angle = {round(math.degrees(r.angle or 0), 6) for _, r in todo if r.angle}
            same = kind != "countersink" or angle <= {round(m.v_bit_angle, 6)}
            notes.append(f"{n_done} {kind}{'s' if n_done != 1 else ''} sunk after the "
                         f"through-cuts with {tool}" + ("" if same else
                         f" (the countersinks are {', '.join(f'{a:g}' for a in sorted(angle))} "
                         "deg: the cone has the bit's angle; set `v_bit_angle`)"))
    return notes


def _pocket(w, m, op, c, R: float, depth: float, rt: float) -> None:
    """A counterbore's pocket at centre ``c``: the tool's centre on rings up to radius ``R``
    (mm), ``depth`` mm deep in passes of ``op.depth_per_pass``."""
    n = max(1, math.ceil(depth / op.depth_per_pass - 1e-9))
    step = STEPOVER * 2 * rt
    rings = []
    k = 1
    while R > 0 and k * step < R - 1e-9:
        rings.append(k * step)
        k += 1
    if R > 0:
        rings.append(R)
    w.rapid(*c)
    for j in range(n):
        w.plunge(-depth * (j + 1) / n, op.plunge)
        w.setting(op.speed)
        for rr in rings:
            w.segment(Line((w.x, w.y), (c[0] + rr, c[1])))
            w.segment(Arc(c, rr, 0.0, math.pi))
            w.segment(Arc(c, rr, math.pi, math.pi))
        w.segment(Line((w.x, w.y), c))
    w.rapid(z=m.safe_height)


def _num(v: float) -> str:
    t = f"{v:.10f}".rstrip("0").rstrip(".")
    return "0" if t in ("-0", "") else t
