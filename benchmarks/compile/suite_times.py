"""The test suite's time by test file: sums the per-test times (setup + call + teardown) of a
``pytest --junitxml`` report by file, largest first.

Run:  .venv/bin/python -m pytest -q --junitxml=/tmp/suite.xml
      .venv/bin/python benchmarks/compile/suite_times.py /tmp/suite.xml [--top N] [--tests N]

A module- or session-scoped fixture's setup is counted in the first test that uses it.
"""
from __future__ import annotations

import argparse
import collections
import xml.etree.ElementTree as ET


def by_file(report: str) -> tuple[collections.Counter, collections.Counter, list]:
    """``(seconds per file, tests per file, [(seconds, test id)])`` of a JUnit XML report."""
    seconds: collections.Counter = collections.Counter()
    count: collections.Counter = collections.Counter()
    tests = []
    for case in ET.parse(report).getroot().iter("testcase"):
        parts = case.get("classname", "").split(".")
        name = parts[1] if parts[0] == "tests" and len(parts) > 1 else parts[0]
        t = float(case.get("time", 0))
        seconds[name] += t
        count[name] += 1
        tests.append((t, f"{case.get('classname')}::{case.get('name')}"))
    return seconds, count, sorted(tests, reverse=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("report", help="a pytest --junitxml file")
    ap.add_argument("--top", type=int, default=30, help="files to list (default 30)")
    ap.add_argument("--tests", type=int, default=0, help="slowest tests to list too")
    args = ap.parse_args()
    seconds, count, tests = by_file(args.report)
    print(f"{sum(seconds.values()):.1f} s in {sum(count.values())} tests")
    for name, s in seconds.most_common(args.top):
        print(f"{s:8.1f} s {count[name]:5d} tests {s / count[name]:6.3f} s/test  {name}")
    for t, test in tests[:args.tests]:
        print(f"{t:8.2f} s  {test}")


if __name__ == "__main__":
    main()
