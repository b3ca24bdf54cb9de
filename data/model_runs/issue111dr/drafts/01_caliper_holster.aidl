# Request (workshop): a wall holster for my 150 mm digital caliper, laminated from 6 mm
# birch ply, five layers glued up: a back, three spacers and a front. Every layer has the
# same outline: 120 mm wide at the top with R12 corners, tapering to a 60 mm round bottom
# (R30), 270 mm tall. The spacers (3 x 6 = 18 mm, my caliper is 17 mm thick at the display)
# have the caliper pocket cut through, open at the top: 86 mm wide x 75 mm deep for the
# head, then 26 mm wide for the beam, 245 mm deep in all, the step corners R3. The front has
# a window 70 mm wide x 55 mm deep open at the top (the jaws show, the lips keep it in)
# and a 12 mm slot down the beam so the scale shows, to 235 mm deep. The back has two
# countersunk holes for 4 mm wood screws (4.5 mm, 9 mm heads) inside the pocket, 30 mm and
# 200 mm below the top. Engrave "CALIPER" up the left of the front and "150 mm" up the right.

units mm
thickness 6 mm

param t = 6 mm, min = 3 mm, max = 9 mm

def layer(kind="spacer") -> solid {
    outline = Hull(RoundedRectangle(center=(0, -45), width=120, height=90, corner_radius=12),
                   Circle(center=(0, -240), radius=30))
    if kind == "spacer" {
        hole pocket {
            head = Rectangle(center=(0, -37.5), width=86, height=75)
            head_out = Rectangle(center=(0, 2), width=86, height=4, overrun=true)
            beam = Rectangle(center=(0, -157.5), width=26, height=175)
            Fillet([head.bottom, beam.left], 3)
            Fillet([head.bottom, beam.right], 3)
        }
    }
    if kind == "front" {
        hole window {
            head = Rectangle(center=(0, -27.5), width=70, height=55)
            head_out = Rectangle(center=(0, 2), width=70, height=4, overrun=true)
            scale_slot = Rectangle(center=(0, -142.5), width=12, height=185)
            Fillet([head.bottom, scale_slot.left], 3)
            Fillet([head.bottom, scale_slot.right], 3)
        }
        drawing label {
            left_word = Text("CALIPER", position=(-22, -160), size=9, rotation=90,
                             valign="middle", font="sans:Bold", fill=true)
            right_word = Text("150 mm", position=(22, -160), size=9, rotation=90,
                              valign="middle", font="sans:Bold", fill=true)
        }
    }
    if kind == "back" {
        hole screw_top { c = Circle(center=(0, -30), diameter=4.5) }
        hole screw_low { c = Circle(center=(0, -200), diameter=4.5) }
        Countersink([screw_top, screw_low], diameter=9)
    }
}

assembly holster {
    back = layer("back")
    spacer1 = layer("spacer")
    spacer2 = layer("spacer")
    spacer3 = layer("spacer")
    front = layer("front")

    # flat on the sheet, side by side
    RightOf(spacer1, back, gap=10)
    RightOf(spacer2, spacer1, gap=10)
    RightOf(spacer3, spacer2, gap=10)
    RightOf(front, spacer3, gap=10)
    AlignTop(spacer1, back)
    AlignTop(spacer2, back)
    AlignTop(spacer3, back)
    AlignTop(front, back)

    # on the wall: the back against it, the layers stacked towards the viewer (-y)
    Place(back, position=(0, 0, 300), face="front", up="up")
    Place(spacer1, position=(0, -t, 300), face="front", up="up")
    Place(spacer2, position=(0, -2 * t, 300), face="front", up="up")
    Place(spacer3, position=(0, -3 * t, 300), face="front", up="up")
    Place(front, position=(0, -4 * t, 300), face="front", up="up")

    # the request's numbers
    assert back.outline.bb.width == 120 mm, "120 mm wide"
    assert back.outline.bb.height == 270 mm, "270 mm tall"
    assert spacer1.pocket.head.width == 86 mm, "head pocket 86 mm"
    assert spacer1.outline.bb.top - spacer1.pocket.beam.bb.bottom == 245 mm, "pocket 245 deep"
    assert 3 * t >= 17 mm, "the spacers hold a 17 mm caliper"
    assert front.outline.bb.top - front.window.scale_slot.bb.bottom == 235 mm, "slot 235 deep"
    assert back.outline.bb.top - back.screw_low.c.center.y == 200 mm, "low screw 200 down"
    assert back.outline.bb.top - back.screw_top.c.center.y == 30 mm, "top screw 30 down"
}
