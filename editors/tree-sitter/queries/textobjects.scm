; Text objects of AIDL (CAD). Each node carries both families of names, so one file serves
; nvim-treesitter-textobjects (@function.outer / @function.inner, ...) and Helix and Zed
; (@function.around / @function.inside, ...): each editor reads the names it knows.
;
;   function  a template: `def bolt(d) -> hole { ... }`, `solid bolt(d) { ... }`
;   class     a structure: `solid plate { ... }` (Helix `t`, "type")
;   parameter a template's parameter, a call's argument
;   block, loop, conditional, call, assignment, statement, comment, number

; templates
(function_definition
  body: (block) @function.inner @function.inside) @function.outer @function.around

(template_definition
  body: (block) @function.inner @function.inside) @function.outer @function.around

; structures
(structure_declaration
  body: (block) @class.inner @class.inside) @class.outer @class.around

; parameters and arguments
(parameters
  (parameter) @parameter.inner @parameter.outer @parameter.inside @parameter.around)

(argument_list
  (_) @parameter.inner @parameter.outer @parameter.inside @parameter.around)

; blocks, loops, branches
(block) @block.outer

(for_statement
  body: (block) @loop.inner) @loop.outer

(list_comprehension) @loop.outer

(if_statement
  consequence: (block) @conditional.inner) @conditional.outer

(elif_clause
  consequence: (block) @conditional.inner)

(else_clause
  body: (block) @conditional.inner)

(conditional_expression) @conditional.outer

; calls: a primitive, a constraint, a template instance
(call
  arguments: (argument_list) @call.inner) @call.outer

; assignments
(assignment
  name: (_) @assignment.lhs
  value: (_) @assignment.rhs @assignment.inner) @assignment.outer

(kind_assignment
  name: (_) @assignment.lhs
  value: (_) @assignment.rhs @assignment.inner) @assignment.outer

(param_declaration
  name: (_) @assignment.lhs
  value: (_) @assignment.rhs @assignment.inner) @assignment.outer

; statements
[
  (units_declaration)
  (import_declaration)
  (param_declaration)
  (thickness_declaration)
  (kerf_declaration)
  (min_wall_declaration)
  (assignment)
  (kind_assignment)
  (assert_statement)
  (expression_statement)
  (structure_declaration)
  (for_statement)
  (if_statement)
] @statement.outer

; comments
(comment) @comment.outer @comment.inner @comment.inside

(comment)+ @comment.around

(number) @number.inner
