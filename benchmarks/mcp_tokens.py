"""Tokens per job of `aidl mcp` (issue 73): four whole jobs an agent does through the official
SDK's stdio client, and what the server returns for each, counted.

    python benchmarks/mcp_tokens.py [ROOT]      # a fresh temporary folder when not given

The jobs:

(a) ``plate``: a switch plate to DXF with every size checked (check, describe, values, render
    to DXF);
(b) ``hinge``: a living-hinge cover to SVG and G-code (check, describe, values, render to SVG,
    render to G-code);
(c) ``box``: a finger-joint box on a sheet with kerf and a 3D fit check (check, render
    assembled, render on a sheet with kerf to DXF);
(d) ``import``: the DXF of job (a) turned into an editable program (import_drawing with
    infer), the program edited (the screw holes made larger) and re-rendered, with the
    ``write_program`` tool when the server has one, else by passing the edited text.

Tokens are counted as characters / 4 (``tiktoken``'s ``cl100k_base`` when it is installed:
the result says which) of everything the server returns: each text block's text, each image
block's base64 data, and the structured content as compact JSON.  The pictures are asked at
the smallest width (16 px), so the count is that of the words and numbers.
:func:`run_jobs` returns ``{job: {"calls", "chars", "tokens"}, "_counter": how}`` and the
results of every call (for tests to check what each job made).
"""
from __future__ import annotations

import asyncio
import json
import os
import sys
from pathlib import Path

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

BOX = """units mm
import "std/joints.aidl"
kerf 0.15 mm
thickness 3 mm
assembly kit {
    box = finger_box(length=100 mm, depth=70 mm, height=40 mm, thickness=3 mm, finger=10 mm)
}
"""

JOBS = ("plate", "hinge", "box", "import")


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


def server_params(root: str):
    from mcp.client.stdio import StdioServerParameters
    env = {k: v for k, v in os.environ.items() if k != "AIDL_DEBUG"}
    return StdioServerParameters(command=sys.executable,
                                 args=["-m", "aidl_lang.cli", "mcp", "--root", str(root)],
                                 env=env, cwd=str(Path(__file__).resolve().parent.parent))


async def run_jobs(root: str | os.PathLike, then=None) -> tuple[dict, dict]:
    """Run the four jobs against ``aidl mcp --root ROOT``: ``(figures, results)``, figures
    ``{job: {"calls", "chars", "tokens"}, "_counter": how}``, results ``{job: [(tool,
    arguments, CallToolResult), ...]}``.  ``then``: an async function of the session, run
    after the jobs (not counted), for a test's further calls."""
    from mcp.client.session import ClientSession
    from mcp.client.stdio import stdio_client
    how, count = counter()
    root = Path(root)
    (root / "plate.aidl").write_text(PLATE)
    (root / "hinge.aidl").write_text(HINGE)
    (root / "box.aidl").write_text(BOX)
    figures: dict = {"_counter": how}
    results: dict = {}
    async with stdio_client(server_params(str(root))) as (read, write):
        async with ClientSession(read, write) as session:
            await session.initialize()
            tools = {t.name for t in (await session.list_tools()).tools}

            async def call(job: str, tool: str, args: dict):
                r = await session.call_tool(tool, args)
                text = returned_text(r)
                f = figures.setdefault(job, {"calls": 0, "chars": 0, "tokens": 0})
                f["calls"] += 1
                f["chars"] += len(text)
                f["tokens"] += count(text)
                results.setdefault(job, []).append((tool, args, r))
                return r

            # (a) the switch plate, every size checked, to DXF
            await call("plate", "check", {"path": "plate.aidl"})
            await call("plate", "describe", {"path": "plate.aidl"})
            await call("plate", "values", {"path": "plate.aidl"})
            await call("plate", "render", {"path": "plate.aidl", "output": "plate.dxf",
                                           "width": 16})
            # (b) the living-hinge cover, to SVG and G-code
            await call("hinge", "check", {"path": "hinge.aidl"})
            await call("hinge", "describe", {"path": "hinge.aidl"})
            await call("hinge", "values", {"path": "hinge.aidl"})
            await call("hinge", "render", {"path": "hinge.aidl", "output": "hinge.svg",
                                           "width": 16})
            await call("hinge", "render", {"path": "hinge.aidl", "output": "hinge.gcode",
                                           "width": 16, "style": "laser"})
            # (c) the finger-joint box: 3D fit check, then on a sheet with kerf
            await call("box", "check", {"path": "box.aidl"})
            await call("box", "render", {"path": "box.aidl", "assembled": True, "width": 16})
            await call("box", "render", {"path": "box.aidl", "layout": "sheet",
                                         "sheet": "600x400mm", "kerf": 0.15,
                                         "output": "box.dxf", "width": 16})
            # (d) the DXF of (a) back to a program, edited, re-rendered
            r = await call("import", "import_drawing", {"path": "plate.dxf",
                                                        "output": "plate2.aidl"})
            program = (r.structured_content or json.loads(r.content[-1].text))["program"]
            old = "param holes_d = 3.5 mm"
            new = "param holes_d = 4 mm"
            assert old in program, program
            if "write_program" in tools:
                await call("import", "write_program", {"path": "plate2.aidl", "old": old,
                                                       "new": new})
                await call("import", "check", {"path": "plate2.aidl"})
                await call("import", "render", {"path": "plate2.aidl", "output": "plate2.dxf",
                                                "width": 16})
            else:
                edited = program.replace(old, new)
                await call("import", "check", {"source": edited})
                await call("import", "render", {"source": edited, "output": "plate2.dxf",
                                                "width": 16})
            if then is not None:
                await then(session)
    figures["total"] = {k: sum(figures[j][k] for j in JOBS) for k in ("calls", "chars",
                                                                       "tokens")}
    return figures, results


def main(argv: list[str]) -> int:
    import tempfile
    if argv:
        figures, _ = asyncio.run(run_jobs(argv[0]))
    else:
        with tempfile.TemporaryDirectory() as d:
            figures, _ = asyncio.run(run_jobs(d))
    print(f"tokens counted as {figures['_counter']}")
    for job in (*JOBS, "total"):
        f = figures[job]
        print(f"{job:8} {f['calls']:3} calls {f['chars']:8} chars {f['tokens']:7} tokens")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
