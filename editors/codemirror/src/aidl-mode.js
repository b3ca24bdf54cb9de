// The AIDL mode of the studio's editor: a CodeMirror StreamLanguage whose word lists are
// words.json, written by editors/gen_grammar.py from the registry and grammar/aidl.lark (the
// same lists as the VS Code TextMate grammar). It follows that grammar's rules: `#` comments,
// `/* */` blocks, `//` comments (at a line's start, alone, or before prose, else floor
// division), "..." and '...' strings with an optional f prefix, numbers with a unit suffix.
import { StreamLanguage, indentUnit } from "@codemirror/language";
import { Tag, tags as t, tagHighlighter } from "@lezer/highlight";
import WORDS from "./words.json";

// One tag per category, each a sub-tag of a standard one (other highlighters still colour
// them; a sub-tag's parent cannot be a modified tag such as t.function(...)); the class names
// below are what the page's styles and tests see.
const T = {
  structure: Tag.define(t.definitionKeyword),
  control: Tag.define(t.controlKeyword),
  logical: Tag.define(t.operatorKeyword),
  keyword: Tag.define(t.keyword),
  self: Tag.define(t.self),
  constant: Tag.define(t.bool),
  primitive: Tag.define(t.className),
  constraint: Tag.define(t.variableName),
  builtin: Tag.define(t.variableName),
  call: Tag.define(t.variableName),
  defname: Tag.define(t.variableName),
  number: Tag.define(t.number),
  unit: Tag.define(t.unit),
  string: Tag.define(t.string),
  comment: Tag.define(t.comment),
  operator: Tag.define(t.operator),
  punctuation: Tag.define(t.punctuation),
  property: Tag.define(t.propertyName),
  variable: Tag.define(t.variableName),
};

/** Highlighter: the token of category `k` gets class `cm-aidl-k` (e.g. `cm-aidl-structure`). */
export const aidlHighlighter = tagHighlighter(
  Object.entries(T).map(([k, tag]) => ({ tag, class: `cm-aidl-${k}` })));

const set = (...lists) => new Set(lists.flat());
const STRUCTURE = set(WORDS.structure_kinds);
const CONTROL = set(WORDS.control);
const LOGICAL = set(WORDS.logical);
const DECLARATION = set(WORDS.declaration);
const SELF = set(WORDS.self);
const CONSTANTS = set(WORDS.constants);
const PRIMITIVES = set(WORDS.primitives);
const CONSTRAINTS = set(WORDS.constraints);
const FUNCTIONS = set(WORDS.functions);
const UNITS = [...WORDS.units].sort((a, b) => b.length - a.length || (a < b ? -1 : 1));
const esc = (w) => w.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");
const UNIT_RE = new RegExp(`^(?:${UNITS.map(esc).join("|")})\\b|^°`);
const PROSE = WORDS.prose.join("|");
// the TextMate grammar's `//`-is-a-comment rule, for the text after the `//`
const SLASH_COMMENT = new RegExp(
  `^(?:[ \\t]*$|[^#\\n]*?\\b(?!(?:${PROSE})\\b)[A-Za-z_]\\w*[ \\t]+(?!(?:${PROSE})\\b)[A-Za-z_]` +
  `|[^#\\n]*?[^\\w\\s.()\\[\\]+\\-*/%,<>=!#])`);
