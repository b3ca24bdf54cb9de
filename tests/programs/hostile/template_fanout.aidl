# expect: E0304 9:20
def t(n = 14) -> assembly {
    if n > 0 {
        a = t(n - 1)
        b = t(n - 1)
        c = t(n - 1)
    }
}
assembly top { x = t() }
