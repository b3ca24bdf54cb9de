//! The AIDL (CAD) extension's language server: `aidl lsp --stdio`, found as the Neovim plugin
//! and the VS Code extension find it: the path in Zed's settings
//! (`"lsp": {"aidl-lsp": {"binary": {"path": "...", "arguments": [...]}}}`), else the
//! project's `.venv/bin/aidl` or `venv/bin/aidl`, else `aidl` on the project's PATH.
use zed_extension_api::{self as zed, settings::LspSettings, LanguageServerId, Result};

struct AidlCad;

impl zed::Extension for AidlCad {
    fn new() -> Self {
        AidlCad
    }

    fn language_server_command(
        &mut self,
        language_server_id: &LanguageServerId,
        worktree: &zed::Worktree,
    ) -> Result<zed::Command> {
        let binary = LspSettings::for_worktree(language_server_id.as_ref(), worktree)
            .ok()
            .and_then(|settings| settings.binary);
        let args = binary
            .as_ref()
            .and_then(|b| b.arguments.clone())
            .unwrap_or_else(|| vec!["lsp".to_string(), "--stdio".to_string()]);
        let env = worktree.shell_env();
        if let Some(path) = binary.and_then(|b| b.path) {
            return Ok(zed::Command { command: path, args, env });
        }
        // the console script of a virtual environment in the project is a text file: reading
        // it is how an extension (no file system of its own) sees that it is there
        for venv in [".venv", "venv"] {
            let script = format!("{venv}/bin/aidl");
            if worktree.read_text_file(&script).is_ok() {
                let command = format!("{}/{script}", worktree.root_path());
                return Ok(zed::Command { command, args, env });
            }
        }
        let command = worktree.which("aidl").ok_or_else(|| {
            "aidl-cad: no `aidl` found: install it into the project's .venv \
             (python3 -m venv .venv && .venv/bin/pip install aidl-lang), or set \
             lsp.aidl-lsp.binary.path in Zed's settings"
                .to_string()
        })?;
        Ok(zed::Command { command, args, env })
    }
}

zed::register_extension!(AidlCad);
