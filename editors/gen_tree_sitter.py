#!/usr/bin/env python3
"""Regenerate what tree-sitter-aidl-cad (``editors/tree-sitter``) derives from the repository:
``python editors/gen_tree_sitter.py``.

Writes

- ``editors/tree-sitter/queries/highlights.scm``: the captures of the TextMate grammar
  (structure kinds, constraints, primitives, builtin functions, constants, params, units,
  keywords), its name lists from :func:`aidl_lang.editor.highlight.vocabulary` -- the ones
  ``editors/gen_grammar.py`` makes the TextMate grammar of, so the two never drift;
- ``editors/tree-sitter/test/corpus/<group>.txt``: a ``tree-sitter test`` corpus of every
  example (``examples/``), standard-library file (``stdlib/``) and documentation example (the
  ```aidl blocks of README.md and docs/*.md, and docs/figures/*.aidl), each with the tree the
  committed parser gives it. A source that parses with an ERROR or MISSING node stops the
  script: the grammar is what must change, not the corpus. A docs block meant to show a syntax
  error (the Lark parser rejects it: ``<!-- expect: E0001 -->``) goes to ``docs-errors.txt``
  with the ``:error`` attribute instead (the test then asks for an ERROR node);
- ``editors/tree-sitter/test/corpus/errors.txt``: the error-recovery cases of
  :data:`ERROR_CASES` (sources the Lark parser rejects) with the trees the parser gives them,
  each holding an ERROR node and the statements around it.

``--check`` writes nothing and exits 1 if a committed file is out of date; ``--no-corpus``
leaves the corpora alone (highlights.scm needs neither a C compiler nor the ``tree-sitter``
package). The parser itself
(``src/``) is ``tree-sitter generate``'s, run in ``editors/tree-sitter`` after ``grammar.js``
changes; the corpora are then regenerated with this script.

The trees are read with the ``tree-sitter`` Python package from a library compiled from the
committed ``src/parser.c`` and ``src/scanner.c`` (:func:`language`; a C compiler is needed).
"""
from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from generated import write_or_check  # noqa: E402

TS = ROOT / "editors" / "tree-sitter"
SRC = TS / "src"
HIGHLIGHTS = TS / "queries" / "highlights.scm"
CORPUS = TS / "test" / "corpus"
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md")),
        *sorted((ROOT / "docs" / "dev").glob("*.md"))]
# the corpus files written here (test/corpus holds no other)
GENERATED_GROUPS = ("examples", "stdlib", "docs", "docs-errors", "errors")

# error recovery: sources the Lark parser rejects, with what the tree keeps around the error
# (written to errors.txt with the trees the parser gives; each must hold an ERROR node)
ERROR_CASES = [
    ("a stray `=`: the ERROR is inside the assignment; the next statement and structure parse",
     "solid a {\n    x = = 1\n    y = 2\n}\nsolid b { z = 3 }\n"),
    ("a call left open at the end of a line: the next structure parses",
     "solid a {\n    c = Circle(center=(0, 0), radius=\n}\nsolid b { z = 3 }\n"),
    ("a block never closed: the statements after its opening still parse",
     "solid a {\n    r = Rectangle(width=10, height=5)\nsolid b { z = 3 }\n"),
    ("two operators in a row: the ERROR is the second; the next top-level statement parses",
     "param w = 40 mm\nx = 1 +* 2\nunits mm\n"),
    ("an unclosed string: the ERROR ends at the next line's first name; the block parses",
     "solid a {\n    s = \"unclosed\n    t = 2\n}\n"),
    ("a stray `}`: the structures before and after it parse",
     "solid a {\n    x = 1 }\n}\nsolid b { }\n"),
    ("a top-level-only statement inside a block: the block's other statements parse",
     "solid a {\n    units mm\n    x = 1\n}\n"),
    ("a missing operand before a newline inside brackets: the closing bracket is found",
     "solid a {\n    c = Circle(center=(0, 0),\n               radius= )\n    d = 2\n}\n"),
]

# the grammar's declaration words that are not quoted in grammar/aidl.lark (%declare'd
# terminals the post-lexer makes of a NAME at the start of a statement)
DECLARED_WORDS = ["kerf", "min_wall", "thickness"]


# ------------------------------------------------------------------ the compiled grammar
def c_compiler() -> str | None:
    """The C compiler to build the parser with: ``$CC``, else cc, gcc or clang on PATH."""
    cc = os.environ.get("CC")
    if cc and shutil.which(cc.split()[0]):
        return cc
    for name in ("cc", "gcc", "clang"):
        if shutil.which(name):
            return name
    return None


