# expect: E0304 3:5
solid s {
    for i in range(10000) {
        for j in range(10000) { x = 1 }
    }
}
