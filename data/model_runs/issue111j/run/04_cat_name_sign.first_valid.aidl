# Pets: a name sign for a cat's bed, 6 mm acrylic. The name "MILO" in sans Bold letters 40 mm
# high (cap height) as the material, standing on a rail 14 mm high that overlaps the letters'
# bottom by 3 mm and runs from 20 mm left of the word to 60 mm right of it. A paw-print badge:
# a 36 mm disc centred 28 mm right of the word and level with the letters' middle, with a paw
# print cut through (a 14 x 11 mm pad and four 5.2 x 6.6 mm toes). Two 3.5 mm screw holes in the
# rail, 8 mm from each end, on its middle line, countersunk 8 mm.
units mm
thickness 6 mm

solid sign {
    word = Text("MILO", (0, 0), size=40, font="sans:Bold")
    rail = Rectangle(center=(0, 0), width=word.bb.width + 80, height=14)
    rail.bb.top == word.bb.bottom + 3 mm
    rail.bb.left == word.bb.left - 20 mm

    solid paw {
        disc = Circle(center=(0, 0), diameter=36)
        hole print {
            pad = Ellipse(center=(0, -6), rx=7, ry=5.5)
            toe_a = Ellipse(center=(-9, 3), rx=2.6, ry=3.3)
            toe_b = Ellipse(center=(-3.5, 9), rx=2.6, ry=3.3)
            toe_c = Ellipse(center=(3.5, 9), rx=2.6, ry=3.3)
            toe_d = Ellipse(center=(9, 3), rx=2.6, ry=3.3)
        }
    }
    paw.disc.center.x == word.bb.right + 28 mm
    paw.disc.center.y == word.bb.center_y

    hole screws {
        for k in range(2) {
            c = Circle(center=(0, 0), diameter=3.5)
        }
    }
    At(screws.c[0].center, rail.left.midpoint, dx=8)
    At(screws.c[1].center, rail.right.midpoint, dx=-8)
    Countersink(screws, diameter=8)

    assert word.size == 40 mm, "letters 40 mm"
    assert rail.bb.height == 14 mm, "rail 14 high"
    assert word.bb.bottom - rail.bb.bottom == 14 mm - 3 mm, "rail overlaps the letters by 3 mm"
    assert word.bb.left - rail.bb.left == 20 mm, "rail 20 left of the word"
    assert rail.bb.right - word.bb.right == 60 mm, "rail 60 right of the word"
    assert paw.disc.diameter == 36 mm, "36 mm badge"
    assert paw.disc.center.x - word.bb.right == 28 mm, "badge 28 right of the word"
    assert paw.print.pad.rx == 7 mm and paw.print.pad.ry == 5.5 mm, "pad 14 x 11"
    assert paw.print.toe_a.rx == 2.6 mm and paw.print.toe_a.ry == 3.3 mm, "toes 5.2 x 6.6"
    assert screws.c[0].diameter == 3.5 mm, "3.5 mm screws"
    assert screws.c[0].center.x - rail.bb.left == 8 mm and rail.bb.right - screws.c[1].center.x == 8 mm, "8 from each end"
    assert screws.c[0].center.y == rail.center.y, "on the rail's middle line"
    assert paw.disc.bb.right <= rail.bb.right, "badge within the rail's length"
}