def build_library(cache: Path | None = None) -> Path:
    """The shared library of the committed parser (``src/parser.c`` + ``src/scanner.c``),
    compiled once per content into ``cache`` (default: a folder in the system's temporary
    directory) and reused. Raises :class:`FileNotFoundError` when there is no C compiler and
    :class:`subprocess.CalledProcessError` when the sources do not compile."""
    sources = [SRC / "parser.c", SRC / "scanner.c"]
    digest = hashlib.sha256()
    for p in sources + sorted((SRC / "tree_sitter").glob("*.h")):
        digest.update(p.name.encode() + b"\0" + p.read_bytes())
    cache = cache or Path(tempfile.gettempdir()) / f"aidl-tree-sitter-{os.getuid()}"
    cache.mkdir(parents=True, exist_ok=True)
    lib = cache / f"aidl-{digest.hexdigest()[:16]}.so"
    if lib.exists():
        return lib
    cc = c_compiler()
    if cc is None:
        raise FileNotFoundError("no C compiler (cc, gcc or clang, or $CC) to build the parser")
    tmp = lib.with_name(f"{lib.stem}.{os.getpid()}.tmp.so")
    subprocess.run([*cc.split(), "-shared", "-fPIC", "-O1", "-I", str(SRC),
                    *map(str, sources), "-o", str(tmp)],
                   check=True, capture_output=True, text=True, timeout=900)
    os.replace(tmp, lib)            # atomic: parallel test workers may build it at once
    return lib


def language(cache: Path | None = None):
    """The AIDL grammar as a ``tree_sitter.Language`` (from :func:`build_library`)."""
    import ctypes

    import tree_sitter

    lib = ctypes.CDLL(str(build_library(cache)))
    fn = lib.tree_sitter_aidl_cad
    fn.restype = ctypes.c_void_p
    capsule = ctypes.pythonapi.PyCapsule_New
    capsule.restype = ctypes.py_object
    capsule.argtypes = (ctypes.c_void_p, ctypes.c_char_p, ctypes.c_void_p)
    return tree_sitter.Language(capsule(fn(), b"tree_sitter.Language", None))


# ------------------------------------------------------------------ the sources
def docs_blocks(path: Path) -> list[tuple[int, str]]:
    """The ```aidl blocks of a Markdown file: (line of the first code line, dedented text),
    as tests/test_docs.py reads them."""
    lines = path.read_text(encoding="utf-8").split("\n")
    out, i = [], 0
    while i < len(lines):
        if lines[i].strip() == "```aidl":
            j = i + 1
            while j < len(lines) and lines[j].strip() != "```":
                j += 1
            out.append((i + 2, textwrap.dedent("\n".join(lines[i + 1:j])) + "\n"))
            i = j
        i += 1
    return out


def _rel(p: Path) -> str:
    return p.relative_to(ROOT).as_posix()


def corpus_sources() -> dict[str, list[tuple[str, str]]]:
    """Every example, standard-library file and documentation example by corpus group:
    ``{group: [(title, source), ...]}``; the title is the file (``examples/gear.aidl``) or
    the docs block (``docs/language.md:9``)."""
    def files(folder: Path) -> list[tuple[str, str]]:
        return [(_rel(p), p.read_text(encoding="utf-8"))
                for p in sorted(folder.rglob("*.aidl"), key=_rel)]

    docs = [(f"{_rel(md)}:{line}", text) for md in DOCS for line, text in docs_blocks(md)]
    docs += files(ROOT / "docs" / "figures")
    return {"examples": files(ROOT / "examples"), "stdlib": files(ROOT / "stdlib"),
            "docs": docs}


def lark_syntax_errors(source: str, path: str = "<corpus>") -> list:
    """The errors the Lark parser (aidl_lang/parser.py, the parse alone) reports for ``source``."""
    from aidl_lang.base.diagnostics import DiagnosticSink
    from aidl_lang.parser import parse

    sink = DiagnosticSink()
    parse(source, path, sink)
    return [d for d in sink.items if d.severity == "error"]


