# Request: an emergency-stop legend plate for a 22 mm mushroom button on my CNC router's
# control box, 3 mm yellow acrylic. A disc 80 mm across with the standard 22.3 mm mounting
# hole and its anti-rotation keyway at the top: 3.2 mm wide, reaching 24.1 mm across the
# hole (1.8 mm past its edge). "EMERGENCY" over the top and "STOP" under the bottom, bold
# letters 7 mm tall, engraved filled (black paint fill), their middles on a circle of
# radius 30, both reading left to right. An engraved border ring 2.5 mm inside the rim.

thickness 3 mm

solid legend_plate {
    disc = Circle(center=(0, 0), diameter=80)
    hole mount {
        bore = Circle(center=(0, 0), diameter=22.3)
        # from the centre up to 24.1 mm above the hole's far (bottom) edge
        key = Rectangle(bottom_left=(-1.6, 0), width=3.2, height=24.1 - 22.3 / 2)
    }
    drawing legend {
        ring = Circle(center=(0, 0), radius=30, construction=true)
        top = Text("EMERGENCY", along=ring, size=7, valign="middle", font="sans:Bold",
                   fill=true)
        bottom = Text("STOP", along=ring, size=7, valign="middle", font="sans:Bold",
                      fill=true, flip=true)
        border = Circle(center=(0, 0), radius=40 - 2.5)
    }

    # the request's numbers
    assert disc.diameter == 80 mm, "disc 80 across"
    assert mount.bore.diameter == 22.3 mm, "22.3 mm hole"
    assert mount.key.bb.width == 3.2 mm, "keyway 3.2 wide"
    assert mount.key.bb.top - mount.bore.bb.bottom == 24.1 mm, "keyway 24.1 across the hole"
    assert disc.radius - legend.border.radius == 2.5 mm, "border 2.5 inside the rim"
}
