# Parties: a balloon weight for a 30th birthday, 6 mm MDF (three glued for weight): a
# five-point star 90 mm across its tips circle (outer radius 45 mm, inner radius 21 mm),
# tips rounded R4, one tip up; a 6 mm ribbon hole on the up tip, its centre 18 mm below the
# star's sharp top point; "30" in bold sans 20 mm tall engraved filled, its capitals'
# middle 2 mm below the star's centre.

thickness 6 mm

param outer = 45 mm, min = 30 mm, max = 70 mm
param inner = 21 mm, min = 12 mm, max = 35 mm
param age = "30"

solid weight {
    star = Star(center=(0, 0), points=5, outer_radius=outer, inner_radius=inner, tip_radius=4 mm)
    Fixed(star)

    hole ribbon {
        c = Circle(center=(0, outer - 18 mm), diameter=6 mm)
    }

    drawing number {
        t = Text(age, position=(0, -2 mm), size=20 mm, font="sans:Bold", valign="middle",
                 fill=true)
    }

    assert star.outer_radius * 2 == 90 mm, "90 mm across the tips circle"
    assert star.inner_radius == 21 mm, "inner radius 21"
    assert star.tip_radius == 4 mm, "R4 tips"
    assert ribbon.c.diameter == 6 mm, "6 mm ribbon hole"
    assert star.center.y + 45 mm - ribbon.c.center.y == 18 mm, "hole 18 mm below the top point"
    assert number.t.size == 20 mm, "20 mm numerals"
    assert star.center.y - number.t.position.y == 2 mm, "2 mm below the centre"
}
