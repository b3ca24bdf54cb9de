"""Issue 109, law 6, "one answer on every machine, the suite too": the README's test command
draws the same cases on every machine and every run.  A fresh machine once drew, at random,
a T-bracket in inches no other machine had drawn (tests/test_infer_profiles.py), and the
command failed there.

The rules (tests/conftest.py, docs/dev/testing.md): Hypothesis runs under the profile "aidl"
(derandomized, no example database, no deadline, no too_slow health check: the last two read
the wall clock); a test's own `settings(...)` inherits it and must not say `derandomize=` or
`database=` (they would also stop `--hypothesis-seed=N` from reaching it); other random
numbers come from a generator with a fixed seed.  Cost: reading the test files, < 0.5 s."""
from __future__ import annotations

import re

from hypothesis import HealthCheck, settings

from conftest import HYPOTHESIS_PROFILE, ROOT

TESTS = sorted(p for p in (ROOT / "tests").glob("*.py")
               if p.name not in ("conftest.py", "test_suite_seeds.py"))
# a draw from the process's own random state (seeded from the clock or the OS): the module
# functions of `random` and `numpy.random`, and generators made without a seed
UNSEEDED = re.compile(
    r"(?<![\w.])random\.(?:random|randint|randrange|choice|choices|shuffle|sample|uniform|"
    r"gauss|getrandbits|randbytes)\("
    r"|(?<![\w.])(?:random\.)?Random\(\s*\)|default_rng\(\s*\)|RandomState\(\s*\)"
    r"|np\.random\.(?:rand|randn|randint|random|choice|shuffle|permutation|normal|uniform)\(")


def _code(path) -> str:
    """The file's text with its comments dropped (a comment may name what it must not do)."""
    return "\n".join(line.split("#", 1)[0] for line in path.read_text().split("\n"))


def test_no_test_undoes_the_profile():
    """No `settings(...)` of a test file says `derandomize=` or `database=` (the profile's
    own), and no test pins a seed with `@seed` but through the profile's derandomize."""
    bad = [f"{p.name}:{n}: {line.strip()}" for p in TESTS
           for n, line in enumerate(_code(p).split("\n"), 1)
           if re.search(r"\b(?:derandomize|database)\s*=|^\s*@seed\(", line)]
    assert bad == [], bad


def test_no_test_draws_from_an_unseeded_generator():
    """`random.Random(seed)`, `np.random.default_rng(seed)` with a seed written in the test
    or drawn by Hypothesis; never the module-level `random.random()` or a generator made
    without one (a different case on every run)."""
    bad = [f"{p.name}:{n}: {line.strip()}" for p in TESTS
           for n, line in enumerate(_code(p).split("\n"), 1) if UNSEEDED.search(line)]
    assert bad == [], bad


def test_the_check_sees_an_unseeded_draw():
    """The pattern above finds what it is for, and passes a seeded generator."""
    for line in ("x = random.random()", "rng = Random()", "g = np.random.default_rng()",
                 "v = np.random.normal(0, 1)", "random.shuffle(xs)"):
        assert UNSEEDED.search(line), line
    for line in ("rng = random.Random(seed)", "rng.random()", "np.random.default_rng(3)",
                 "rnd.choice(xs)", "x = gen.random_design(rng)"):
        assert not UNSEEDED.search(line), line


def test_the_loaded_profile_is_derandomized_unless_a_seed_was_asked(request):
    """Under the README's command the profile is "aidl": derandomized, no database, no
    deadline, too_slow suppressed; with `--hypothesis-seed=N` (or AIDL_HYPOTHESIS_PROFILE=
    random) "random", the same but for derandomize.  A test's own settings made now (as a
    test module's decorator is, at import) inherit it."""
    import os
    name = settings.get_current_profile_name()
    seeded = request.config.getoption("--hypothesis-seed", None) is not None
    asked = (request.config.getoption("--hypothesis-profile", None)
             or os.environ.get(HYPOTHESIS_PROFILE) or ("random" if seeded else "aidl"))
    assert name == asked
    if name not in ("aidl", "random"):
        return
    own = settings(max_examples=3)
    for s in (settings.default, own):
        assert s.derandomize is (name == "aidl")
        assert s.database is None and s.deadline is None
        assert HealthCheck.too_slow in s.suppress_health_check
    assert own.max_examples == 3
