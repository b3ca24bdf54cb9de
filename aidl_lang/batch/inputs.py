"""What a batch compiles: files, folders (every ``*.aidl`` below, hidden folders skipped) and
JSONL files of ``{"id": ..., "source": ...}`` rows (optionally ``"set": {NAME: VALUE}`` and
``"budget": K`` per row), each turned into a task dict for :func:`.row.run_one`."""
from __future__ import annotations

import json
import os
import re
from pathlib import Path

from ..host.files import FileRefused, read_file
from ..library.sources import MAX_IMPORT_BYTES, SourceRefused, decode_program
from .row import options_key, sha256


class InputError(ValueError):
    """A mistake in the inputs (a missing path, a bad JSONL line): a usage error."""


def _file_task(path: str) -> dict:
    task = {"id": path, "path": path, "source": None}
    try:        # as the main file of `aidl check`: a regular file, size-limited, non-blocking
        data = read_file(path, MAX_IMPORT_BYTES)
    except FileRefused as e:           # a FIFO, /dev/zero, a file larger than imports may be
        task.update(sha256=sha256(b""), read_error=e.message)
        return task
    except OSError as e:
        task.update(sha256=sha256(b""),
                    read_error=f"cannot read `{path}`: {e.strerror or e}")
        return task
    task["sha256"] = sha256(data)
    try:
        task["source"] = decode_program(data, path)
    except SourceRefused as e:
        task["read_error"] = e.message
    return task


def _walk(folder: Path) -> list[str]:
    found = []
    for root, dirs, files in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        found.extend(os.path.normpath(os.path.join(root, f)) for f in sorted(files)
                     if f.endswith(".aidl"))
    return found


def _jsonl_tasks(path: Path) -> list[dict]:
    tasks = []
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as e:
        raise InputError(f"cannot read `{path}`: {getattr(e, 'strerror', None) or e}") from None
    for no, line in enumerate(lines, 1):
        if not line.strip():
            continue
        where = f"{path}:{no}"
        try:
            obj = json.loads(line)
        except ValueError as e:
            raise InputError(f"{where}: not a JSON object ({e.msg})") from None
        if not isinstance(obj, dict):
            raise InputError(f"{where}: expected a JSON object with `id` and `source`")
        ident, source = obj.get("id"), obj.get("source")
        if not isinstance(ident, (str, int)) or isinstance(ident, bool) or str(ident) == "":
            raise InputError(f"{where}: `id` must be a non-empty string or a number")
        if not isinstance(source, str):
            raise InputError(f"{where}: `source` must be a string (the program's text)")
        task = {"id": str(ident), "path": None, "source": source, "sha256": sha256(source)}
        if "set" in obj:
            values = obj["set"]
            if not isinstance(values, dict) or not all(isinstance(v, (str, int, float))
                                                       and not isinstance(v, bool)
                                                       for v in values.values()):
                raise InputError(f"{where}: `set` must map names to values, "
                                 'e.g. {"width": "40mm"}')
            task["overrides"] = {str(k): str(v) for k, v in values.items()}
        if "budget" in obj:
            k = obj["budget"]
            if not isinstance(k, (int, float)) or isinstance(k, bool) or not 0 < k <= 1000:
                raise InputError(f"{where}: `budget` must be a factor between 0 and 1000")
            task["budget"] = float(k)
        tasks.append(task)
    return tasks


def collect(inputs: list[str], overrides: dict, budget: float, cfg: dict) -> list[dict]:
    """The tasks of ``inputs`` in order; raises :class:`InputError` for a path that does not
    exist, a bad JSONL line or an id given twice.  A file given twice (also through its
    folder) is compiled once."""
    tasks: list[dict] = []
    for item in inputs:
        p = Path(item)
        if p.is_dir():
            tasks.extend(_file_task(f) for f in _walk(p))
        elif p.suffix.lower() == ".jsonl" and p.is_file():
            tasks.extend(_jsonl_tasks(p))
        elif p.exists():
            tasks.append(_file_task(os.path.normpath(item)))
        else:
            raise InputError(f"`{item}` does not exist (give .aidl files, folders or "
                             ".jsonl files of {\"id\", \"source\"} rows)")
    seen: dict[str, dict] = {}
    out = []
    for t in tasks:
        prev = seen.get(t["id"])
        if prev is not None:
            if t["path"] is not None and prev["path"] is not None:
                continue                        # the same file twice
            raise InputError(f"the id `{t['id']}` is given twice; ids must be unique")
        seen[t["id"]] = t
        out.append(t)
    stems: dict[str, int] = {}
    for t in out:
        t.setdefault("overrides", dict(overrides))
        t.setdefault("budget", float(budget))
        t["options"] = options_key(t["overrides"], t["budget"], cfg)
        t["stem"] = _stem(t, stems)
    return out


def _stem(task: dict, used: dict[str, int]) -> str:
    """The rendered files' name: a file's name without `.aidl` (`examples/key.aidl` gives
    `key`), or a JSONL row's id, every character but letters, digits, `.`, `-`, `_` turned
    into `_`; a name taken by an earlier task gets the id's hash appended (`key-1f0c...`)."""
    name = Path(task["path"]).stem if task["path"] is not None else task["id"]
    name = re.sub(r"[^A-Za-z0-9._-]+", "_", name).strip("._")[:120] or "program"
    if name in used:
        name = f"{name}-{sha256(task['id'])[:10]}"
    used[name] = 1
    return name
