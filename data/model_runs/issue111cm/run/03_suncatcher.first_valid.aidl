# Request: a garden suncatcher to hang from a tree branch, cut from 3 mm orange acrylic.
# A sun 150 mm across with 12 pointed rays (rounded 1.5 mm at the tips), the rays starting
# 52 mm from the centre. Windows let the light through: a round 16 mm window in the middle
# and 8 petal-shaped windows (24 x 12 mm ellipses) around it on a 25 mm radius. "HERE COMES
# THE SUN" engraved round the top on a 40 mm radius, 4 mm letters. A 5 mm hanging hole in the
# top ray, 58 mm from the centre, and a 3 mm hole in the bottom ray for a glass prism.

thickness 3 mm

solid suncatcher {
    sun = Star(center=(0, 0), points=12, outer_radius=75 mm, inner_radius=52 mm,
               tip_radius=1.5 mm)

    hole middle { c = Circle(center=(0, 0), diameter=16 mm) }

    hole petal { e = Ellipse(center=(25 mm, 0), rx=12 mm, ry=6 mm) }
    petals = CircularPattern(petal, 8, (0, 0))

    hole hang { c = Circle(center=(0, 58 mm), diameter=5 mm) }
    hole prism { c = Circle(center=(0, -58 mm), diameter=3 mm) }

    drawing motto {
        track = Circle(center=(0, 0), radius=40 mm, construction=true)
        words = Text("HERE COMES THE SUN", along=track, size=4 mm)
    }

    assert sun.outer_radius * 2 == 150 mm, "150 mm across"
    assert sun.bb.height <= 150 mm, "rounded tips stay within 150 mm"
    assert len(petals) == 8, "eight petal windows"
    assert petal.e.rx * 2 == 24 mm and petal.e.ry * 2 == 12 mm, "24 x 12 mm petals"
    assert hang.c.center.y - sun.center.y == 58 mm, "hanging hole 58 mm up"
}
