-- Tree-sitter for AIDL (CAD) in Neovim, without nvim-treesitter: the parser `aidl_cad`
-- (editors/tree-sitter, built as `parser/aidl_cad.so` somewhere on 'runtimepath', e.g. by
-- nvim-treesitter's `:TSInstall aidl_cad` or by hand, docs/editors.md) and the queries this
-- plugin ships in queries/aidl_cad/ (highlights, folds, indents, locals, textobjects,
-- injections).
--
-- ftplugin/aidl-cad.vim calls `start(0)` for every `aidl-cad` buffer: when the parser is
-- found, tree-sitter highlighting replaces the regex syntax file (`let g:aidl_treesitter = 0`
-- keeps the syntax file), and with `let g:aidl_treesitter_folds = 1` the window folds by
-- folds.scm ('foldmethod' expr, 'foldexpr' `foldexpr()` below). Without the parser nothing
-- changes (the syntax file colours the buffer).
--
-- Works on Neovim 0.7 (vim.treesitter.get_parser + vim.treesitter.highlighter.new, its parser
-- ABI 13-14) and on 0.10+ (vim.treesitter.language.register / add, vim.treesitter.start,
-- vim.treesitter.foldexpr; parser ABI 13-15).
local M = {}

M.lang = 'aidl_cad'          -- the grammar's and the parser's name (symbol tree_sitter_aidl_cad)
M.filetype = 'aidl-cad'      -- the filetype it serves

local ts = vim.treesitter

--- Map the filetype `aidl-cad` to the parser `aidl_cad` (Neovim 0.9+; earlier versions take
--- the language name in each call).
function M.register()
  if ts.language and ts.language.register then
    ts.language.register(M.lang, M.filetype)
  end
end

--- Whether the parser `aidl_cad` can be loaded (found on 'runtimepath' as parser/aidl_cad.so
--- or already loaded). Never raises.
function M.available()
  if ts.language and ts.language.add then                  -- 0.9+
    -- 0.10 raises on a missing parser and returns nothing on success; 0.11 returns true,
    -- or nil and the reason. The grammar is named aidl_cad: its symbol is the default one.
    local ok, res, err = pcall(ts.language.add, M.lang)
    return ok and (res ~= nil or err == nil)
  end
  local require_language = ts.require_language or (ts.language and ts.language.require_language)
  if not require_language then
    return false
  end
  local ok, res = pcall(require_language, M.lang, nil, true)
  return ok and res == true
end

--- The query `name` (highlights, folds, ...) of the parser, or nil.
function M.query(name)
  local get = (ts.query and ts.query.get) or ts.get_query or (ts.query and ts.query.get_query)
  local ok, q = pcall(get, M.lang, name)
  return ok and q or nil
end

--- The folder of this checkout of AIDL (this file is editors/nvim/lua/aidl_cad/treesitter.lua).
local function repo_root()
  local src = debug.getinfo(1, 'S').source:gsub('^@', '')
  return vim.fn.fnamemodify(src, ':p:h:h:h:h:h')
end

--- The parser entry for nvim-treesitter (its `master` branch): `:TSInstall aidl_cad` then
--- builds editors/tree-sitter of this checkout (no download). Added when nvim-treesitter is
--- loaded (plugin/aidl_cad.lua at start-up; call it again after a lazily loaded
--- nvim-treesitter). Returns the entry, or nil without nvim-treesitter.
function M.nvim_treesitter()
  local ok, parsers = pcall(require, 'nvim-treesitter.parsers')
  if not ok or type(parsers.get_parser_configs) ~= 'function' then
    return nil
  end
  local configs = parsers.get_parser_configs()
  configs[M.lang] = configs[M.lang] or {
    install_info = {
      url = repo_root(),
      location = 'editors/tree-sitter',
      files = { 'src/parser.c', 'src/scanner.c' },
      requires_generate_from_grammar = false,
    },
    filetype = M.filetype,
    maintainers = {},
  }
  return configs[M.lang]
end

--- Start tree-sitter highlighting for the buffer (0 or nil: the current one). Returns true
--- when the parser was found and the highlighter runs, false otherwise (nothing changed).
function M.start(bufnr)
  if bufnr == nil or bufnr == 0 then
    bufnr = vim.api.nvim_get_current_buf()
  end
  M.register()
  if not M.available() then
    return false
  end
  if ts.start then                                        -- 0.8+: also ends the regex syntax
    ts.start(bufnr, M.lang)
  else                                                    -- 0.7
    ts.highlighter.new(ts.get_parser(bufnr, M.lang))
    -- the syntax file is set by the FileType event after this ftplugin: ended just after
    vim.schedule(function()
      if vim.api.nvim_buf_is_valid(bufnr) and ts.highlighter.active[bufnr] then
        vim.api.nvim_buf_set_option(bufnr, 'syntax', '')
      end
    end)
  end
  if vim.g.aidl_treesitter_folds == 1 or vim.g.aidl_treesitter_folds == true then
    M.set_folds(bufnr)
  end
  return true
end

--- Fold the windows showing the buffer by folds.scm: 'foldmethod' expr and 'foldexpr'
--- (window-local; 'foldlevel' is left to the user).
function M.set_folds(bufnr)
  for _, win in ipairs(vim.fn.win_findbuf(bufnr)) do
    vim.api.nvim_win_set_option(win, 'foldmethod', 'expr')
    vim.api.nvim_win_set_option(win, 'foldexpr', "v:lua.require'aidl_cad.treesitter'.foldexpr()")
  end
end

-- Neovim 0.7 has no vim.treesitter.foldexpr: the levels are worked out here from folds.scm,
-- once per buffer change (b:changedtick).
local fold_cache = {}       -- bufnr -> { tick = n, levels = { [lnum] = '>2' | '2' ... } }

local function fold_levels(bufnr)
  local tick = vim.api.nvim_buf_get_changedtick(bufnr)
  local cached = fold_cache[bufnr]
  if cached and cached.tick == tick then
    return cached.levels
  end
  local levels = {}
  local query = M.query('folds')
  local ok, parser = pcall(ts.get_parser, bufnr, M.lang)
  if query and ok and parser then
    local tree = parser:parse()[1]
    local starts, stops = {}, {}      -- 1-based line -> folds starting / ending there
    local seen = {}
    for _, node in query:iter_captures(tree:root(), bufnr, 0, -1) do
      local srow, _, erow, ecol = node:range()
      if ecol == 0 then
        erow = erow - 1               -- a node that ends at a line's start ends on the line above
      end
      local key = srow .. ':' .. erow
      if erow > srow and not seen[key] then
        seen[key] = true
        starts[srow + 1] = (starts[srow + 1] or 0) + 1
        stops[erow + 1] = (stops[erow + 1] or 0) + 1
      end
    end
    local level = 0
    for lnum = 1, vim.api.nvim_buf_line_count(bufnr) do
      local opened = starts[lnum] or 0
      level = level + opened
      levels[lnum] = (opened > 0 and '>' or '') .. level
      level = level - (stops[lnum] or 0)
    end
  end
  fold_cache[bufnr] = { tick = tick, levels = levels }
  return levels
end

--- 'foldexpr' for a window showing an `aidl-cad` buffer: Neovim's own tree-sitter folding
--- (0.10+), else the levels of the regions folds.scm captures (Neovim 0.7-0.9).
function M.foldexpr(lnum)
  if ts.foldexpr then
    return ts.foldexpr(lnum)
  end
  lnum = lnum or vim.v.lnum
  return fold_levels(vim.api.nvim_get_current_buf())[lnum] or '0'
end

return M
