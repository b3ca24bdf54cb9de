#!/usr/bin/env bash
# Installs code-server (VS Code 1.100.3 in the browser, the npm package `code-server@4.100.3`,
# built for Node 20) into DIR from the npm registry alone, and prints the path of its
# `code-server` program.  The package's own postinstall is not run: it installs VS Code's
# server dependencies with their native modules, one of which (@vscode/ripgrep) downloads
# from GitHub.  Instead:
#   - the package and its dependencies (its npm-shrinkwrap.json pins them), no scripts;
#   - argon2 (code-server's password hashing, which it loads at start even with
#     `--auth none`) built from its sources against this node's headers (no header download);
#   - VS Code's server modules (lib/vscode) and its built-in extensions, no scripts: the native
#     ones (@parcel/watcher, @vscode/spdlog, node-pty, kerberos, ...) stay unbuilt, which
#     costs the file watcher, the log files, the terminal and Quick Open's file search, none of
#     which tests/test_vscode_code_server.py uses (it opens files from the Explorer);
#   - the links postinstall.sh makes (node_modules.asar, the remote CLI, the browser helper).
# Needs node 20 with its headers (include/node beside bin/node), npm, g++, make and python3.
# A DIR that already holds a working install is reused.  Usage:
#   editors/vscode/test/install_code_server.sh DIR     # prints DIR/node_modules/.bin/code-server
set -euo pipefail
VERSION=4.100.3
dir=${1:?usage: install_code_server.sh DIR}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
export XDG_CONFIG_HOME="$dir/.config" XDG_DATA_HOME="$dir/.data"     # not the user's
bin="$dir/node_modules/.bin/code-server"
if [ -x "$bin" ] && "$bin" --version 2>/dev/null | grep -q "^$VERSION "; then
    echo "$bin"
    exit 0
fi
nodedir=$(node -p 'require("path").resolve(process.execPath, "..", "..")')
[ -f "$nodedir/include/node/node.h" ] || {
    echo "install_code_server.sh: no node headers in $nodedir/include/node" >&2; exit 1; }
export npm_config_nodedir="$nodedir" npm_config_audit=false npm_config_fund=false
cd "$dir"
[ -f package.json ] || echo '{"private": true}' > package.json
npm install --ignore-scripts --no-save "code-server@$VERSION" >&2
(cd node_modules/argon2 && ../.bin/node-pre-gyp rebuild --build-from-source >&2)
vs=node_modules/code-server/lib/vscode
(cd "$vs" && npm install --omit=dev --ignore-scripts >&2)
(cd "$vs/extensions" && npm install --omit=dev --ignore-scripts >&2)
ln -sfn node_modules "$vs/node_modules.asar"
ln -sfn code-linux.sh "$vs/bin/remote-cli/code-server"
ln -sfn browser-linux.sh "$vs/bin/helpers/browser.sh"
"$bin" --version | grep -q "^$VERSION " || {
    echo "install_code_server.sh: $bin does not run" >&2; exit 1; }
echo "$bin"
