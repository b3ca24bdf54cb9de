// Tokenize every examples/*.aidl with the extension's TextMate grammar (vscode-textmate +
// vscode-oniguruma, the engine VS Code uses) and check the scopes of keywords, structure
// kinds, primitives, constraints, numbers with units, strings and comments.
'use strict';
const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const path = require('node:path');
const vsctm = require('vscode-textmate');
const onig = require('vscode-oniguruma');

const ROOT = path.resolve(__dirname, '..', '..', '..');
const GRAMMAR = path.join(__dirname, '..', 'syntaxes', 'aidl.tmLanguage.json');
const EXAMPLES = fs.readdirSync(path.join(ROOT, 'examples'))
  .filter((f) => f.endsWith('.aidl')).map((f) => path.join(ROOT, 'examples', f))
  .concat([path.join(ROOT, 'examples', 'parts', 'gears.aidl')]);

let grammarPromise;
function grammar() {
  if (!grammarPromise) {
    const wasm = fs.readFileSync(path.join(path.dirname(require.resolve('vscode-oniguruma')), 'onig.wasm'));
    const onigLib = onig.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength)).then(() => ({
      createOnigScanner: (p) => new onig.OnigScanner(p),
      createOnigString: (s) => new onig.OnigString(s),
    }));
    const registry = new vsctm.Registry({
      onigLib,
      loadGrammar: async (scope) => (scope === 'source.aidl-cad'
        ? vsctm.parseRawGrammar(fs.readFileSync(GRAMMAR, 'utf8'), GRAMMAR) : null),
    });
    grammarPromise = registry.loadGrammar('source.aidl-cad');
  }
  return grammarPromise;
}

// -> array of lines, each an array of {start, end, text, scopes}
async function tokenize(src) {
  const g = await grammar();
  let stack = vsctm.INITIAL;
  return src.split('\n').map((line) => {
    const r = g.tokenizeLine(line, stack);
    stack = r.ruleStack;
    return r.tokens.map((t) => ({ start: t.startIndex, end: t.endIndex,
      text: line.slice(t.startIndex, t.endIndex), scopes: t.scopes }));
  });
}

function scopesAt(lines, li, col) {
  const tok = lines[li].find((t) => t.start <= col && col < t.end);
  return tok ? tok.scopes.join(' ') : '';
}

function tokenAt(lines, li, col) {
  return lines[li].find((t) => t.start <= col && col < t.end);
}

const inCode = (s) => !/\b(comment|string)\./.test(s);

function* matches(src, re) {
  const lines = src.split('\n');
  for (let li = 0; li < lines.length; li++) {
    for (const m of lines[li].matchAll(re)) yield { li, m, col: m.index, line: lines[li] };
  }
}

