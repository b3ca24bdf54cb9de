/**
 * @file AIDL (CAD): a solver-aided hierarchical 2D CAD language. Written from
 *   grammar/aidl.lark (the reference grammar: every rule there has its rule here).
 * @license Apache-2.0
 */

/// <reference types="tree-sitter-cli/dsl" />
// @ts-check

// Precedences, lowest first, as the `?expr` chain of grammar/aidl.lark.
const PREC = {
  ternary: 1,
  or: 2,
  and: 3,
  not: 4,
  compare: 5,
  sum: 6,
  product: 7,
  unary: 8,
  power: 9,
  postfix: 10,
};

// The units a number may carry (the NUMBER terminal of grammar/aidl.lark).
const UNITS = ['mm', 'cm', 'm', 'inches', 'inch', 'in', 'ft', 'deg', 'rad', '°'];

/**
 * Comma-separated, at least one, an optional trailing comma.
 * @param {RuleOrLiteral} rule
 */
function commaSep1(rule) {
  return seq(rule, repeat(seq(',', rule)), optional(','));
}

/**
 * A list of statements as grammar/aidl.lark writes `(_stmt _sep+)* _stmt?`, with the
 * post-lexer's rule that a closing `}` ends a statement: a statement that ends with a block
 * needs no separator after it.
 * @param {GrammarSymbols<string>} $
 * @param {RuleOrLiteral} simple
 * @param {RuleOrLiteral} compound
 */
function statements($, simple, compound) {
  return seq(
    repeat($._sep),
    repeat(choice(
      seq(simple, repeat1($._sep)),
      seq(compound, repeat($._sep)),
    )),
    optional(simple),
  );
}

