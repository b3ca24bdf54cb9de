// aidl studio's code pane: CodeMirror 6 with the AIDL mode, bundled by build.mjs into
// aidl_lang/studio/static/vendor/codemirror/aidl-editor.js (one ES module, no network).
//
//   import { createEditor } from "./vendor/codemirror/aidl-editor.js";
//   const ed = createEditor(parent, { doc, onChange, hover, readOnly, wrap });
//   ed.getText(); ed.setText(text); ed.setDiagnostics(list); ed.view; ed.destroy();
//
// Positions that cross this API count characters as Python does (Unicode code points): the
// diagnostics' 1-based columns and the 0-based offset given to `hover`. CodeMirror counts
// UTF-16 units; the two differ only after a character outside the BMP (an emoji).
import { Annotation, EditorState } from "@codemirror/state";
import {
  EditorView, drawSelection, dropCursor, highlightActiveLine,
  highlightActiveLineGutter, highlightSpecialChars, hoverTooltip, keymap, lineNumbers,
  rectangularSelection,
} from "@codemirror/view";
import { bracketMatching, indentOnInput, syntaxHighlighting } from "@codemirror/language";
import { defaultKeymap, history, historyKeymap, indentWithTab } from "@codemirror/commands";
import { highlightSelectionMatches, searchKeymap } from "@codemirror/search";
import {
  autocompletion, closeBrackets, closeBracketsKeymap, completeFromList, completionKeymap,
} from "@codemirror/autocomplete";
import { lintGutter, lintKeymap, setDiagnostics as lintSetDiagnostics } from "@codemirror/lint";
import { WORDS, aidlHighlighter, aidlIndentUnit, aidlLanguage } from "./aidl-mode.js";

/** Marks the transactions of `setText`, which do not call `onChange`. */
const external = Annotation.define();

const COMPLETIONS = [
  ...[...WORDS.structure_kinds, ...WORDS.control, ...WORDS.logical, ...WORDS.declaration,
    ...WORDS.self].map((label) => ({ label, type: "keyword" })),
  ...WORDS.constants.map((label) => ({ label, type: "constant" })),
  ...WORDS.primitives.map((label) => ({ label, type: "class", detail: "shape" })),
  ...WORDS.constraints.map((label) => ({ label, type: "function", detail: "constraint" })),
  ...WORDS.functions.map((label) => ({ label, type: "function", detail: "builtin" })),
  ...WORDS.units.map((label) => ({ label, type: "text", detail: "unit" })),
];

const MONO = 'ui-monospace, "SFMono-Regular", "DejaVu Sans Mono", Menlo, Consolas, monospace';

const theme = EditorView.theme({
  "&": { height: "100%", fontSize: "13px", backgroundColor: "#ffffff", color: "#24292f" },
  "&.cm-focused": { outline: "none" },
  ".cm-scroller": { fontFamily: MONO, lineHeight: "1.5", overflow: "auto" },
  ".cm-content": { caretColor: "#24292f" },
  // line numbers at 5:1 contrast on the gutter (WCAG AA; was #8c959f, 2.85:1)
  ".cm-gutters": { backgroundColor: "#f6f8fa", color: "#57606a", borderRight: "1px solid #e1e4e8" },
  ".cm-activeLine": { backgroundColor: "#f5f8ff" },
  ".cm-activeLineGutter": { backgroundColor: "#eaeef2", color: "#24292f" },
  "&.cm-focused .cm-selectionBackground, .cm-selectionBackground, ::selection":
    { backgroundColor: "#cfe3ff" },
  "&.cm-focused .cm-matchingBracket": { backgroundColor: "#d8f0dc", outline: "1px solid #9ccfa6" },
  ".cm-tooltip": { fontFamily: MONO, fontSize: "12px", border: "1px solid #d0d7de",
    backgroundColor: "#ffffff", boxShadow: "0 2px 8px rgba(0,0,0,0.12)", borderRadius: "4px" },
  ".cm-aidl-hover": { margin: "0", padding: "6px 9px", maxWidth: "60em", maxHeight: "24em",
    overflow: "auto", whiteSpace: "pre-wrap", fontFamily: MONO, fontSize: "12px" },
  ".cm-diagnosticSource": { fontSize: "11px", opacity: "0.75" },
  ".cm-aidl-structure": { color: "#8250df", fontWeight: "600" },
  ".cm-aidl-control, .cm-aidl-logical, .cm-aidl-keyword": { color: "#cf222e" },
  ".cm-aidl-self": { color: "#cf222e", fontStyle: "italic" },
  ".cm-aidl-constant": { color: "#0550ae" },
  ".cm-aidl-primitive": { color: "#0a7a6c", fontWeight: "600" },
  ".cm-aidl-constraint": { color: "#0550ae" },
  ".cm-aidl-builtin, .cm-aidl-call": { color: "#6639ba" },
  ".cm-aidl-defname": { color: "#953800", fontWeight: "600" },
  ".cm-aidl-number": { color: "#0550ae" },
  ".cm-aidl-unit": { color: "#1a7f37" },
  ".cm-aidl-string": { color: "#0a3069" },
  ".cm-aidl-comment": { color: "#57606a", fontStyle: "italic" },   // 5.9:1 on the active line
  ".cm-aidl-operator": { color: "#57606a" },
}, { dark: false });