# ------------------------------------------------------------------ the corpora
def sexp(node, field: str | None = None, depth: int = 0) -> str:
    """``node``'s named tree as ``tree-sitter test`` writes it (fields, two-space indents)."""
    head = "  " * depth + (f"{field}: " if field else "") + "(" + node.type
    if node.is_missing:
        return "  " * depth + (f"{field}: " if field else "") + f"(MISSING {node.type})"
    if node.type == "ERROR" and node.child_count == 0 and node.text:
        # an error leaf: the character no token starts with, as the CLI writes it
        c = node.text.decode("utf-8", "replace")[0]
        shown = {"\n": "\\n", "\t": "\\t", "\r": "\\r"}.get(c) or (
            c if c.isascii() and c.isprintable() else f"\\u{ord(c)}")
        return "  " * depth + (f"{field}: " if field else "") + f"(UNEXPECTED '{shown}')"
    kids = [(c, node.field_name_for_child(i)) for i, c in enumerate(node.children) if c.is_named]
    if not kids:
        return head + ")"
    return head + "\n" + "\n".join(sexp(c, f, depth + 1) for c, f in kids) + ")"


def has_error(node) -> bool:
    return node.has_error


HEADER = "=" * 80
DIVIDER = "-" * 80


def corpus_entry(title: str, source: str, tree: str | None, error: bool = False) -> str:
    """One ``tree-sitter test`` entry; the 80-character header and divider are longer than
    any ``===``/``---`` line of a source (the CLI takes the longest divider)."""
    attrs = ":error\n" if error else ""
    body = source if source.endswith("\n") else source + "\n"
    out = f"{HEADER}\n{title}\n{attrs}{HEADER}\n\n{body}\n{DIVIDER}\n"
    return out + (f"\n{tree}\n" if tree is not None else "")


def corpora(lang=None) -> dict[Path, str]:
    """The generated corpus files, ``{path: text}``. Raises ``ValueError`` naming the sources
    that parse with an ERROR or MISSING node (and the Lark parser accepts)."""
    import tree_sitter

    parser = tree_sitter.Parser(lang or language())
    texts: dict[str, list[str]] = {g: [] for g in GENERATED_GROUPS}
    bad = []
    for group, items in corpus_sources().items():
        for title, source in items:
            for line in source.splitlines():
                assert not line.startswith((HEADER, DIVIDER)), f"{title}: a divider line"
            tree = parser.parse(source.encode("utf-8"))
            if group == "docs" and lark_syntax_errors(source, title):
                texts["docs-errors"].append(corpus_entry(title, source, None, error=True))
                continue
            if has_error(tree.root_node):
                bad.append(title)
                continue
            texts[group].append(corpus_entry(title, source, sexp(tree.root_node)))
    for title, source in ERROR_CASES:
        tree = parser.parse(source.encode("utf-8"))
        assert tree.root_node.has_error, f"error case {title!r} parses without an error"
        assert lark_syntax_errors(source, title), f"the Lark parser accepts {title!r}"
        texts["errors"].append(corpus_entry(f"error recovery: {title}", source,
                                            sexp(tree.root_node)))
    if bad:
        raise ValueError("these parse with an ERROR or MISSING node: " + ", ".join(bad))
    # the CLI (tree-sitter test --update) writes a blank line between entries
    return {CORPUS / f"{g}.txt": "\n".join(t) for g, t in texts.items() if t}


# ------------------------------------------------------------------ highlights.scm
def _grammar_literals() -> set[str]:
    """The anonymous (literal) node types of the grammar (src/node-types.json)."""
    types = json.loads((SRC / "node-types.json").read_text(encoding="utf-8"))
    return {t["type"] for t in types if not t["named"]}


def _strings(words) -> str:
    return " ".join(json.dumps(w) for w in words)


def _any_of(capture: str, words, node: str = "", negate: bool = False) -> str:
    """``((identifier) @capture (#any-of? @capture "w1" ...))`` (``node``: the pattern instead
    of ``(identifier) @capture``; ``negate``: #not-any-of?)."""
    node = node or f"(identifier) @{capture}"
    pred = "#not-any-of?" if negate else "#any-of?"
    words = sorted(words)
    lines, line = [], ""
    for w in (json.dumps(x) for x in words):
        if len(line) + len(w) + 1 > 88:
            lines.append(line)
            line = ""
        line = (line + " " + w).strip()
    lines.append(line)
    body = "\n    ".join(lines)
    return f"({node}\n  ({pred} @{capture}\n    {body}))"


