# Request (signs): a set of three ski-run difficulty markers for our club's dry slope, cut
# from 3 mm white acrylic and screwed over coloured backing boards, so each symbol is cut
# right through and the colour shows.
# - Each marker 150 x 200 mm, corners rounded 10 mm, with a 6 mm hole 15 mm from the top
#   edge and another 15 mm from the bottom edge, on the centre line.
# - The symbol cut through, centred 20 mm above the marker's middle: EASY a circle 80 mm
#   across, INTERMEDIATE a square 70 mm a side, EXPERT a square 60 mm a side turned 45
#   degrees (a diamond).
# - The level's name engraved filled in 16 mm bold letters, centred 50 mm below the middle,
#   never wider than 130 mm.

def marker(label="EASY", kind=0) -> solid {
    body = RoundedRectangle(center=(0, 0), width=150, height=200, corner_radius=10)
    hole fix {
        top = Circle(center=(0, 100 - 15), diameter=6)
        bottom = Circle(center=(0, -100 + 15), diameter=6)
    }
    hole symbol {
        if kind == 0 {
            s = Circle(center=(0, 20), diameter=80)
        } elif kind == 1 {
            s = Rectangle(center=(0, 20), width=70, height=70)
        } else {
            s = Rectangle(center=(0, 20), width=60, height=60, rotation=45 deg)
        }
    }
    drawing name {
        t = Text(label, position=(0, -50), size=16, font="sans:Bold", valign="middle",
                 fill=true, max_width=130)
    }
    assert name.bb.width <= 130 mm
    assert distance(name, symbol) >= 8 mm and distance(name, fix) >= 8 mm
    assert distance(symbol, fix) >= 8 mm
    assert body.bb.top - fix.top.center.y == 15 mm and fix.bottom.center.y - body.bb.bottom == 15 mm
    assert symbol.s.center.y - body.center.y == 20 mm
    assert name.t.position.y - body.center.y == -50 mm
}

assembly piste_markers {
    easy = marker(label="EASY", kind=0)
    intermediate = marker(label="INTERMEDIATE", kind=1)
    expert = marker(label="EXPERT", kind=2)

    RightOf(intermediate, easy, gap=10)
    AlignBottom(intermediate, easy)
    RightOf(expert, intermediate, gap=10)
    AlignBottom(expert, intermediate)

    assert easy.body.bb.width == 150 mm and easy.body.bb.height == 200 mm
    assert easy.symbol.s.diameter == 80 mm
    assert intermediate.symbol.s.width == 70 mm and intermediate.symbol.s.height == 70 mm
    assert expert.symbol.s.width == 60 mm
    assert abs(expert.symbol.s.bb.width - 60 mm * sqrt(2)) < 0.01 mm, "turned 45 degrees"
}
