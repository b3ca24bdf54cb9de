; Scopes, definitions and references of AIDL (CAD), in nvim-treesitter's names
; (@local.scope, @local.definition.KIND, @local.reference): what an editor uses to colour a
; name by its definition, to find a definition in the file and to highlight a name's uses.
; (Helix's names differ: editors/helix/queries/aidl-cad/locals.scm.)
;
; Scopes (docs/language.md, "Names"): the file; a template's body and its parameters; a
; structure's block (its children are its own names); a `for` loop (its variable is seen in
; its body only); a list comprehension.

(source_file) @local.scope

(function_definition) @local.scope

(template_definition) @local.scope

(value_definition) @local.scope

(block) @local.scope

(for_statement) @local.scope

(list_comprehension) @local.scope

; Definitions

; `param w = 40 mm`: a design parameter, read-only in the program (`--set` changes it)
(param_declaration
  name: (identifier) @local.definition.constant)

; `def bolt(d) -> hole { ... }` and `solid bolt(d) { ... }`: templates
(function_definition
  name: (identifier) @local.definition.function)

(template_definition
  name: (identifier) @local.definition.function)

; `def angle_of(v) = 225 deg - v * 27 deg`: a function
(value_definition
  name: (identifier) @local.definition.function)

; a template's parameters
(parameter
  name: (identifier) @local.definition.parameter)

; `solid plate { ... }`: a structure, a named part of the design
(structure_declaration
  name: (identifier) @local.definition.type)

; `c = Circle(...)`, `hole h = bolt(...)`
(assignment
  name: (identifier) @local.definition.var)

(kind_assignment
  name: (identifier) @local.definition.var)

; loop variables
(for_statement
  variable: (identifier) @local.definition.var)

(list_comprehension
  variable: (identifier) @local.definition.var)

(comprehension_for
  variable: (identifier) @local.definition.var)

; `import "std/shapes.aidl" as shapes`, `import std.gears as g`
(import_declaration
  alias: (identifier) @local.definition.namespace)

; References: any other name (a member after a dot and a keyword argument's name are not
; uses of a local name)
(identifier) @local.reference
