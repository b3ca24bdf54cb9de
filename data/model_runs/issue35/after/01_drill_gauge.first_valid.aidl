# drill-bit gauge: 120 x 40 plate, ten holes 1..10 mm, labels below
solid gauge {
    body = Rectangle(center=(0, 0), width=120, height=40)
    Fixed(body)
    hole bits {
        for i in range(10) {
            c = Circle(center=(-54 + i * 12, 5), diameter=i + 1)
        }
    }
    drawing labels {
        for i in range(10) {
            t = Text(str(i + 1), (-54 + i * 12, -12), size=4)
        }
    }
}