def highlights_scm() -> str:
    """``queries/highlights.scm``. The patterns do not overlap on a node (an identifier is
    in at most one list; the fallback for calls leaves out every listed name), so editors
    that let the first pattern win (tree-sitter highlight, GitHub, Helix) and those that let
    the last win (Neovim) show the same colours."""
    from aidl_lang.editor.highlight import vocabulary

    v = vocabulary()
    literals = _grammar_literals()

    def kw(words):
        missing = [w for w in words if w not in literals]
        assert not missing, f"not keywords of grammar.js: {missing}"
        return _strings(sorted(words))

    control_if = [w for w in v["control"] if w in ("if", "else", "elif")]
    control_for = [w for w in v["control"] if w in ("for", "in")]
    imports = [w for w in v["declaration"] if w in ("import", "as")]
    functions_kw = [w for w in v["declaration"] if w == "def"]
    other_kw = sorted([w for w in v["declaration"] if w not in imports + functions_kw]
                      + DECLARED_WORDS)
    listed = (set(v["structure_kinds"]) | set(v["constants"]) | set(v["self"])
              | set(v["primitives"]) | set(v["constraints"]) | set(v["functions"]))
    overlap = [w for w in v["functions"] if w in set(v["primitives"]) | set(v["constraints"])]
    assert not overlap, f"a name in two lists: {overlap}"
    units_note = ", ".join(v["units"])
    call = "(call\n  function: (identifier) @{})"
    builtin_calls = _any_of("function.builtin", v["functions"], call.format("function.builtin"))
    other_calls = _any_of("function.call", listed, call.format("function.call"), negate=True)
    return f"""\
; tree-sitter-aidl-cad highlights: the captures the TextMate grammar of the VS Code extension
; (editors/vscode/syntaxes/aidl.tmLanguage.json) gives the same text.
; GENERATED by editors/gen_tree_sitter.py from aidl_lang/registry.py and grammar/aidl.lark
; (the word lists of aidl_lang.editor.highlight.vocabulary): do not edit by hand.
; No two patterns capture one node, so the first-wins and last-wins editors agree.

(comment) @comment

; ---- literals
(number) @number
; the units ({units_note}): keyword.other.unit
(unit) @keyword
(units_declaration
  unit: (identifier) @keyword)
(string) @string
(fstring) @string
(escape_sequence) @string.escape
(format_specifier) @string.special
(interpolation
  "{{" @punctuation.special
  "}}" @punctuation.special)

; ---- keywords (the quoted words of grammar/aidl.lark and its declared statement words)
[{kw(control_if)}] @keyword.conditional
; `in` is a unit too (`units in`, `2 in`): the loop words are taken where loops have them
(for_statement
  [{kw(control_for)}] @keyword.repeat)
(list_comprehension
  [{kw(control_for)}] @keyword.repeat)
(comprehension_for
  [{kw(control_for)}] @keyword.repeat)
[{kw(v["logical"])}] @keyword.operator
[{kw(imports)}] @keyword.import
{kw(functions_kw)} @keyword.function
[{kw(other_kw)}] @keyword

; ---- declarations: storage.type.structure + entity.name.type.structure, def + its name,
; param + its name (variable.other.constant)
(structure_declaration
  name: (identifier) @type.definition)
(kind_assignment
  name: (identifier) @variable)
(function_definition
  name: (identifier) @function)
(template_definition
  name: (identifier) @function)
(value_definition
  name: (identifier) @function)
(param_declaration
  name: (identifier) @constant)
(param_option
  name: (identifier) @variable.parameter)
(parameter
  name: (identifier) @variable.parameter)
(keyword_argument
  name: (identifier) @variable.parameter)
(attribute
  attribute: (identifier) @property)

; ---- the registry's names, wherever they stand: structure kinds (storage.type.structure),
; constants (constant.language), self, primitives (support.class.primitive), constraints
; (support.function.constraint); builtin functions (support.function.builtin) where called
{_any_of("keyword.type", v["structure_kinds"])}

{_any_of("constant.builtin", v["constants"])}

{_any_of("variable.builtin", v["self"])}

{_any_of("type.builtin", v["primitives"])}

{_any_of("function.builtin", v["constraints"])}

{builtin_calls}

; any other name called (entity.name.function.call)
{other_calls}

; ---- operators and punctuation
["+" "-" "*" "/" "//" "%" "**"] @operator
["==" "!=" "<=" ">=" "<" ">"] @operator
["=" ":" "->"] @operator
["," ";" "."] @punctuation.delimiter
["(" ")" "[" "]"] @punctuation.bracket
(block
  ["{{" "}}"] @punctuation.bracket)
"""


def main(argv) -> int:
    targets = [(HIGHLIGHTS, highlights_scm())]
    if "--no-corpus" not in argv:
        targets += sorted(corpora().items())
    stale = write_or_check(targets, argv, Path(__file__).name)
    if "--check" in argv and "--no-corpus" not in argv:
        known = {p for p, _ in targets}
        for extra in sorted(set(CORPUS.glob("*.txt")) - known):
            print(f"{extra.relative_to(ROOT)} is not made by this script: remove it")
            stale = 1
    return stale


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
