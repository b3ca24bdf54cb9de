# Request (parties): a tap handle for the keg at our garden party, glued up from three
# layers: 6 mm birch ply front and back, a 15 mm birch ply core. Outline 230 mm tall: a
# shaft 30 mm wide at the bottom widening to 40 mm at 140 mm up, under a shield 80 x 90 mm
# (top corners rounded 25 mm, bottom corners 10 mm). The core holds a 3/8"-16 hex nut
# (16.5 mm across corners, 8.3 mm thick, flats to the faces) in a 16.8 x 8.6 mm window
# centred 20 mm up, reached by a 9.8 mm channel from the bottom edge for the tap's stud.
# Front, engraved filled (sans bold): "HAZY" and "DAYS" on the shield (15 mm, at most
# 66 mm wide) inside an engraved border line 5 mm in from the shield's edge, and
# "IPA 6.2%" (11 mm) reading up the shaft. Back: "BREWED BY" (9 mm) and "SAM" (20 mm).

units mm
thickness 6 mm

FACE_T = 6 mm
CORE_T = 15 mm

def tap_layer(th=6 mm) -> solid {
    thickness th
    shaft = Trapezoid(center=(0, 70), bottom_width=30, top_width=40, height=140)
    shield = RoundedRectangle(center=(0, 185), width=80, height=90,
                              corner_radii=[25, 25, 10, 10])
}

assembly tap_handle {
    front = tap_layer(th=FACE_T)
    core = tap_layer(th=CORE_T)
    back = tap_layer(th=FACE_T)

    hole nut {
        window = Rectangle(center=(0, 20), width=16.8, height=8.6)
        channel = Rectangle(bottom_left=(-4.9, -1), width=9.8, height=21)
    }
    CutInto(nut, core)
    AlignCenterX(nut, core)
    nut.window.center.y == core.shaft.bb.bottom + 20 mm
    nut.channel.bb.bottom == core.shaft.bb.bottom - 1 mm

    drawing brew {
        border = RoundedRectangle(center=(0, 185), width=70, height=80,
                                  corner_radii=[20, 20, 5, 5])
        l1 = Text("HAZY", position=(0, 197), size=15, font="sans:Bold", valign="middle",
                  max_width=66, fill=true)
        l2 = Text("DAYS", position=(0, 173), size=15, font="sans:Bold", valign="middle",
                  max_width=66, fill=true)
        style = Text("IPA 6.2%", position=(0, 70), size=11, rotation=90, font="sans:Bold",
                     valign="middle", fill=true)
    }
    CutInto(brew, front)
    AlignCenterX(brew.border, front.shield)
    brew.border.center.y == front.shield.center.y

    drawing maker {
        l1 = Text("BREWED BY", position=(0, 200), size=9, font="sans:Bold", valign="middle",
                  fill=true)
        l2 = Text("SAM", position=(0, 175), size=20, font="sans:Bold", valign="middle",
                  fill=true)
    }
    CutInto(maker, back)
    AlignCenterX(maker, back.shield)
    maker.l1.position.y == back.shield.center.y + 15 mm

    # flat: three layers side by side
    RightOf(core, front, gap=10)
    RightOf(back, core, gap=10)
    AlignBottom(core, front)
    AlignBottom(back, front)

    # glued up: front (y -13.5..-7.5), core (-7.5..7.5), back (7.5..13.5)
    Place(front, position=(0, -CORE_T / 2, 0), face="front", up="up")
    Place(core, position=(0, CORE_T / 2, 0), face="front", up="up")
    Place(back, position=(0, CORE_T / 2, 0), face="back", up="up")

    assert front.shield.bb.top - front.shaft.bb.bottom == 230 mm, "230 tall"
    assert front.shaft.bottom_width == 30 mm and front.shaft.top_width == 40 mm, "shaft"
    assert front.shaft.bb.height == 140 mm, "shaft 140"
    assert front.shield.bb.width == 80 mm and front.shield.bb.height == 90 mm, "shield"
    assert nut.window.center.y - core.shaft.bb.bottom == 20 mm, "nut 20 up"
    assert nut.window.width >= 16.5 mm and nut.window.height >= 8.3 mm, "nut fits"
    assert CORE_T >= 14.3 mm, "nut flats fit in the core"
    assert nut.window.width < 16.5 mm + 1 mm, "nut cannot turn"
    assert brew.l1.bb.width <= 66 mm and brew.l2.bb.width <= 66 mm, "words fit"
    assert front.shield.bb.right - brew.border.bb.right == 5 mm, "border 5 in"
    assert brew.style.bb.top <= front.shaft.bb.top, "style on the shaft"
    assert distance(brew.l2, brew.border) >= 2 mm, "words inside the border"
    # the back has no border: its words need only stay 4 mm inside the 80 mm shield
    assert maker.bb.width <= 80 mm - 2 * 4 mm, "maker fits"
}
