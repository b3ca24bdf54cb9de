assembly gift {
    solid a {
        ring = Circle(center=(0, 0), diameter=70)
    }
    solid tag {
        card = Rectangle(center=(0, 0), width=60, height=30)
    }
    RightOf(tag, a, gap=10)
    assert tag.card.bb.right >= 1000 mm, "x"
}