const NUMBER = /^(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?/;
const IDENT = /^[A-Za-z_]\w*/;

const INDENT = 4;
const OPEN = "([{", CLOSE = ")]}";

/** Read the rest of a string opened by `quote` (an unclosed string ends with its line). */
function skipString(stream, quote) {
  let escaped = false, ch;
  while ((ch = stream.next()) != null) {
    if (ch === quote && !escaped) return;
    escaped = !escaped && ch === "\\";
  }
}

// The tokens' names are T's keys prefixed with `aidl-`: StreamLanguage reads some bare names
// ("variable", "builtin", "property", "def", ...) as its own legacy ones before the tokenTable.
const TABLE = Object.fromEntries(Object.entries(T).map(([k, tag]) => [`aidl-${k}`, tag]));

function token(stream, state) {
  const k = category(stream, state);
  return k && `aidl-${k}`;
}

const parser = {
  name: "aidl",
  startState: () => ({ block: false, next: null, unit: false, dot: false, depth: 0 }),
  copyState: (s) => ({ ...s }),
  token,
  indent(state, textAfter) {
    // one level per open bracket at the line's start; a line starting with a closer: one less
    const closes = /^\s*[)\]}]/.test(textAfter) ? 1 : 0;
    return Math.max(0, state.depth - closes) * INDENT;
  },
  tokenTable: TABLE,
  languageData: {
    commentTokens: { line: "#", block: { open: "/*", close: "*/" } },
    closeBrackets: { brackets: ["(", "[", "{", '"', "'"] },
    indentOnInput: /^\s*[)\]}]$/,
  },
};

/** The category (a key of T) of the token at `stream`, which it reads; null for none. */
function category(stream, state) {
  if (stream.sol()) state.unit = false;
  if (state.block) {
    if (stream.skipTo("*/")) { stream.pos += 2; state.block = false; } else stream.skipToEnd();
    return "comment";
  }
  if (stream.eatSpace()) return null;
  const unit = state.unit;
  state.unit = false;
  if (unit && stream.match(UNIT_RE)) return "unit";
  const ch = stream.peek();
  if (ch === "#") { stream.skipToEnd(); return "comment"; }
  if (stream.match("/*")) {
    state.block = true;
    if (stream.skipTo("*/")) { stream.pos += 2; state.block = false; } else stream.skipToEnd();
    return "comment";
  }
  if (stream.match("//", false)) {
    const before = stream.string.slice(0, stream.pos);
    if (/^\s*$/.test(before) || SLASH_COMMENT.test(stream.string.slice(stream.pos + 2))) {
      stream.skipToEnd();
      return "comment";
    }
    stream.pos += 2;
    return "operator";
  }
  if (stream.match(/^[fF]?["']/)) {
    skipString(stream, stream.current().slice(-1));
    return "string";
  }
  const prev = stream.pos > 0 ? stream.string[stream.pos - 1] : "";
  if (!/[\w.]/.test(prev) && stream.match(NUMBER)) { state.unit = true; return "number"; }
  if (stream.match(IDENT)) {
    const w = stream.current(), next = state.next, dot = state.dot;
    state.next = null;
    state.dot = false;
    if (next === "name") return "defname";
    if (next === "unit" && UNITS.includes(w)) return "unit";
    if (dot) return "property";
    if (STRUCTURE.has(w)) { state.next = "name"; return "structure"; }
    if (CONTROL.has(w)) return "control";
    if (LOGICAL.has(w)) return "logical";
    if (DECLARATION.has(w)) {
      if (w === "def" || w === "param") state.next = "name";
      else if (w === "units") state.next = "unit";
      return "keyword";
    }
    if (SELF.has(w)) return "self";
    if (CONSTANTS.has(w)) return "constant";
    if (PRIMITIVES.has(w)) return "primitive";
    if (CONSTRAINTS.has(w)) return "constraint";
    const call = stream.match(/^[ \t]*\(/, false);
    if (call) return FUNCTIONS.has(w) ? "builtin" : "call";
    return "variable";
  }
  state.next = null;
  if (stream.match("->") || stream.match(/^(?:==|!=|<=|>=|\*\*|[<>\-+*/%=:])/)) {
    return "operator";
  }
  stream.next();
  if (ch === ".") { state.dot = true; return "punctuation"; }
  if (OPEN.includes(ch)) { state.depth++; return "punctuation"; }
  if (CLOSE.includes(ch)) { state.depth = Math.max(0, state.depth - 1); return "punctuation"; }
  if (ch === "," || ch === ";") return "punctuation";
  return null;
}

export const aidlLanguage = StreamLanguage.define(parser);
export const aidlIndentUnit = indentUnit.of(" ".repeat(INDENT));
export { WORDS };
