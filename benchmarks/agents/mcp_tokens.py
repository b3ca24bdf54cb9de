"""Tokens per job of `aidl mcp` (issues 73 and 86): whole jobs an agent does through the
official SDK's stdio client, what the server returns for each counted, and what it costs
before any work (`tools/list`, the served prompt).

    python benchmarks/agents/mcp_tokens.py [ROOT] [--tree DIR]   # ROOT: a fresh temporary folder
                                                          # when not given; DIR: the aidl
                                                          # source tree to serve (this one)

Issue 86's four jobs (:data:`JOBS`), as an agent does them, pictures at the tools' defaults:

(a) ``plate``: a plate with four M4 clearance holes written, edited to M5 holes and 150 mm
    wide (``set_params`` when the server lists it, else two ``write_program`` patches) and
    saved to DXF;
(b) ``box``: a finger-jointed box written, laid out on a cutting sheet to DXF and rendered
    assembled to STL, with its fit result;
(c) ``drawing``: a DXF rail with a row of six holes turned into a design
    (``import_drawing``, infer), its pitch changed (``set_params`` or a patch) and saved to
    DXF;
(d) ``gears``: a gear pair (``std/gears.aidl``) on one plate written, its centre distance
    read (``measure`` when the server lists it, else ``values``) and saved to DXF.

Issue 73's four jobs (:data:`EARLIER`: a switch plate, a living hinge, a box on a sheet, the
plate's DXF imported and patched) are run after them, pictures 16 px wide.

Tokens are counted as characters / 4 (``tiktoken``'s ``cl100k_base`` when it is installed:
the result says which) of everything the server returns: each text block's text, each image
block's base64 data, and the structured content as compact JSON; ``tools/list`` and the
prompt likewise (the list result as compact JSON, the prompt's text).
:func:`run_jobs` returns ``{job: {"calls", "chars", "tokens"}, "tools/list": ...,
"prompt": ..., "_counter": how}`` and the results of every call (for tests to check what
each job made).
"""
from __future__ import annotations

import asyncio
import json
import os
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parents[2]

# ---- issue 86's jobs
PLATE4 = """units mm
# a mounting plate with four M4 clearance holes (ISO 273 medium: 4.5 mm)
param width = 120 mm
param height = 80 mm
param hole_d = 4.5 mm
param inset = 8 mm
solid plate {
    body = RoundedRectangle(center=(0, 0), width=width, height=height, corner_radius=4)
    hole screws {
        a = Circle(center=(-width / 2 + inset, -height / 2 + inset), diameter=hole_d)
        b = Circle(center=(width / 2 - inset, -height / 2 + inset), diameter=hole_d)
        c = Circle(center=(width / 2 - inset, height / 2 - inset), diameter=hole_d)
        d = Circle(center=(-width / 2 + inset, height / 2 - inset), diameter=hole_d)
    }
}
"""
PLATE4_EDIT = {"hole_d": ("4.5 mm", "5.5 mm"), "width": ("120 mm", "150 mm")}

FINGER_BOX = """units mm
import "std/joints.aidl"
kerf 0.15 mm
thickness 3 mm
assembly kit {
    box = finger_box(length=100 mm, depth=70 mm, height=40 mm, thickness=3 mm, finger=10 mm)
}
"""

RAIL_EDIT = {"holes_pitch": ("25 mm", "22 mm")}

GEARS = """units mm
import "std/gears.aidl"
# a gear pair cut from one plate: 20 and 40 teeth of module 2
assembly drive {
    pair = gear_pair(teeth1=20, teeth2=40, module=2 mm, bore1=5 mm, bore2=8 mm)
}
"""
GEAR_CENTRES = ["drive.pair.gear1.hub.center", "drive.pair.gear2.hub.center"]

JOBS = ("plate", "box", "drawing", "gears")


def rail_dxf(path: Path) -> None:
    """The drawing of job (c): a 160 x 60 mm rail with six 5 mm holes 25 mm apart (ezdxf)."""
    import ezdxf
    doc = ezdxf.new()
    doc.header["$INSUNITS"] = 4                  # mm
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (160, 0), (160, 60), (0, 60)], close=True)
    for k in range(6):
        msp.add_circle((17.5 + 25 * k, 30), 2.5)
    doc.saveas(path)


# ---- issue 73's jobs
PLATE = """units mm
# a single-gang toggle switch plate
param width = 70 mm
param height = 115 mm
solid plate {
    body = RoundedRectangle(center=(0, 0), width=width, height=height, corner_radius=4)
    hole toggle { t = Rectangle(center=(0, 0), width=10.3, height=23.8) }
    hole screws {
        top = Circle(center=(0, 30.15), diameter=3.5)
        bottom = Circle(center=(0, -30.15), diameter=3.5)
    }
}
"""