const toCodePoints = (s) => {
  let n = 0;
  for (let i = 0; i < s.length; i++, n++) {
    const c = s.charCodeAt(i);
    if (c >= 0xd800 && c < 0xdc00 && i + 1 < s.length) i++;
  }
  return n;
};

/** The UTF-16 offset in `text` of its `cp`-th code point (clamped to the text). */
const fromCodePoints = (text, cp) => {
  let i = 0;
  for (let n = 0; n < cp && i < text.length; n++) {
    const c = text.charCodeAt(i);
    i += c >= 0xd800 && c < 0xdc00 && i + 1 < text.length ? 2 : 1;
  }
  return i;
};

const int = (v, dflt) => {
  const n = Math.floor(Number(v));
  return Number.isFinite(n) ? n : dflt;
};

/** The document offset of 1-based (line, col), clamped into the document. */
function offset(doc, line, col) {
  const l = doc.line(Math.min(Math.max(int(line, 1), 1), doc.lines));
  return l.from + fromCodePoints(l.text, Math.max(int(col, 1), 1) - 1);
}

const SEVERITY = { error: "error", warning: "warning", warn: "warning", info: "info",
  information: "info", hint: "hint" };

/** `list` (the studio's diagnostics) as @codemirror/lint diagnostics; bad items are skipped. */
function toLint(doc, list) {
  const out = [];
  for (const d of Array.isArray(list) ? list : []) {
    if (!d || typeof d !== "object") continue;
    const line = d.from ?? d.line ?? 1;
    const from = offset(doc, line, d.col ?? 1);
    let to = offset(doc, d.to_line ?? line, d.to_col ?? d.col ?? 1);
    if (to < from) to = from;
    if (to === from) {                      // a point: the word there, or one character
      const l = doc.lineAt(from), rest = l.text.slice(from - l.from);
      const word = /^[\w.]+/.exec(rest);
      to = from + (word ? word[0].length : Math.min(1, rest.length));
    }
    const item = {
      from, to,
      severity: SEVERITY[String(d.severity).toLowerCase()] || "error",
      message: d.message == null ? "" : String(d.message),
    };
    if (d.code) item.source = String(d.code);
    out.push(item);
  }
  return out;
}

