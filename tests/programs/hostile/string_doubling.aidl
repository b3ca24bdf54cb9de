# expect: E0304 20:9
solid s {
    t = "abcdefgh"
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    t = t + t
    c = Circle((0, 0), 1)
}
