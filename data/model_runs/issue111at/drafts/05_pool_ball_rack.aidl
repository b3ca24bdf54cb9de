# Request (sport): a triangle rack for fifteen 57.2 mm (2 1/4 in) pool balls, built up from five
# glued layers of 6 mm birch ply (30 mm tall). Each layer is a triangular frame: the opening an
# equilateral triangle of side 329.6 mm (4 ball diameters + sqrt(3) diameters, for 57.5 mm:
# 0.3 mm play), point up; the frame 25 mm wide all round, its outer corners rounded (the opening
# grown by 25 mm with round joins). The top layer has "CLUB 147" engraved as filled bold
# letters 12 mm tall centred in the bottom bar. Layers laid out in a row, 20 mm apart.

thickness 6 mm

param ball = 57.5 mm, min = 57 mm, max = 58 mm   # ball diameter with its play
param frame = 25 mm, min = 18 mm, max = 35 mm

side = 4 * ball + sqrt(3) * ball
tri_h = side * sqrt(3) / 2

def layer(top=false) -> solid {
    guide = Triangle(center=(0, 0), base=side, height=tri_h, construction=true)
    outer = Offset(guide, frame)
    hole opening {
        t2 = Triangle(center=(0, 0), base=side, height=tri_h)
    }
    if top {
        drawing name {
            t = Text("CLUB 147", position=(0, -tri_h / 2 - frame / 2), size=12, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
}

assembly rack {
    for i in range(4) {
        plain = layer()
    }
    top = layer(top=true)
    for i in range(1, 4) {
        RightOf(plain[i], plain[i - 1], gap=20)
        AlignBottom(plain[i], plain[0])
    }
    RightOf(top, plain[3], gap=20)
    AlignBottom(top, plain[0])

    assert len(plain) + 1 == 5, "five layers"
    assert abs(top.opening.t2.base - 329.6 mm) < 0.05 mm, "opening side 329.6"
    assert abs(top.outer.bb.width - top.opening.bb.width - 2 * 25 mm) < 0.01 mm, "frame 25 wide at the sides"
    assert top.name.t.size == 12 mm, "letters 12 tall"
    assert abs(top.name.t.position.y - (top.opening.bb.bottom - 12.5 mm)) < 0.01 mm, "text centred in the 25 mm bottom bar"
}
