/*
 * External scanner of tree-sitter-aidl-cad (Apache-2.0). It reads the four things of AIDL that
 * depend on more than the next few characters (grammar/aidl.lark and the post-lexer and
 * comment masking of aidl_lang/parser.py):
 *
 * - newlines where a statement may end (the grammar says where: NEWLINE is valid), one token
 *   for a run of blank lines; none before `else`/`elif` (the post-lexer drops those), so
 *   `}` NEWLINE `else {` continues the `if`, and none before a line that starts with an
 *   operator no statement starts with (`==`, `<`, `and`, `*`, ...: it goes on). The token
 *   is empty: the line breaks before it
 *   are its padding, so a comment between them keeps its place;
 * - comments: `# ...`, block comments (slash-star to star-slash), and `// ...` where `//` is not floor division;
 * - `//`: floor division when the parser is after an operand (FLOOR_DIV is valid) and not at
 *   the start of a statement line, unless the rest of the line reads as prose (two words side
 *   by side that are not keywords, or a character no expression uses) -- the rule of
 *   parser.mask_comments and _is_prose, which docs/language.md ("Comments") describes;
 * - the text of a string between its quotes and escapes, and of an f-string between them and
 *   its `{...}` interpolations (inside them a `#` or `//` is text, not a comment).
 */
#include "tree_sitter/parser.h"

#include <stdbool.h>
#include <stdint.h>
#include <string.h>

enum TokenType {
  NEWLINE,
  COMMENT,
  FLOOR_DIV,
  FSTRING_CONTENT_DOUBLE,
  FSTRING_CONTENT_SINGLE,
  STRING_CONTENT_DOUBLE,
  STRING_CONTENT_SINGLE,
  ERROR_SENTINEL,
};

#define REST_MAX 2048

void *tree_sitter_aidl_cad_external_scanner_create(void) { return NULL; }
void tree_sitter_aidl_cad_external_scanner_destroy(void *payload) { (void)payload; }
unsigned tree_sitter_aidl_cad_external_scanner_serialize(void *payload, char *buffer) {
  (void)payload;
  (void)buffer;
  return 0;
}
void tree_sitter_aidl_cad_external_scanner_deserialize(void *payload, const char *buffer,
                                                   unsigned length) {
  (void)payload;
  (void)buffer;
  (void)length;
}

static inline void advance(TSLexer *lexer) { lexer->advance(lexer, false); }
static inline void skip(TSLexer *lexer) { lexer->advance(lexer, true); }

/* Python's str.isspace() */
static bool is_space(int32_t c) {
  return c == ' ' || (c >= '\t' && c <= '\r') || (c >= 0x1c && c <= 0x1f) || c == 0x85 ||
         c == 0xa0 || c == 0x1680 || (c >= 0x2000 && c <= 0x200a) || c == 0x2028 ||
         c == 0x2029 || c == 0x202f || c == 0x205f || c == 0x3000;
}

/* Python's `\w` (str patterns): letters and digits of any script, and `_`. Outside ASCII an
 * approximation by blocks: Latin-1 letters and numbers, Latin Extended, Greek, Cyrillic,
 * Armenian, Hebrew, Arabic, kana, CJK and Hangul. */
static bool is_word(int32_t c) {
  if (c < 0x80) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           c == '_';
  }
  if (c == 0xaa || c == 0xb2 || c == 0xb3 || c == 0xb5 || c == 0xb9 || c == 0xba ||
      (c >= 0xbc && c <= 0xbe))
    return true;
  if (c >= 0xc0 && c <= 0x24f) return c != 0xd7 && c != 0xf7;
  if (c >= 0x370 && c <= 0x6ff) return c != 0x37e && c != 0x387;
  if (c >= 0x3040 && c <= 0x30ff) return true;
  if (c >= 0x4e00 && c <= 0x9fff) return true;
  if (c >= 0xac00 && c <= 0xd7af) return true;
  return false;
}