for (const file of EXAMPLES) {
  const name = path.relative(ROOT, file);
  test(`scopes in ${name}`, async () => {
    const src = fs.readFileSync(file, 'utf8');
    const lines = await tokenize(src);
    let checked = 0;
    // whole-line comments are comments from their first character to the end
    for (const { li, col, line } of matches(src, /^\s*(#|\/\/)/g)) {
      const start = line.search(/\S/);
      for (const t of lines[li]) {
        if (t.end > start) assert.match(t.scopes.join(' '), /comment\.line/, `${name}:${li + 1}: ${line}`);
      }
      checked++;
    }
    // trailing comments after code (lines without strings)
    for (const { li, col, line } of matches(src, /^[^#"'\/]*\S[^#"'\/]*(#.*)$/g)) {
      const c = line.indexOf('#');
      assert.match(scopesAt(lines, li, c), /comment\.line\.number-sign/, `${name}:${li + 1}`);
      assert.ok(inCode(scopesAt(lines, li, line.search(/\S/))), `${name}:${li + 1}: code read as comment`);
      checked++;
    }
    // structure declarations: kind and name
    for (const { li, m, col } of matches(src, /^\s*(solid|hole|drawing|assembly)\s+(\w+)\s*\{/g)) {
      const k = m[0].indexOf(m[1]);
      const n = m[0].indexOf(m[2], k + m[1].length);
      assert.match(scopesAt(lines, li, col + k), /storage\.type\.structure/, `${name}:${li + 1}`);
      assert.match(scopesAt(lines, li, col + n), /entity\.name\.type\.structure/, `${name}:${li + 1}`);
      checked++;
    }
    // keywords in code
    for (const { li, m, col } of matches(src, /\b(param|for|in|if|else|elif|units|def|import|and|or|not|self|true|false)\b/g)) {
      const s = scopesAt(lines, li, col);
      if (!inCode(s)) continue;
      if (m[1] === 'in' && /keyword\.other\.unit/.test(s)) continue; // `2 in`: inches
      assert.match(s, /keyword\.|storage\.|variable\.language|constant\.language/, `${name}:${li + 1}: ${m[1]} -> ${s}`);
      checked++;
    }
    // capitalised calls are the registry's primitives or constraints
    for (const { li, m, col } of matches(src, /\b([A-Z]\w*)\s*\(/g)) {
      const s = scopesAt(lines, li, col);
      if (!inCode(s)) continue;
      assert.match(s, /support\.class\.primitive|support\.function\.constraint/, `${name}:${li + 1}: ${m[1]}`);
      checked++;
    }
    // numbers with units: the number and the unit
    for (const { li, m, col } of matches(src, /(?<![\w.])(\d+\.?\d*|\.\d+)([ \t]*)(mm|cm|deg|rad|in|ft|°)(?!\w)/g)) {
      const s = scopesAt(lines, li, col);
      if (!inCode(s)) continue;
      assert.match(s, /constant\.numeric/, `${name}:${li + 1}: ${m[0]}`);
      const u = col + m[1].length + m[2].length;
      assert.match(scopesAt(lines, li, u), /keyword\.other\.unit/, `${name}:${li + 1}: ${m[0]}`);
      checked++;
    }
    assert.ok(checked > 10, `${name}: only ${checked} checks`);
  });
}

test('primitives and constraints are told apart', async () => {
  const src = fs.readFileSync(path.join(ROOT, 'examples', 'telephone.aidl'), 'utf8');
  const lines = await tokenize(src);
  const find = (word) => {
    for (const { li, col } of matches(src, new RegExp(`\\b${word}\\(`, 'g'))) return scopesAt(lines, li, col);
    return '';
  };
  for (const p of ['Circle', 'Polygon', 'RoundedRectangle', 'Text', 'Line', 'Arc', 'Rectangle']) {
    assert.match(find(p), /support\.class\.primitive\.aidl-cad/, p);
  }
  for (const c of ['OnCircle', 'Concentric', 'AlignBottom', 'Horizontal', 'HorizontalDistance', 'Above', 'AlignCenterX', 'Coincident']) {
    assert.match(find(c), /support\.function\.constraint\.aidl-cad/, c);
  }
});

test('strings, f-strings, comments and floor division', async () => {
  const src = [
    'label = f"{w:.1f} mm" + "text # not a comment"',
    'half = w // 2',
    '// a comment at the start of a line',
    'x = 3 // half of the width',
    '/* block',
    '   comment */ y = 30°',
    'r = 0.5 in + 2.5in + 10mm',
  ].join('\n');
  const lines = await tokenize(src);
  assert.match(scopesAt(lines, 0, 8), /string\.interpolated/);
  assert.match(scopesAt(lines, 0, 11), /meta\.interpolation/);                  // `w` in {w:.1f}
  assert.match(scopesAt(lines, 0, 30), /string\.quoted\.double/);               // `#` in a string
  assert.doesNotMatch(scopesAt(lines, 1, 9), /comment/);                        // `//` operator
  assert.match(scopesAt(lines, 1, 9), /keyword\.operator\.arithmetic/);
  assert.match(scopesAt(lines, 2, 0), /comment\.line\.double-slash/);
  assert.match(scopesAt(lines, 3, 6), /comment\.line\.double-slash/);           // followed by prose
  assert.match(scopesAt(lines, 4, 0), /comment\.block/);
  assert.match(scopesAt(lines, 5, 5), /comment\.block/);
  assert.match(scopesAt(lines, 5, 18), /constant\.numeric/);
  assert.match(scopesAt(lines, 5, 20), /keyword\.other\.unit/);                 // °
  for (const [col, re] of [[4, /constant\.numeric/], [8, /keyword\.other\.unit/], [13, /constant\.numeric/],
    [16, /keyword\.other\.unit/], [21, /constant\.numeric/], [23, /keyword\.other\.unit/]]) {
    assert.match(scopesAt(lines, 6, col), re, `col ${col}: ${tokenAt(lines, 6, col).text}`);
  }
});
