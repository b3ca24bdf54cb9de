# expect: W0105 4:26
solid s {
    c = Circle((0, 0), 20)
    drawing d { t = Text("Aé漢字", (0, 0)) }
}