static bool is_name_start(int32_t c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

/* A character an expression may hold (`[\w\s.()\[\]{}+\-*\/%,<>=!:;"'°]`). */
static bool is_code_char(int32_t c) {
  if (is_word(c) || is_space(c) || c == 0xb0) return true;
  return c != 0 && strchr(".()[]{}+-*/%,<>=!:;\"'", (int)c) != NULL;
}

static const char *const PROSE_KEYWORDS[] = {"if", "else", "and", "or", "not", "for", "in"};

static bool is_keyword(const int32_t *w, int n) {
  for (unsigned k = 0; k < sizeof PROSE_KEYWORDS / sizeof *PROSE_KEYWORDS; k++) {
    const char *kw = PROSE_KEYWORDS[k];
    int len = (int)strlen(kw);
    if (len != n) continue;
    int i = 0;
    while (i < n && w[i] == (int32_t)kw[i]) i++;
    if (i == n) return true;
  }
  return false;
}

/* parser._is_prose on the rest of the line after `//` (rest[0..n)). */
static bool is_prose(const int32_t *rest, int n) {
  int32_t code[REST_MAX + 2]; /* a string left open at the end grows by one */
  int m = 0;
  /* strings become "" (an f/F just before a quote goes with them) */
  for (int i = 0; i < n; i++) {
    int32_t c = rest[i];
    if (c == '"' || c == '\'') {
      if (m > 0 && (code[m - 1] == 'f' || code[m - 1] == 'F')) m--;
      i++;
      while (i < n && rest[i] != c) {
        if (rest[i] == '\\') i++;
        i++;
      }
      code[m++] = '"';
      code[m++] = '"';
      continue;
    }
    code[m++] = c;
  }
  /* up to a `#`, then up to a `//` */
  for (int i = 0; i < m; i++) {
    if (code[i] == '#') {
      m = i;
      break;
    }
  }
  for (int i = 0; i + 1 < m; i++) {
    if (code[i] == '/' && code[i + 1] == '/') {
      m = i;
      break;
    }
  }
  bool blank = true;
  for (int i = 0; i < m; i++) {
    if (!is_space(code[i])) {
      blank = false;
      break;
    }
  }
  if (blank) return true;
  /* two words side by side, neither a keyword */
  for (int i = 0; i < m; i++) {
    if (!is_name_start(code[i])) continue;
    if (i > 0 && (is_word(code[i - 1]) || code[i - 1] == '.')) continue;
    int j = i + 1;
    while (j < m && is_word(code[j])) j++;
    int k = j;
    while (k < m && (code[k] == ' ' || code[k] == '\t')) k++;
    if (k == j || k >= m || !is_name_start(code[k])) continue;
    int e = k + 1;
    while (e < m && is_word(code[e])) e++;
    if (!is_keyword(code + i, j - i) && !is_keyword(code + k, e - k)) return true;
  }
  for (int i = 0; i < m; i++) {
    if (!is_code_char(code[i])) return true;
  }
  return false;
}

/* A line ends at CR LF, a lone CR or LF, as editors and the LSP count lines (LINE_BREAK in
 * aidl_lang/diagnostics.py): a `#` comment ends at a lone CR too. */
static bool is_line_break(int32_t c) { return c == '\n' || c == '\r'; }

static void to_line_end(TSLexer *lexer) {
  while (!lexer->eof(lexer) && !is_line_break(lexer->lookahead)) advance(lexer);
}

/* The text of a string up to its closing quote, a `\` escape or the end of the line; of an
 * f-string (`braces`) also up to a `{` that opens an interpolation (`{{` is text). */
static bool scan_string_content(TSLexer *lexer, int32_t quote, bool braces,
                                enum TokenType type) {
  bool any = false;
  for (;;) {
    int32_t c = lexer->lookahead;
    if (lexer->eof(lexer) || c == quote || is_line_break(c) || c == '\\') break;
    if (c == '{' && braces) {
      lexer->mark_end(lexer);
      advance(lexer);
      if (lexer->lookahead != '{') {
        if (!any) return false;
        lexer->result_symbol = type;
        return true;
      }
      advance(lexer);
      any = true;
      continue;
    }
    advance(lexer);
    any = true;
  }
  lexer->mark_end(lexer);
  if (!any) return false;
  lexer->result_symbol = type;
  return true;
}

static bool word_is(TSLexer *lexer, const char *word) {
  /* compares the lookahead with `word` followed by a non-word character (consumes it) */
  for (const char *p = word; *p; p++) {
    if (lexer->lookahead != (int32_t)*p) return false;
    advance(lexer);
  }
  return !is_word(lexer->lookahead);
}

/* Whether the lookahead is the word `else` or `elif` (consumes what it reads). */
static bool is_else(TSLexer *lexer) {
  if (lexer->lookahead != 'e') return false;
  advance(lexer);
  if (lexer->lookahead != 'l') return false;
  advance(lexer);
  if (lexer->lookahead == 's') {
    advance(lexer);
    return word_is(lexer, "e");
  }
  if (lexer->lookahead == 'i') {
    advance(lexer);
    return word_is(lexer, "f");
  }
  return false;
}

/* a line that starts with an operator no statement starts with goes on the line before it
 * (the post-lexer's LEADS, aidl_lang/parsing/lexing.py): `==`, `!=`, `<`, `>`, `*`, `%`,
 * `and`, `or` (not `/`: a comment may start so) */
static bool is_lead(TSLexer *lexer) {
  int32_t c = lexer->lookahead;
  if (c == '<' || c == '>' || c == '*' || c == '%') return true;
  if (c == '=' || c == '!') {
    advance(lexer);
    return lexer->lookahead == '=';
  }
  if (c == 'a') {
    advance(lexer);
    if (lexer->lookahead != 'n') return false;
    advance(lexer);
    return word_is(lexer, "d");
  }
  if (c == 'o') {
    advance(lexer);
    return word_is(lexer, "r");
  }
  return false;
}

bool tree_sitter_aidl_cad_external_scanner_scan(void *payload, TSLexer *lexer,
                                            const bool *valid_symbols) {
  (void)payload;
  bool recovering = valid_symbols[ERROR_SENTINEL];

  if (!recovering) {
    if (valid_symbols[FSTRING_CONTENT_DOUBLE])
      return scan_string_content(lexer, '"', true, FSTRING_CONTENT_DOUBLE);
    if (valid_symbols[FSTRING_CONTENT_SINGLE])
      return scan_string_content(lexer, '\'', true, FSTRING_CONTENT_SINGLE);
    if (valid_symbols[STRING_CONTENT_DOUBLE])
      return scan_string_content(lexer, '"', false, STRING_CONTENT_DOUBLE);
    if (valid_symbols[STRING_CONTENT_SINGLE])
      return scan_string_content(lexer, '\'', false, STRING_CONTENT_SINGLE);
  }

  bool crossed = false; /* a line break skipped before the next token */
  for (;;) {
    int32_t c = lexer->lookahead;
    if (is_line_break(c)) {
      crossed = true;
      skip(lexer);
    } else if (c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == 0xa0 ||
               c == 0xfeff) {
      skip(lexer);
    } else {
      break;
    }
  }

  bool newline = crossed && valid_symbols[NEWLINE];
  lexer->mark_end(lexer); /* an empty NEWLINE ends here */

  if (lexer->lookahead == '#') {
    to_line_end(lexer);
    lexer->mark_end(lexer);
    lexer->result_symbol = COMMENT;
    return true;
  }

  if (lexer->lookahead == '/') {
    advance(lexer);
    if (lexer->lookahead == '*') {
      advance(lexer);
      for (;;) {
        if (lexer->eof(lexer)) break;
        if (lexer->lookahead == '*') {
          advance(lexer);
          if (lexer->lookahead == '/') {
            advance(lexer);
            break;
          }
          continue;
        }
        advance(lexer);
      }
      if (newline) {
        /* a block comment first on a line after a statement: when code follows it on that
         * line, the statement before ended (the empty NEWLINE before the comment), unless
         * the code is `else`/`elif`, which continues an `if` */
        while (lexer->lookahead == ' ' || lexer->lookahead == '\t' || lexer->lookahead == '\f')
          advance(lexer);
        int32_t c = lexer->lookahead;
        if (!(lexer->eof(lexer) || is_line_break(c) || c == '#' || c == '/' || c == 'e')) {
          lexer->result_symbol = NEWLINE;
          return true;
        }
        lexer->mark_end(lexer);
        lexer->result_symbol = COMMENT;
        if (c == 'e' && !is_else(lexer)) {
          /* a block comment, then `elsewhere = 1`: the comment goes inside the NEWLINE */
          lexer->result_symbol = NEWLINE;
        }
        return true;
      }
      lexer->mark_end(lexer);
      lexer->result_symbol = COMMENT;
      return true;
    }
    if (lexer->lookahead == '/') {
      advance(lexer);
      lexer->mark_end(lexer);
      if (valid_symbols[FLOOR_DIV] && !newline) {
        int32_t rest[REST_MAX];
        int n = 0;
        while (!lexer->eof(lexer) && !is_line_break(lexer->lookahead)) {
          if (n < REST_MAX) rest[n++] = lexer->lookahead;
          advance(lexer);
        }
        if (!is_prose(rest, n)) {
          lexer->result_symbol = FLOOR_DIV;
          return true;
        }
      }
      to_line_end(lexer);
      lexer->mark_end(lexer);
      lexer->result_symbol = COMMENT;
      return true;
    }
    if (newline) {
      /* a line starting with `/`: the statement before it ended */
      lexer->result_symbol = NEWLINE;
      return true;
    }
    return false;
  }

  if (newline) {
    /* the (empty) token ends before the next line's first word */
    if (lexer->lookahead == 'e' ? is_else(lexer) : is_lead(lexer)) return false;
    lexer->result_symbol = NEWLINE;
    return true;
  }
  return false;
}
