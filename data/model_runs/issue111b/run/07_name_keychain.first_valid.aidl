# Name keychain, 3 mm acrylic: the word "MAX" as solid letters (sans Bold, 20 mm cap height)
# standing on a rail 3 mm tall that runs the word's full width and overlaps the letters'
# baseline by 1 mm; at the left a 12 mm disc whose center is 4 mm left of the word's left
# edge and 10 mm above the baseline, with a 5 mm key-ring hole concentric with it.

units mm
thickness 3 mm

param cap = 20 mm, min = 12 mm, max = 40 mm

solid keychain {
    word = Text("MAX", position=(0, 0), size=cap, font="sans:Bold")
    rail = Rectangle(center=(word.center.x, -0.5 mm), width=word.bb.width, height=3)
    loop = Circle(center=(word.bb.left - 4 mm, 10), diameter=12)

    hole ring {
        c = Circle(center=(-4, 10), diameter=5)
    }
    Concentric(ring.c, loop)

    assert abs(word.size - 20 mm) < 0.001 mm, "20 mm letters"
    assert abs(rail.bb.width - word.bb.width) < 0.001 mm, "rail the word's width"
    assert abs(rail.bb.top - word.position.y - 1 mm) < 0.001 mm, "rail overlaps the baseline by 1 mm"
    assert abs(rail.bb.height - 3 mm) < 0.001 mm, "rail 3 mm tall"
    assert abs(word.bb.left - loop.center.x - 4 mm) < 0.001 mm, "loop 4 mm left of the word"
    assert abs(loop.center.y - word.position.y - 10 mm) < 0.001 mm, "loop 10 mm above the baseline"
    assert loop.diameter == 12 mm and ring.c.diameter == 5 mm, "12 mm disc, 5 mm hole"
}
