# Holidays: a Diwali rangoli stencil cut from 0.5 mm PET, a 220 x 220 mm sheet with
# 10 mm corner radius and a 6 mm hanging hole 8 mm from the top edge. Centred on it:
# a 16 mm round centre hole; 8 petals (ellipses 40 x 16 mm) pointing out from the
# centre, their centres on a 40 mm radius; 8 five-pointed stars (outer radius 6,
# inner 2.5 mm) between the petals on a 52 mm radius, a tip pointing outward;
# 16 dots of 6 mm on a 70 mm radius. "DIWALI" as stencil letters (sans Bold, 10 mm
# cap height) centred 90 mm below the centre.
thickness 0.5 mm

param petals = 8, min = 6, max = 10

solid stencil {
    sheet = RoundedRectangle(center=(0, 0), width=220, height=220, corner_radius=10)

    hole hang { c = Circle(center=(0, 102), diameter=6) }
    AlignCenterX(hang, sheet)
    hang.c.center.y == sheet.bb.top - 8 mm

    hole middle { c = Circle(center=(0, 0), diameter=16) }
    Concentric(middle.c, sheet)

    hole petal { e = Ellipse(center=(40, 0), rx=20, ry=8) }
    ring = CircularPattern(petal, petals, sheet.center)
    Coincident(petal.e.center, polar(sheet.center, 40, 0 deg))

    hole star {
        s = Star(center=(48, 20), points=5, outer_radius=6, inner_radius=2.5,
                 rotation=180 / petals - 90)
    }
    stars = CircularPattern(star, petals, sheet.center)
    Coincident(star.s.center, polar(sheet.center, 52, 180 deg / petals))

    hole dot { c = Circle(center=(70, 0), diameter=6) }
    dots = CircularPattern(dot, 2 * petals, sheet.center)
    Coincident(dot.c.center, polar(sheet.center, 70, 0 deg))

    hole word {
        t = Text("DIWALI", (0, -90), size=10, valign="middle", font="sans:Bold", stencil=true)
    }
    AlignCenterX(word, sheet)
    word.t.position.y == sheet.center.y - 90 mm

    assert sheet.width == 220 mm and sheet.height == 220 mm, "sheet 220 x 220"
    assert len(ring) == 8 and len(stars) == 8 and len(dots) == 16, "8 petals, 8 stars, 16 dots"
    assert petal.e.rx == 20 mm and petal.e.ry == 8 mm, "petals 40 x 16"
    assert distance(dot.c.center, sheet.center) == 70 mm, "dots on 70"
    assert distance(star.s.center, sheet.center) == 52 mm, "stars on 52"
    assert sheet.bb.top - hang.c.center.y == 8 mm, "hang hole 8 from top"
}