export default grammar({
  name: 'aidl_cad',

  word: $ => $.identifier,

  // Newlines are tokens only where a statement may end (the scanner reads them, and drops
  // the ones before `else`/`elif`, as the post-lexer of aidl_lang/parser.py does); inside
  // () and [] no statement can end, so there they are whitespace.
  externals: $ => [
    $._newline,
    $.comment,
    $._floor_div,
    $._fstring_content_double,
    $._fstring_content_single,
    $._string_content_double,
    $._string_content_single,
    $._error_sentinel,
  ],

  extras: $ => [/[ \t\f\r\n\v\u00a0\ufeff]/, $.comment],

  supertypes: $ => [$._expression],

  rules: {
    source_file: $ => statements($, $._top_simple_statement, $._top_compound_statement),

    _sep: $ => choice($._newline, ';'),

    _top_simple_statement: $ => choice(
      $.units_declaration,
      $.import_declaration,
      $.param_declaration,
      $._simple_statement,
    ),

    _top_compound_statement: $ => $._compound_statement,

    // a `def` may stand in a structure too (the parser hoists it above the structure)
    _simple_statement: $ => choice(
      $.value_definition,
      $.thickness_declaration,
      $.kerf_declaration,
      $.min_wall_declaration,
      $.assignment,
      $.kind_assignment,
      $.assert_statement,
      $.expression_statement,
    ),

    _compound_statement: $ => choice(
      $.function_definition,
      $.template_definition,
      $.structure_declaration,
      $.for_statement,
      $.if_statement,
      $.block,
    ),

    // ---------------------------------------------------------------- top level only
    units_declaration: $ => seq('units', field('unit', choice($.unit, $.identifier))),

    import_declaration: $ => seq(
      'import',
      field('path', choice($.string, $.dotted_name)),
      optional(seq('as', field('alias', $.identifier))),
    ),

    dotted_name: $ => seq($.identifier, repeat(seq('.', $.identifier))),

    param_declaration: $ => seq(
      'param',
      field('name', $.identifier),
      '=',
      field('value', $._expression),
      repeat(seq(',', $.param_option)),
    ),

    // min=, max=, step= (the slider range)
    param_option: $ => seq(
      field('name', $.identifier),
      choice('=', ':'),
      field('value', $._expression),
    ),

    // ---------------------------------------------------------------- definitions (top level or in a structure)
    // def NAME(params) -> KIND { ... }
    function_definition: $ => seq(
      'def',
      field('name', $.identifier),
      field('parameters', $.parameters),
      '->',
      field('kind', $.identifier),
      field('body', $.block),
    ),

    // def NAME(params) = EXPR: a function, its value (a simple statement: one line)
    value_definition: $ => seq(
      'def',
      field('name', $.identifier),
      field('parameters', $.parameters),
      '=',
      field('value', $._expression),
    ),

    // KIND NAME(params) { ... }: the short form of a template definition
    template_definition: $ => seq(
      field('kind', $.identifier),
      field('name', $.identifier),
      field('parameters', $.parameters),
      field('body', $.block),
    ),

    parameters: $ => seq('(', optional(commaSep1($.parameter)), ')'),

    parameter: $ => seq(
      field('name', $.identifier),
      optional(seq(choice('=', ':'), field('default', $._expression))),
    ),

    // ---------------------------------------------------------------- statements
    // KIND NAME { ... }
    structure_declaration: $ => seq(
      field('kind', $.identifier),
      field('name', $.identifier),
      field('body', $.block),
    ),

    // `thickness 3 mm`; `thickness = 3` stays an assignment (see assignment; so `units = 3`)
    thickness_declaration: $ => seq('thickness', field('value', $._expression)),
    kerf_declaration: $ => seq('kerf', field('value', $._expression)),
    min_wall_declaration: $ => seq('min_wall', field('value', $._expression)),

    assignment: $ => seq(
      field('name', choice(
        $.identifier,
        alias(choice('thickness', 'kerf', 'min_wall', 'units'), $.identifier),
      )),
      '=',
      field('value', $._expression),
    ),

    // `hole h = outline(...)`: a template instance of the kind written
    kind_assignment: $ => seq(
      field('kind', $.identifier),
      field('name', $.identifier),
      '=',
      field('value', $._expression),
    ),

    for_statement: $ => seq(
      'for',
      field('variable', $.identifier),
      'in',
      field('iterable', $._expression),
      field('body', $.block),
    ),

    if_statement: $ => seq(
      'if',
      field('condition', $._expression),
      field('consequence', $.block),
      optional(field('alternative', choice($.else_clause, $.elif_clause))),
    ),

    else_clause: $ => seq('else', field('body', choice($.block, $.if_statement))),

    elif_clause: $ => seq(
      'elif',
      field('condition', $._expression),
      field('consequence', $.block),
      optional(field('alternative', choice($.else_clause, $.elif_clause))),
    ),

    // assert COND [, "message"]: checked at the solved values, not a constraint
    assert_statement: $ => seq(
      'assert',
      field('condition', $._expression),
      optional(seq(',', field('message', $.string))),
    ),

    // `thickness` alone on its line is a name, as in the Lark parser (its post-lexer makes a
    // THICKNESS of it only before a number, a name or a sign)
    expression_statement: $ => choice(
      $._expression,
      alias(choice('thickness', 'kerf', 'min_wall', 'units'), $.identifier),
    ),

    block: $ => seq(
      '{',
      statements($, $._simple_statement, $._compound_statement),
      '}',
    ),

    // ---------------------------------------------------------------- expressions
    _expression: $ => choice(
      $.conditional_expression,
      $.boolean_operator,
      $.not_operator,
      $.comparison_operator,
      $._primary_expression,
    ),

    // what binds tighter than a comparison (Lark's `sum` and below): arithmetic, calls,
    // members, subscripts, atoms
    _primary_expression: $ => choice(
      $.binary_expression,
      $.unary_expression,
      $.call,
      $.attribute,
      $.subscript,
      $.number,
      $.string,
      $.fstring,
      $.identifier,
      $.parenthesized_expression,
      $.tuple,
      $.list,
      $.list_comprehension,
    ),

    conditional_expression: $ => prec.right(PREC.ternary, seq(
      field('consequence', $._expression),
      'if',
      field('condition', $._expression),
      'else',
      field('alternative', $._expression),
    )),

    boolean_operator: $ => choice(
      prec.left(PREC.or, seq(
        field('left', $._expression), field('operator', 'or'), field('right', $._expression))),
      prec.left(PREC.and, seq(
        field('left', $._expression), field('operator', 'and'), field('right', $._expression))),
    ),

    not_operator: $ => prec(PREC.not, seq('not', field('argument', $._expression))),

    // a < b <= c: one chain, as Lark's `compare`, whose operands are sums (arithmetic and
    // what binds tighter): `a == 1 or b == 2` is two comparisons joined by `or`
    comparison_operator: $ => prec.left(PREC.compare, seq(
      $._primary_expression,
      repeat1(seq(
        field('operators', choice('==', '!=', '<=', '>=', '<', '>')),
        $._primary_expression,
      )),
    )),

    binary_expression: $ => choice(
      ...[['+', PREC.sum], ['-', PREC.sum]].map(([op, p]) => prec.left(p, seq(
        field('left', $._primary_expression),
        field('operator', op),
        field('right', $._primary_expression),
      ))),
      ...['*', '/', '%'].map(op => prec.left(PREC.product, seq(
        field('left', $._primary_expression),
        field('operator', op),
        field('right', $._primary_expression),
      ))),
      prec.left(PREC.product, seq(
        field('left', $._primary_expression),
        field('operator', alias($._floor_div, '//')),
        field('right', $._primary_expression),
      )),
      prec.right(PREC.power, seq(
        field('left', $._primary_expression),
        field('operator', '**'),
        field('right', $._primary_expression),
      )),
    ),

    unary_expression: $ => prec(PREC.unary, seq(
      field('operator', choice('-', '+')),
      field('argument', $._primary_expression),
    )),

    call: $ => prec(PREC.postfix, seq(
      field('function', $._primary_expression),
      field('arguments', $.argument_list),
    )),

    argument_list: $ => seq(
      '(',
      optional(commaSep1(choice($._expression, $.keyword_argument))),
      ')',
    ),

    keyword_argument: $ => seq(
      field('name', $.identifier),
      choice('=', ':'),
      field('value', $._expression),
    ),

    attribute: $ => prec(PREC.postfix, seq(
      field('object', $._primary_expression),
      '.',
      field('attribute', $.identifier),
    )),

    subscript: $ => prec(PREC.postfix, seq(
      field('value', $._primary_expression),
      '[',
      field('index', $._expression),
      ']',
    )),

    parenthesized_expression: $ => seq('(', $._expression, ')'),

    tuple: $ => seq(
      '(',
      $._expression,
      ',',
      optional(commaSep1($._expression)),
      ')',
    ),

    list: $ => seq('[', optional(commaSep1($._expression)), ']'),

    list_comprehension: $ => seq(
      '[',
      field('element', $._expression),
      'for',
      field('variable', $.identifier),
      'in',
      field('iterable', $._expression),
      optional(seq('if', field('filter', $._expression))),
      repeat($.comprehension_for),
      ']',
    ),

    // a further `for` of a comprehension, as Python nests them: `[f(a, b) for a in xs for b in ys]`
    comprehension_for: $ => seq(
      'for',
      field('variable', $.identifier),
      'in',
      field('iterable', $._expression),
      optional(seq('if', field('filter', $._expression))),
    ),

    // ---------------------------------------------------------------- literals
    number: $ => seq(
      /(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?/,
      optional(field('unit', $.unit)),
    ),

    unit: _ => choice(...UNITS),

    // one line, escapes `\\x` (as the STRING terminal)
    string: $ => choice(
      seq(
        '"',
        repeat(choice(alias($._string_content_double, $.string_content), $.escape_sequence)),
        token.immediate('"'),
      ),
      seq(
        "'",
        repeat(choice(alias($._string_content_single, $.string_content), $.escape_sequence)),
        token.immediate("'"),
      ),
    ),

    fstring: $ => choice(
      seq(
        alias(/[fF]"/, '"'),
        repeat(choice(
          alias($._fstring_content_double, $.string_content),
          $.escape_sequence,
          $.interpolation,
        )),
        token.immediate('"'),
      ),
      seq(
        alias(/[fF]'/, "'"),
        repeat(choice(
          alias($._fstring_content_single, $.string_content),
          $.escape_sequence,
          $.interpolation,
        )),
        token.immediate("'"),
      ),
    ),

    escape_sequence: _ => token.immediate(/\\./),

    interpolation: $ => seq(
      token.immediate('{'),
      field('expression', $._expression),
      optional(field('format', $.format_specifier)),
      '}',
    ),

    format_specifier: _ => seq(':', optional(token.immediate(prec(1, /[^}"'\n]+/)))),

    identifier: _ => /[A-Za-z_][A-Za-z_0-9]*/,
  },
});
