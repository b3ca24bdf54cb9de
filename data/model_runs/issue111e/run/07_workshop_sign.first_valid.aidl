# Door sign for the workshop, 3 mm plywood: the word "WORKSHOP" cut out as the part, in sans
# Bold letters 30 mm tall (cap height), standing on a 6 mm tall rail exactly as wide as the
# word, the rail's top 2 mm above the letters' baseline so every letter fuses into it. At each
# end of the rail a 16 mm round screw ear centered on the rail's end, with a 4 mm screw hole
# countersunk 8 mm.
units mm
thickness 3 mm

solid sign {
    word = Text("WORKSHOP", position=(0, 0), size=30, font="sans:Bold")
    rail = Rectangle(center=(word.center.x, -1), width=word.bb.width, height=6)
    left_ear = Circle(center=rail.left.midpoint, diameter=16)
    right_ear = Circle(center=rail.right.midpoint, diameter=16)
    hole mount {
        l = Circle(center=(0, 0), diameter=4)
        r = Circle(center=(100, 0), diameter=4)
    }
    Concentric(mount.l, left_ear)
    Concentric(mount.r, right_ear)
    Countersink(mount, diameter=8)

    assert word.size == 30 mm, "letters 30 mm tall"
    assert rail.height == 6 mm, "rail 6 mm tall"
    assert rail.width == word.bb.width, "rail as wide as the word"
    assert rail.bb.top - word.position.y == 2 mm, "rail top 2 mm above the baseline"
    assert left_ear.diameter == 16 mm and right_ear.diameter == 16 mm, "16 mm ears"
    assert mount.l.center.x == rail.bb.left and mount.r.center.x == rail.bb.right, "ears on the rail's ends"
    assert mount.l.diameter == 4 mm, "4 mm screw holes"
}