HINGE = """units mm
import "std/plates.aidl"
solid cover {
    body = RoundedRectangle(center=(0, 0), width=120, height=80, corner_radius=5)
    flex = living_hinge(width=40, height=80, pitch=2, cut=15, bridge=3)
}
"""

BOX = FINGER_BOX

EARLIER = ("switch", "hinge", "sheet", "import")


def counter():
    """``(name, count)``: tiktoken's cl100k_base when installed, else characters / 4."""
    try:
        import tiktoken
        enc = tiktoken.get_encoding("cl100k_base")
        return "tiktoken cl100k_base", lambda s: len(enc.encode(s, disallowed_special=()))
    except Exception:                         # noqa: BLE001 - not installed, or no data
        return "characters/4", lambda s: (len(s) + 3) // 4


def returned_text(result) -> str:
    """Everything ``result`` (a ``CallToolResult``) carries back to the agent, as text."""
    parts = []
    for c in result.content:
        if c.type == "text":
            parts.append(c.text)
        elif c.type == "image":
            parts.append(c.data)
    if result.structured_content is not None:
        parts.append(json.dumps(result.structured_content, separators=(",", ":")))
    return "\n".join(parts)


def listing_text(listed) -> str:
    """``tools/list``'s result (a ``ListToolsResult``) as the compact JSON of the wire."""
    return json.dumps(listed.model_dump(mode="json", by_alias=True, exclude_none=True),
                      separators=(",", ":"))


def server_params(root: str, tree: str | os.PathLike | None = None):
    """``aidl mcp --root ROOT`` of the source tree ``tree`` (default: this one)."""
    from mcp.client.stdio import StdioServerParameters
    tree = Path(tree or HERE).resolve()
    env = {k: v for k, v in os.environ.items() if k != "AIDL_DEBUG"}
    env["PYTHONPATH"] = str(tree)
    return StdioServerParameters(command=sys.executable,
                                 args=["-m", "aidl_lang.cli", "mcp", "--root", str(root)],
                                 env=env, cwd=str(tree))


def _params_argument(tool) -> str:
    """The argument of ``set_params`` that takes the names and values (an object)."""
    props = tool.input_schema.get("properties", {})
    for name, p in props.items():
        kinds = [p] + p.get("anyOf", [])
        types = [t for k in kinds for t in (k.get("type") if isinstance(k.get("type"), list)
                                            else [k.get("type")])]
        if name != "path" and "object" in types:
            return name
    return "params"


