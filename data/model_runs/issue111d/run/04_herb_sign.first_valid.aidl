# Herb garden sign (garden): the word "HERBS" in Noto Sans Bold, 40 mm cap height, cut as the
# material itself (5 mm acrylic), the letters joined by a 6 mm rail under them as wide as the
# word, the rail's top 2 mm above the baseline (into the letters' feet); a 12 mm wide stake
# under the middle of the word reaching 160 mm below the rail's bottom edge, its last 25 mm
# tapered to a point.

thickness 5 mm

solid sign {
    word = Text("HERBS", position=(0, 0), size=40, font="sans:Bold")
    rail = Rectangle(center=(0, -1), width=word.bb.width, height=6)
    AlignCenterX(rail, word)
    rail.bb.top == word.position.y + 2 mm

    stake = Rectangle(center=(0, -70), width=12, height=135 + 6)
    AlignCenterX(stake, rail)
    stake.bb.top == rail.bb.top

    tip = Triangle(center=(0, -150), base=12, height=25, rotation=180)
    AlignCenterX(tip, stake)
    Below(tip, stake)

    assert word.size == 40 mm, "40 mm letters"
    assert rail.bb.height == 6 mm, "6 mm rail"
    assert rail.bb.width == word.bb.width, "rail as wide as the word"
    assert rail.bb.top - word.position.y == 2 mm, "rail 2 mm into the letters"
    assert stake.bb.width == 12 mm, "12 mm stake"
    assert rail.bb.bottom - tip.bb.bottom == 160 mm, "stake reaches 160 mm below the rail"
    assert tip.bb.height == 25 mm, "25 mm point"
    assert abs(stake.bb.center_x - word.bb.center_x) < 0.01 mm, "stake under the middle"
}
