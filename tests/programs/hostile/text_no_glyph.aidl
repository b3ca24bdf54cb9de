# expect: E0134 4:26
solid s {
    c = Circle((0, 0), 20)
    drawing d { t = Text("漢字", (0, 0)) }
}
