; Scopes, definitions and references of AIDL (CAD) in Helix's names: a definition's capture
; names the highlight its references get (@local.definition.variable.parameter: a template's
; parameter is coloured as a parameter wherever it is used in the template).
; (The same scopes as editors/tree-sitter/queries/locals.scm, nvim-treesitter's names.)

(source_file) @local.scope

(function_definition) @local.scope

(template_definition) @local.scope

(block) @local.scope

(for_statement) @local.scope

(list_comprehension) @local.scope

(parameter
  name: (identifier) @local.definition.variable.parameter)

(param_declaration
  name: (identifier) @local.definition.constant)

(for_statement
  variable: (identifier) @local.definition.variable)

(list_comprehension
  variable: (identifier) @local.definition.variable)

(comprehension_for
  variable: (identifier) @local.definition.variable)

(assignment
  name: (identifier) @local.definition.variable)

(kind_assignment
  name: (identifier) @local.definition.variable)

(import_declaration
  alias: (identifier) @local.definition.namespace)

(identifier) @local.reference
