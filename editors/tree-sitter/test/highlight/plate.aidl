# Highlight assertions (tree-sitter test): `^` marks a column of the code line above, `<-`
# the column where the comment starts; the names are the captures of highlights.scm.
# Written by hand: the colours the TextMate grammar gives these names.
units mm
# <- keyword
#     ^ keyword
param w = 40 mm, min=10
# <- keyword
#     ^ constant
#         ^ number
#                ^ variable.parameter
solid plate {
# <- keyword.type
#     ^ type.definition
    body = Rectangle(center=(0, 0), width=w, height=pi)
    #      ^ type.builtin
    #                ^ variable.parameter
    #                                               ^ constant.builtin
    Coincident(body.center, self.center)
    # <- function.builtin
    #               ^ property
    #                       ^ variable.builtin
    n = floor(w / 3) + helper(2)
    #   ^ function.builtin
    #                  ^ function.call
    #           ^ operator
    s = "a # b \" c"
    #   ^ string
    #          ^ string.escape
    for i in range(3) { c = Circle(center=(i, 0), radius=1 mm) }
    # <- keyword.repeat
    #     ^ keyword.repeat
    #                       ^ type.builtin
    #                                                      ^ keyword
    hole h = tab(2)  // a tab
    # <- keyword.type
    #        ^ function.call
    #                ^ comment
    k = n // 2
    #     ^ operator
    if n > 2 { t = 1 } else { t = 2 }
    # <- keyword.conditional
    #                  ^ keyword.conditional
}
def tab(d=3) -> hole { c = Circle(center=(0, 0), radius=d) }
# <- keyword.function
#   ^ function
#       ^ variable.parameter
#               ^ keyword.type
