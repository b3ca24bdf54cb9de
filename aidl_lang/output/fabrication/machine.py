"""Machine profiles: what a laser, a router or a plotter/vinyl cutter needs to run a drawing
that the drawing itself does not say (docs/machines.md, "Machine profiles").

A profile is a small TOML file (``aidl render --machine FILE``), every key optional::

    kind = "laser"            # laser | router | plotter
    units = "mm"              # mm | inch: the units the machine file is written in
    max_power = 1000          # laser: the S value of full power (GRBL's $30)
    laser_mode = "M4"         # laser: M4 (dynamic power, GRBL's laser mode) or M3 (constant)
    travel_speed = 6000       # mm/min: rapid moves (G0), for the job-time estimate
    tool_diameter = 3.175     # router: the cutter's diameter (mm); the path is offset by half
    safe_height = 5           # router / plotter: z (mm) of travel moves above the top
    tabs = 0                  # holding tabs per outer cut (0: none)
    tab_width = 3             # mm along the cut
    tab_height = 1            # mm of material left standing (router); a laser skips the tab
    lead_in = 0               # mm: start each cut this far off the loop (0: on it)
    relief = "dogbone"        # router: dogbone | tbone | none: the bit run into each inside
                              # corner until its edge touches it (the built-in router: dogbone)
    v_bit_angle = 90          # router: deg, the V-bit that plunges each countersink's cone
    pocket_tool = 0           # router: mm, the end mill that pockets each counterbore (0: the
                              # profile's tool_diameter)

    [engrave]                 # text and drawings
    power = 20                # percent of max_power (laser)
    speed = 3000              # mm/min: the feed (F)
    passes = 1
    [score]                   # open outlines (W0402: lines that close no loop)
    [cut_inner]               # the loops that cut holes out of a part
    [cut_outer]               # the outline that frees a part
    [fill]                    # areas engraved filled (Text(..., font=, fill=true))
    interval = 0.1            # mm between the fill's parallel lines (laser, plotter)
    depth_per_pass = 1.5      # router: mm of depth per pass (the passes follow from thickness)
    plunge = 300              # router: mm/min going down
    spindle = 18000           # router: rpm (S)

An operation's keys not given take the defaults of :data:`DEFAULTS` for the profile's kind.
The program's own ``kerf`` and ``thickness`` keep their meaning; a profile that states them
too (``kerf = ...``, ``thickness = ...``) is compared and a difference is reported by the
writer as a warning. All lengths are millimetres (``units`` is only how the file is written),
speeds mm/min, power percent.  Every number has a range (:data:`RANGES`, :data:`OP_RANGES`):
past it the profile is refused (:class:`MachineError` naming the key and the range).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from ..part.part import OutputError

KINDS = ("laser", "router", "plotter")
# what a router does at an inside corner its round bit cannot reach (:mod:`.reliefs`)
RELIEFS = ("dogbone", "tbone", "none")
OPERATIONS = ("engrave", "score", "cut_inner", "cut_outer", "fill")


class MachineError(OutputError):
    """A profile that cannot be read or holds a value out of range; the message names the
    file, the key and what is allowed."""


@dataclass(frozen=True)
class Operation:
    """One operation's settings: ``power`` (percent of the profile's ``max_power``; lasers),
    ``speed`` (mm/min, the feed), ``passes`` (a laser or plotter repeats the path; a router's
    passes follow from ``depth_per_pass``), ``depth_per_pass`` (mm, routers), ``plunge``
    (mm/min down, routers), ``spindle`` (rpm, routers), ``interval`` (mm between the
    parallel lines of a fill, :mod:`.hatch`)."""
    power: float = 100.0
    speed: float = 600.0
    passes: int = 1
    depth_per_pass: float = 1.0
    plunge: float = 300.0
    spindle: float = 18000.0
    interval: float = 0.1


@dataclass(frozen=True)
class Machine:
    """A machine profile (see the module's docstring for each key); ``source``: the file it
    was read from ("" for a built-in default)."""
    kind: str = "laser"
    units: str = "mm"
    max_power: float = 1000.0
    laser_mode: str = "M4"
    travel_speed: float = 6000.0
    tool_diameter: float = 3.175
    safe_height: float = 5.0
    tabs: int = 0
    tab_width: float = 3.0
    tab_height: float = 1.0
    lead_in: float = 0.0
    relief: str = "none"
    v_bit_angle: float = 90.0
    pocket_tool: float = 0.0
    kerf: float | None = None
    thickness: float | None = None
    operations: dict = field(default_factory=dict)
    source: str = ""

    def operation(self, name: str) -> Operation:
        """The settings of operation ``name`` (one of :data:`OPERATIONS`)."""
        return self.operations.get(name) or DEFAULTS[self.kind].operations[name]

    def tool_text(self) -> str:
        """A router's bit as its G-code header says it (issue 111: the built-in bit's
        diameter was said nowhere): ``a 3.175 mm end mill (tool_diameter): every cut's path
        runs 1.5875 mm beside the line; inside corners: dogbone relief``."""
        relief = "no relief" if self.relief in (None, "none") else f"{self.relief} relief"
        return (f"a {self.tool_diameter:g} mm end mill (tool_diameter): every cut's path runs "
                f"{self.tool_diameter / 2:g} mm beside the line; inside corners: {relief}")


def _ops(**ops) -> dict:
    return {name: ops.get(name, Operation()) for name in OPERATIONS}


# the built-in profiles, one per kind: a 5-10 W diode or 40 W CO2 laser on 3 mm plywood at
# middling settings, a hobby router with a 1/8" end mill, a vinyl cutter or pen plotter
DEFAULTS: dict[str, Machine] = {
    "laser": Machine("laser", operations=_ops(
        engrave=Operation(power=20, speed=3000),
        score=Operation(power=40, speed=2000),
        cut_inner=Operation(power=100, speed=400, passes=2),
        cut_outer=Operation(power=100, speed=400, passes=2),
        fill=Operation(power=20, speed=6000, interval=0.1))),
    "router": Machine("router", tool_diameter=3.175, safe_height=5.0, relief="dogbone",
                      operations=_ops(
                          engrave=Operation(speed=1200, depth_per_pass=0.5, plunge=300),
                          score=Operation(speed=1200, depth_per_pass=0.5, plunge=300),
                          cut_inner=Operation(speed=1000, depth_per_pass=1.5, plunge=300),
                          cut_outer=Operation(speed=1000, depth_per_pass=1.5, plunge=300),
                          fill=Operation(speed=1200, depth_per_pass=0.5, plunge=300))),
    "plotter": Machine("plotter", travel_speed=12000, operations=_ops(
        engrave=Operation(speed=3000), score=Operation(speed=3000),
        cut_inner=Operation(speed=1500), cut_outer=Operation(speed=1500),
        fill=Operation(speed=3000, interval=0.5))),
}

_NUMBER = ("max_power", "travel_speed", "tool_diameter", "safe_height", "tab_width",
           "tab_height", "lead_in", "kerf", "thickness", "v_bit_angle", "pocket_tool")
_OP_KEYS = ("power", "speed", "passes", "depth_per_pass", "plunge", "spindle", "interval")
# The range of every number a profile may give, ``key: (low, high, unit)``, the ends included;
# lengths in mm and speeds in mm/min (an inch profile's values are converted first).  They
# bound the work a job may ask for: a laser or plotter runs each path ``passes`` times, a
# router ``thickness / depth_per_pass`` times (a depth of 1e-12 mm asked for 1e12 passes and
# ended in MemoryError; 1e-6 mm wrote millions of passes for minutes), each tab splits a cut,
# a lead-in or tab far off the loop writes coordinates far off the sheet, a speed near 0 an
# estimate of centuries.  Past a range: one MachineError naming the key and the range
# (docs/machines.md, "Ranges"), and nothing is written.
RANGES: dict[str, tuple[float, float, str]] = {
    "max_power": (1.0, 100_000.0, ""),
    "travel_speed": (1.0, 100_000.0, "mm/min"),
    "tool_diameter": (0.0, 50.0, "mm"),
    "safe_height": (0.0, 500.0, "mm"),
    "tabs": (0, 16, ""),
    "tab_width": (0.0, 100.0, "mm"),
    "tab_height": (0.0, 100.0, "mm"),
    "lead_in": (0.0, 100.0, "mm"),
    "kerf": (0.0, 10.0, "mm"),
    "thickness": (0.0, 1000.0, "mm"),
    "v_bit_angle": (30.0, 150.0, "deg"),
    "pocket_tool": (0.0, 50.0, "mm"),
}
OP_RANGES: dict[str, tuple[float, float, str]] = {
    "power": (0.0, 100.0, "%"),
    "speed": (1.0, 100_000.0, "mm/min"),
    "passes": (1, 100, ""),
    "depth_per_pass": (0.01, 100.0, "mm"),
    "plunge": (1.0, 100_000.0, "mm/min"),
    "spindle": (0.0, 100_000.0, "rpm"),
    "interval": (0.01, 10.0, "mm"),
}
# mm: the least positive length of the keys that may also be 0 (none): a lead-in, a tab, a
# tool are 0 or at least a step of the machine (0.01 mm, as `depth_per_pass`); a lead-in of
# 1e-308 mm ran through the lead-in search to a note of "no room for one of 2.5e-309 mm"
LENGTH_LEAST = 0.01
_ZERO_OR_LEAST = ("tool_diameter", "tab_width", "tab_height", "lead_in", "pocket_tool")
_WHOLE = ("tabs", "passes")          # whole numbers
_PLAIN = ("max_power", "power", "spindle", "tabs", "passes", "v_bit_angle")   # never scaled
# router passes of one cut (thickness / depth_per_pass, rounded up): past it the G-code writer
# refuses the job naming the part (a 1 km thick part at 0.01 mm a pass)
MAX_DEPTH_PASSES = 1000
# moves of one machine program (G-code lines, HPGL segments): the profile's passes or depths
# times the drawing's segments may not go past it (about 30 MB of G-code, 3-5 s to
# write); past it the writer refuses the job and nothing is written
MAX_JOB_MOVES = 1_000_000


def too_long(what: str) -> OutputError:
    """The error of a job past :data:`MAX_JOB_MOVES` (``what``: ``G-code lines``...)."""
    return OutputError(f"the job would have more than {MAX_JOB_MOVES:,} {what}: the profile's "
                       "`passes` (or a router's thickness / `depth_per_pass`) times the "
                       "drawing's segments; use fewer passes or a larger depth_per_pass, or "
                       "cut the drawing in parts; nothing was written")
INCH = 25.4


def default(kind: str = "laser") -> Machine:
    """The built-in profile of ``kind`` (:data:`KINDS`)."""
    if kind not in DEFAULTS:
        raise MachineError(f"no machine kind `{kind}`: one of {', '.join(KINDS)}")
    return DEFAULTS[kind]


def load(path) -> Machine:
    """The profile in TOML file ``path`` (str or Path), over the built-in defaults of its
    ``kind``.  Raises :class:`MachineError` for a file that cannot be read, bad TOML (with
    the line and column), an unknown key or kind, or a value out of range."""
    import tomllib
    from pathlib import Path
    p = Path(path)
    try:
        text = p.read_bytes().decode("utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise MachineError(f"cannot read the machine profile `{p}`: {e}") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise MachineError(f"the machine profile `{p}` is not TOML: {e}") from None
    except ValueError:
        # an integer past Python's 4,300 digits for conversion (no profile number is near it)
        raise MachineError(f"machine profile `{p}`: {_long_number(text)}") from None
    return from_dict(data, str(p))


def _long_number(text: str) -> str:
    """Where TOML ``text`` holds a number too long to read (the key and line)."""
    import re
    for n, line in enumerate(text.splitlines(), 1):
        m = re.match(r"\s*([^=\s]+)\s*=\s*[-+]?\d[\d_]{4300,}", line)
        if m:
            return f"`{m.group(1)}` on line {n} is a number of more than 4300 digits"
    return "it holds a number of more than 4300 digits"


def _shown(v) -> str:
    """``v`` as a message shows it: a long integer by its size (its repr may be refused past
    4,300 digits)."""
    if isinstance(v, int) and v.bit_length() > 100:
        if v.bit_length() > 14_000:
            return "an integer of more than 4000 digits"
        return f"an integer of {len(str(abs(v)))} digits"
    return repr(v)


def from_dict(data: dict, source: str = "") -> Machine:
    """A :class:`Machine` from a profile's table ``data`` (as :func:`load` reads it); errors
    as :func:`load`'s."""
    where = f"machine profile `{source}`" if source else "machine profile"

    def bad(key, why):
        return MachineError(f"{where}: `{key}` {why}")
    kind = data.get("kind", "laser")
    if kind not in KINDS:
        raise bad("kind", f"is `{kind}`, not one of {', '.join(KINDS)}")
    base = DEFAULTS[kind]
    units = data.get("units", "mm")
    if units not in ("mm", "inch"):
        raise bad("units", f"is `{units}`, not `mm` or `inch`")
    scale = INCH if units == "inch" else 1.0
    known = {"kind", "units", "laser_mode", "tabs", "relief", *_NUMBER, *OPERATIONS}
    for key in data:
        if key not in known:
            near = [k for k in sorted(known) if k.split("_")[0] == str(key).split("_")[0]]
            raise bad(key, "is not a profile key" + (f" (did you mean `{near[0]}`?)" if near
                                                      else f"; the keys: {', '.join(sorted(known))}"))
    def number(key: str, v, low, high, unit: str):
        """``v`` checked against its range (``low``..``high`` in mm, mm/min, ...); an inch
        profile's lengths and speeds are converted to mm first."""
        name = key.rsplit(".", 1)[-1]
        whole = name in _WHOLE
        k = 1.0 if name in _PLAIN else scale
        shown = f"{low:g} to {high:g}" + (f" {unit}" if unit else "")
        if k != 1.0:
            shown += f" ({low / k:.3g} to {high / k:.3g} {unit.replace('mm', 'in')})"
        what = "a whole number" if whole else "a number"
        ok_type = isinstance(v, int) if whole else isinstance(v, (int, float))
        if isinstance(v, bool) or not ok_type or v != v:
            raise bad(key, f"must be {what} from {shown}, not {_shown(v)}")
        try:
            x = float(v) * k
        except OverflowError:            # an integer past a float's range (1.8e308)
            x = math.inf if v > 0 else -math.inf
        if not low - 1e-12 * max(1.0, abs(low)) <= x <= high * (1 + 1e-12):
            raise bad(key, f"must be {what} from {shown}, not {_shown(v)}")
        if name in _ZERO_OR_LEAST and 0 < x < LENGTH_LEAST * (1 - 1e-12):
            least = f"{LENGTH_LEAST:g} to {high:g} {unit}"
            if k != 1.0:
                least += f" ({LENGTH_LEAST / k:.3g} to {high / k:.3g} in)"
            raise bad(key, f"must be 0 (none) or a number from {least}, not {_shown(v)}")
        return int(v) if whole else x

    values = {}
    for key in _NUMBER:
        if key in data:
            values[key] = number(key, data[key], *RANGES[key])
    if "laser_mode" in data:
        if data["laser_mode"] not in ("M3", "M4"):
            raise bad("laser_mode", f"is {data['laser_mode']!r}, not \"M3\" or \"M4\"")
        values["laser_mode"] = data["laser_mode"]
    if "relief" in data:
        if data["relief"] not in RELIEFS:
            raise bad("relief", f"is {_shown(data['relief'])}, not one of "
                      + ", ".join(f'"{r}"' for r in RELIEFS))
        values["relief"] = data["relief"]
    if "tabs" in data:
        values["tabs"] = number("tabs", data["tabs"], *RANGES["tabs"])
    tabs = values.get("tabs", base.tabs)
    if tabs >= 1 and values.get("tab_width", base.tab_width) == 0:
        # "4 tabs of 0 mm do not fit": a tab is a length along the cut
        raise bad("tab_width", f"must be greater than 0 with `tabs = {tabs}`: a number from "
                  f"{LENGTH_LEAST:g} to {RANGES['tab_width'][1]:g} mm (or `tabs = 0`: no tabs)")
    ops = {}
    for name in OPERATIONS:
        got = data.get(name, {})
        if not isinstance(got, dict):
            raise bad(name, "must be a table ([" + name + "] with power, speed, passes, ...)")
        op = base.operation(name)
        for key, v in got.items():
            if key not in _OP_KEYS:
                raise bad(f"{name}.{key}", f"is not an operation key; the keys: {', '.join(_OP_KEYS)}")
            v = number(f"{name}.{key}", v, *OP_RANGES[key])
            op = replace(op, **{key: v})
        ops[name] = op
    return replace(base, units=units, operations=ops, source=source, **values)


def resolve(value, kind: str = "laser") -> Machine:
    """The :class:`Machine` a writer's ``options.machine`` names: None (the built-in profile
    of ``kind``, the writer's own default), a Machine, a kind's name (``laser``, ``router``,
    ``plotter``: its built-in profile), a path of a TOML profile, or a dict as a profile's
    table.  Raises :class:`MachineError`."""
    if value is None:
        return default(kind)
    if isinstance(value, Machine):
        return value
    if isinstance(value, dict):
        return from_dict(value)
    if isinstance(value, str) and value in KINDS:
        return default(value)
    return load(value)