function hoverExtension(hover) {
  return hoverTooltip(async (view, pos) => {
    const doc = view.state.doc, text = doc.toString();
    let result;
    try {
      result = await hover(text, toCodePoints(text.slice(0, pos)));
    } catch (e) {
      console.error("aidl-editor: hover failed", e);
      return null;
    }
    if (result == null || result === "" || view.state.doc !== doc) return null;
    const l = doc.lineAt(pos);
    let start = pos, end = pos;
    while (start > l.from && /\w/.test(l.text[start - l.from - 1])) start--;
    while (end < l.to && /\w/.test(l.text[end - l.from])) end++;
    return {
      pos: start, end, above: true,
      create() {
        const dom = document.createElement("pre");
        dom.className = "cm-aidl-hover";
        dom.textContent = String(result);   // plain text: never parsed as HTML
        return { dom };
      },
    };
  }, { hoverTime: 350 });
}

/**
 * Make an AIDL editor in `parent` (an element with a CSS height; the editor fills it).
 * `onChange(text)` is called with the whole text after each user edit (not after setText);
 * `hover(text, pos)` resolves to null or plain text shown in a tooltip; `wrap`: long lines
 * wrap instead of scrolling sideways; `label`: the text area's accessible name (screen
 * readers; it is also a tab stop of its own, tabindex 0).  Tab is not bound: it moves the focus to the next control,
 * as CodeMirror's `indentWithTab` guidance asks of a page a keyboard user must leave
 * (indent with Ctrl-] and Ctrl-[, Cmd on a Mac); `tabIndents: true` binds it to indent instead
 * (then Escape, Tab leaves the editor).
 */
export function createEditor(parent, {
  doc = "", onChange = (text) => {}, hover = async (text, pos) => null, readOnly = false,
  wrap = false, tabIndents = false, label = "AIDL program",
} = {}) {
  const extensions = [
    lineNumbers(),
    highlightActiveLineGutter(),
    highlightSpecialChars(),
    history(),
    drawSelection(),
    dropCursor(),
    EditorState.allowMultipleSelections.of(true),
    indentOnInput(),
    aidlLanguage,
    aidlIndentUnit,
    syntaxHighlighting(aidlHighlighter),
    bracketMatching(),
    closeBrackets(),
    autocompletion({ activateOnTyping: true }),
    aidlLanguage.data.of({ autocomplete: completeFromList(COMPLETIONS) }),
    rectangularSelection(),
    highlightActiveLine(),
    highlightSelectionMatches(),
    lintGutter(),
    keymap.of([
      ...closeBracketsKeymap, ...defaultKeymap, ...searchKeymap, ...historyKeymap,
      ...completionKeymap, ...lintKeymap, ...(tabIndents ? [indentWithTab] : []),
    ]),
    theme,
    EditorView.contentAttributes.of({ "aria-label": String(label), tabindex: "0" }),
    EditorState.readOnly.of(!!readOnly),
    EditorView.updateListener.of((u) => {
      if (!u.docChanged || !u.transactions.some((tr) => tr.docChanged && !tr.annotation(external))) {
        return;
      }
      try {
        onChange(u.state.doc.toString());
      } catch (e) {
        console.error("aidl-editor: onChange failed", e);
      }
    }),
  ];
  if (hover) extensions.push(hoverExtension(hover));
  if (wrap) extensions.push(EditorView.lineWrapping);   // long lines wrap in a narrow pane
  const view = new EditorView({
    parent,
    state: EditorState.create({ doc: String(doc ?? ""), extensions }),
  });
  return {
    view,
    getText: () => view.state.doc.toString(),
    /** Replace the whole text (no onChange); the old diagnostics are cleared. */
    setText(text) {
      text = String(text ?? "");
      if (text === view.state.doc.toString()) return;
      view.dispatch(
        { changes: { from: 0, to: view.state.doc.length, insert: text },
          annotations: external.of(true) },
        lintSetDiagnostics(view.state, []));
    },
    /** Show `list` ({from: line, col, to_line, to_col, severity, message, code}, 1-based). */
    setDiagnostics(list) {
      let diags;
      try {
        diags = toLint(view.state.doc, list);
      } catch (e) {
        console.error("aidl-editor: bad diagnostics", e);
        diags = [];
      }
      view.dispatch(lintSetDiagnostics(view.state, diags));
    },
    destroy: () => view.destroy(),
  };
}
