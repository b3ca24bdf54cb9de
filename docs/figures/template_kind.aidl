# Figure of docs/language.md: one template as a solid, a hole and an engraving.
# Drawn by `python docs/make_pictures.py` to docs/images/template_kind.png.
# render: --png-width 333

def leaf(size = 10) -> solid {
    blade = Polygon([(0, 0), (size, size / 2), (0, size), (-size, size / 2)])
}

solid plate {
    body = Rectangle(center=(0, 0), width=80, height=40)
    boss = leaf(size=12)             # solid, as the template says
    hole cut = leaf(size=8)          # the same outline, cut out
    drawing mark = leaf(size=5)      # engraved
    Above(boss, body, gap=-6)
    CenterInside(cut, body)
    RightOf(mark, cut, gap=8)
    AlignCenterY(mark, cut)
}
