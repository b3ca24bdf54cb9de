"""Where rows go: ``OUT.jsonl`` or ``OUT.parquet``, written so that a crash or a Ctrl-C loses
no finished row (docs/batch.md, "Output and resuming").

Every row is appended to a JSONL *journal* and flushed as soon as it finishes.  For ``.jsonl``
the journal is ``OUT`` itself.  For ``.parquet`` it is ``OUT.journal.jsonl`` beside it: a
Parquet file is only readable once its footer is written, so rows cannot be appended to it one
by one, and a batch killed half-way through a Parquet writer would leave nothing readable; row
groups of one row each would also make a poor file.  At the end of a batch the Parquet file is
written in one go (to a temporary file, then renamed) from the earlier ``OUT.parquet``, if any,
and the journal, and the journal is removed.  An interrupted batch keeps its journal, and the
next run reads both.

At the end, ``OUT`` holds one row per id (the latest), the ids of this batch in input order
first; an interrupted ``.jsonl`` may hold an older row of an id before its newer one (readers
should take the last).
"""
from __future__ import annotations

import errno
import json
import os
from pathlib import Path

from ..output.writers.write import write_atomic
from ..host.files import NOFOLLOW, NONBLOCK, FileRefused, open_append
from .row import FIELDS


class MissingArrow(RuntimeError):
    pass


def _schema():
    import pyarrow as pa
    diag = pa.list_(pa.struct([("code", pa.string()), ("line", pa.int64()),
                               ("column", pa.int64()), ("message", pa.string())]))
    types = {"id": pa.string(), "path": pa.string(), "sha256": pa.string(),
             "options": pa.string(), "status": pa.string(), "ok": pa.bool_(),
             "failure": pa.string(), "errors": diag, "warnings": diag, "dof": pa.int64(),
             "parts": pa.int64(), "holes": pa.int64(), "bbox": pa.list_(pa.float64()),
             "area": pa.float64(), "compile_s": pa.float64(), "solve_s": pa.float64(),
             "render_s": pa.float64(), "outputs": pa.list_(pa.string())}
    return pa.schema([(name, types[name]) for name in FIELDS])


def need_arrow() -> None:
    try:
        import pyarrow  # noqa: F401
        import pyarrow.parquet  # noqa: F401
    except ImportError as e:
        raise MissingArrow(f"Parquet output needs pyarrow ({e.name} is missing): "
                           "pip install 'aidl-lang[batch]', or write OUT.jsonl") from None


def read_jsonl(path: Path, follow_symlinks: bool = True) -> list[dict]:
    """The rows of a JSONL file; a line that is not a row (one cut short by a crash) is
    skipped.  ``follow_symlinks=False``: a link is refused
    (:class:`~aidl_lang.host.files.FileRefused`), as a batch reads its own journal."""
    rows = []
    try:
        flags = os.O_RDONLY | (0 if follow_symlinks else NOFOLLOW)
        with open(os.open(path, flags), encoding="utf-8") as f:
            for line in f:
                try:
                    row = json.loads(line)
                except ValueError:
                    continue
                if isinstance(row, dict) and isinstance(row.get("id"), str):
                    rows.append(row)
    except FileNotFoundError:
        pass
    except OSError as e:
        if e.errno == errno.ELOOP:
            raise FileRefused(f"`{path}` is a symbolic link; refusing to read it as this "
                              "batch's rows") from None
        raise
    return rows


def read_parquet(path: Path) -> list[dict]:
    if not path.exists():
        return []
    import pyarrow.parquet as pq
    return pq.read_table(path).to_pylist()


class NotAResult(ValueError):
    """An existing OUT that a batch did not write (its rows would be dropped or break the
    final write); the message says what is wrong with it."""


def check_result(path: Path) -> None:
    """Raise :class:`NotAResult` unless ``path`` is missing or a batch result: for Parquet, a
    file whose columns are the rows' fields with their types (an integer ``id`` is not); for
    JSONL, every complete line a row object (``id`` text, a ``status``); a last line without
    its newline, cut short by a crash, is allowed."""
    if not path.exists():
        return
    if path.suffix.lower() == ".parquet":
        import pyarrow.parquet as pq
        schema = pq.read_schema(path)
        want = _schema()
        for name in want.names:
            if name not in schema.names:
                raise NotAResult(f"it has no `{name}` column")
            if schema.field(name).type != want.field(name).type:
                raise NotAResult(f"its `{name}` column holds {schema.field(name).type}, "
                                 f"not {want.field(name).type}")
        return
    with open(os.open(path, os.O_RDONLY | NOFOLLOW | NONBLOCK), "rb") as f:
        lines = f.read().split(b"\n")
    for no, line in enumerate(lines[:-1], 1):          # the last piece has no newline
        if not line.strip():
            continue
        try:
            row = json.loads(line)
        except ValueError:
            raise NotAResult(f"line {no} is not JSON") from None
        if not (isinstance(row, dict) and isinstance(row.get("id"), str) and "status" in row):
            raise NotAResult(f"line {no} is not a batch row (an object with `id` and "
                             "`status`)")


def read_rows(path: Path) -> list[dict]:
    """The rows of a batch result, ``.jsonl`` or ``.parquet`` (with its journal, if a batch
    was interrupted), the latest row per id."""
    store = Store(path)
    return list(store.load().values())


class Store:
    def __init__(self, out: Path) -> None:
        self.out = Path(out)
        self.parquet = self.out.suffix.lower() == ".parquet"
        self.journal = (self.out.with_name(self.out.name + ".journal.jsonl") if self.parquet
                        else self.out)
        self._f = None

    def load(self) -> dict[str, dict]:
        """id -> the latest finished row, from ``OUT`` and the journal."""
        rows: dict[str, dict] = {}
        if self.parquet:
            for row in read_parquet(self.out):
                rows[row["id"]] = row
        for row in read_jsonl(self.journal, follow_symlinks=False):
            rows.pop(row["id"], None)            # keep the order of the latest
            rows[row["id"]] = row
        return rows

    def open(self) -> None:
        self.journal.parent.mkdir(parents=True, exist_ok=True)
        # never through a link, even one swapped in after run_batch looked (O_NOFOLLOW)
        self._f = open_append(self.journal)
        if self._f.tell() > 0:                   # a line cut short by a crash: end it
            self._f.seek(self._f.tell() - 1)
            last = self._f.read(1)
            self._f.seek(0, os.SEEK_END)
            if last != "\n":
                self._f.write("\n")

    def append(self, row: dict) -> None:
        self._f.write(json.dumps(row, separators=(",", ":")) + "\n")
        self._f.flush()

    def close(self) -> None:
        if self._f is not None:
            self._f.close()
            self._f = None

    def finish(self, order: list[str]) -> None:
        """Write the final ``OUT``: one row per id, ``order`` first (see the module text)."""
        self.close()
        rows = self.load()
        ordered = [rows.pop(i) for i in order if i in rows] + list(rows.values())
        if self.parquet:
            import pyarrow as pa
            import pyarrow.parquet as pq
            table = pa.Table.from_pylist([{k: r.get(k) for k in FIELDS} for r in ordered],
                                         schema=_schema())
            sink = pa.BufferOutputStream()
            pq.write_table(table, sink)
            data = sink.getvalue().to_pybytes()
        else:
            data = "".join(json.dumps(r, separators=(",", ":")) + "\n"
                           for r in ordered).encode("utf-8")
        write_atomic(self.out, data)
        if self.parquet:
            try:
                os.unlink(self.journal)
            except FileNotFoundError:
                pass