async def run_jobs(root: str | os.PathLike, then=None, tree=None) -> tuple[dict, dict]:
    """Run the jobs against ``aidl mcp --root ROOT`` (of the source tree ``tree``):
    ``(figures, results)``, figures ``{job: {"calls", "chars", "tokens"}, "tools/list":
    {"chars", "tokens", "tools"}, "prompt": {"chars", "tokens"}, "_counter": how}``,
    results ``{job: [(tool, arguments, CallToolResult), ...]}``.  ``then``: an async
    function of the session, run after the jobs (not counted), for a test's further
    calls."""
    from mcp.client.session import ClientSession
    from mcp.client.stdio import stdio_client
    how, count = counter()
    root = Path(root)
    (root / "plate.aidl").write_text(PLATE)
    (root / "hinge.aidl").write_text(HINGE)
    (root / "box.aidl").write_text(BOX)
    rail_dxf(root / "rail.dxf")
    figures: dict = {"_counter": how}
    results: dict = {}
    async with stdio_client(server_params(str(root), tree)) as (read, write):
        async with ClientSession(read, write) as session:
            await session.initialize()
            listed = await session.list_tools()
            text = listing_text(listed)
            figures["tools/list"] = {"chars": len(text), "tokens": count(text),
                                     "tools": len(listed.tools)}
            tools = {t.name: t for t in listed.tools}
            prompt = (await session.read_resource("aidl://prompt")).contents[0].text
            figures["prompt"] = {"chars": len(prompt), "tokens": count(prompt)}

            async def call(job: str, tool: str, args: dict):
                r = await session.call_tool(tool, args)
                text = returned_text(r)
                f = figures.setdefault(job, {"calls": 0, "chars": 0, "tokens": 0})
                f["calls"] += 1
                f["chars"] += len(text)
                f["tokens"] += count(text)
                results.setdefault(job, []).append((tool, args, r))
                return r

            async def set_params(job: str, path: str, edit: dict):
                """``edit`` ({name: (old, new)}) with `set_params`, else patches."""
                if "set_params" in tools:
                    await call(job, "set_params", {
                        "path": path,
                        _params_argument(tools["set_params"]): {k: new for k, (_, new)
                                                                in edit.items()}})
                    return
                for name, (old, new) in edit.items():
                    await call(job, "write_program", {
                        "path": path, "old": f"param {name} = {old}",
                        "new": f"param {name} = {new}"})

            # (a) four M4 holes -> M5, 150 mm wide, saved
            await call("plate", "write_program", {"path": "mount.aidl", "text": PLATE4})
            await set_params("plate", "mount.aidl", PLATE4_EDIT)
            await call("plate", "render", {"path": "mount.aidl", "output": "mount.dxf"})
            # (b) a finger-jointed box to a cutting sheet, and its assembled fit
            await call("box", "write_program", {"path": "fbox.aidl", "text": FINGER_BOX})
            await call("box", "render", {"path": "fbox.aidl", "layout": "sheet",
                                         "output": "fbox.dxf"})
            await call("box", "render", {"path": "fbox.aidl", "assembled": True,
                                         "output": "fbox.stl"})
            # (c) a DXF turned into a design, its pitch changed, saved
            await call("drawing", "import_drawing", {"path": "rail.dxf",
                                                     "output": "rail.aidl"})
            await set_params("drawing", "rail.aidl", RAIL_EDIT)
            await call("drawing", "render", {"path": "rail.aidl", "output": "rail2.dxf"})
            # (d) a gear pair on one plate, its centre distance read, saved
            await call("gears", "write_program", {"path": "gears.aidl", "text": GEARS})
            if "measure" in tools:
                await call("gears", "measure", {"path": "gears.aidl", "a": GEAR_CENTRES[0],
                                                "b": GEAR_CENTRES[1]})
            else:
                await call("gears", "values", {"path": "gears.aidl", "names": GEAR_CENTRES})
            await call("gears", "render", {"path": "gears.aidl", "output": "gears.dxf"})

            # issue 73's: the switch plate, every size checked, to DXF
            await call("switch", "check", {"path": "plate.aidl"})
            await call("switch", "describe", {"path": "plate.aidl"})
            await call("switch", "values", {"path": "plate.aidl"})
            await call("switch", "render", {"path": "plate.aidl", "output": "plate.dxf",
                                            "width": 16})
            # the living-hinge cover, to SVG and G-code
            await call("hinge", "check", {"path": "hinge.aidl"})
            await call("hinge", "describe", {"path": "hinge.aidl"})
            await call("hinge", "values", {"path": "hinge.aidl"})
            await call("hinge", "render", {"path": "hinge.aidl", "output": "hinge.svg",
                                           "width": 16})
            await call("hinge", "render", {"path": "hinge.aidl", "output": "hinge.gcode",
                                           "width": 16, "style": "laser"})
            # the finger-joint box: 3D fit check, then on a sheet with kerf
            await call("sheet", "check", {"path": "box.aidl"})
            await call("sheet", "render", {"path": "box.aidl", "assembled": True,
                                           "width": 16})
            await call("sheet", "render", {"path": "box.aidl", "layout": "sheet",
                                           "sheet": "600x400mm", "kerf": 0.15,
                                           "output": "box.dxf", "width": 16})
            # the DXF of the switch plate back to a program, patched, re-rendered
            r = await call("import", "import_drawing", {"path": "plate.dxf",
                                                        "output": "plate2.aidl"})
            program = (r.structured_content or json.loads(r.content[-1].text))["program"]
            old = "param holes_d = 3.5 mm"
            new = "param holes_d = 4 mm"
            assert old in program, program
            await call("import", "write_program", {"path": "plate2.aidl", "old": old,
                                                   "new": new})
            await call("import", "check", {"path": "plate2.aidl"})
            await call("import", "render", {"path": "plate2.aidl", "output": "plate2.dxf",
                                            "width": 16})
            if then is not None:
                await then(session)
    for name, jobs in (("total", JOBS), ("total73", EARLIER)):
        figures[name] = {k: sum(figures[j][k] for j in jobs) for k in ("calls", "chars",
                                                                         "tokens")}
    return figures, results


def main(argv: list[str]) -> int:
    import argparse
    import tempfile
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("root", nargs="?")
    ap.add_argument("--tree", help="the aidl source tree to serve (default: this one)")
    args = ap.parse_args(argv)
    if args.root:
        figures, _ = asyncio.run(run_jobs(args.root, tree=args.tree))
    else:
        with tempfile.TemporaryDirectory() as d:
            figures, _ = asyncio.run(run_jobs(d, tree=args.tree))
    print(f"tokens counted as {figures['_counter']}")
    for what in ("tools/list", "prompt"):
        f = figures[what]
        print(f"{what:10} {'':9} {f['chars']:8} chars {f['tokens']:7} tokens")
    for job in (*JOBS, "total", *EARLIER, "total73"):
        f = figures[job]
        print(f"{job:10} {f['calls']:3} calls {f['chars']:8} chars {f['tokens']:7} tokens")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
