; The outline of an AIDL (CAD) file in Zed (the outline panel, `cmd-shift-o`): params,
; templates, structures (nested as written) and named geometry.
(param_declaration
  "param" @context
  name: (identifier) @name) @item

(function_definition
  "def" @context
  name: (identifier) @name) @item

(template_definition
  kind: (identifier) @context
  name: (identifier) @name) @item

(structure_declaration
  kind: (identifier) @context
  name: (identifier) @name) @item

(kind_assignment
  kind: (identifier) @context
  name: (identifier) @name) @item
