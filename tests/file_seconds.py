"""Write tests/file_seconds.json, the seconds each test file took in a whole run, from pytest's
cache of that run (``.pytest_cache/v/aidl/file_seconds``, kept by tests/conftest.py): the
order in which a fresh clone's run hands files to its workers, slowest first, so both workers
end together.  Run after a whole ``python -m pytest -q``; commit the file it writes."""
import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main() -> int:
    cache = ROOT / ".pytest_cache" / "v" / "aidl" / "file_seconds"
    if not cache.exists():
        print(f"no {cache.relative_to(ROOT)}: run the whole suite first", file=sys.stderr)
        return 1
    kept = json.loads(cache.read_text())
    present = {f: round(t, 1) for f, t in kept.items() if (ROOT / f).exists()}
    out = ROOT / "tests" / "file_seconds.json"
    out.write_text(json.dumps(dict(sorted(present.items(), key=lambda kv: (-kv[1], kv[0]))),
                              indent=0) + "\n")
    print(f"wrote {out.relative_to(ROOT)}: {len(present)} files, {sum(present.values()):.0f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
