# Request (gifts): an anniversary plaque for a couple, standing on a desk. Two glued layers
# 200 x 120 mm with 8 mm rounded corners: a back of 3 mm walnut ply and a front of 3 mm white
# acrylic. Through the front, "SAM" and "ALEX" are cut as bold stencil letters 22 mm tall with
# a heart (about 23 mm wide) cut between them, all centred on a line 75 mm above the plaque's
# bottom edge, so the walnut shows through. Below them, engraved (single stroke) on the front:
# the place's coordinates "51.5074° N  0.1278° W" 7 mm tall, 40 mm above the bottom edge, and
# "EST. 14.02.2019" 5 mm tall, 25 mm above the bottom edge; an engraved border line 6 mm inside
# the edge. Both layers have a tenon 180 x 6 mm under their bottom edge that stands in a
# 180.2 x 6.2 mm mortise in a base of 6 mm ply, 220 x 50 mm with 6 mm rounded corners, the
# mortise on the base's centre line; "HOME IS WHERE WE ARE" engraved 5 mm tall on the base,
# centred 14 mm in front of the mortise. Assembled in 3D.

thickness 3 mm

param plaque_w = 200 mm, min = 150 mm, max = 300 mm
param plaque_h = 120 mm, min = 80 mm, max = 200 mm
base_t = 6 mm
tenon_w = 180 mm

def layer() -> solid {
    # own frame: y = 0 is the base's top (the plaque's bottom edge), the tenon below it
    plate = RoundedRectangle(center=(0, plaque_h / 2), width=plaque_w, height=plaque_h, corner_radius=8)
    tenon = Rectangle(center=(0, -base_t / 2), width=tenon_w, height=base_t + 1 mm)
}

assembly plaque {
    back = layer()
    front = layer()
    hole names {
        sam = Text("SAM", position=(-14, 75), size=22, font="sans:Bold", anchor="end",
                   valign="middle", stencil=true)
        heart_l = Hull(Circle(center=(-5.5, 78.5), radius=6), Point(0, 64))
        heart_r = Hull(Circle(center=(5.5, 78.5), radius=6), Point(0, 64))
        alex = Text("ALEX", position=(14, 75), size=22, font="sans:Bold", anchor="start",
                    valign="middle", stencil=true)
    }
    drawing words {
        coords = Text("51.5074° N  0.1278° W", position=(0, 40), size=7, valign="middle")
        est = Text("EST. 14.02.2019", position=(0, 25), size=5, valign="middle")
        border = RoundedRectangle(center=(0, plaque_h / 2), width=plaque_w - 12 mm,
                                  height=plaque_h - 12 mm, corner_radius=4)
    }
    AlignCenterX(words.border, front.plate)
    AlignCenterY(words.border, front.plate)
    # the names and heart as one group, centred across the plate ("ALEX" is wider than "SAM")
    AlignCenterX(names, front.plate)
    names.sam.position.y == front.plate.bb.bottom + 75 mm
    CutInto(names, front)
    CutInto(words, front)

    solid base {
        thickness 6 mm
        slab = RoundedRectangle(center=(0, 0), width=220, height=50, corner_radius=6)
        hole mortise {
            m = Rectangle(center=(0, 0), width=tenon_w + 0.2 mm, height=2 * 3 mm + 0.2 mm)
        }
        drawing motto {
            t = Text("HOME IS WHERE WE ARE", position=(0, -14), size=5, valign="middle")
        }
    }

    # on the sheet
    RightOf(front, back, gap=8)
    AlignBottom(front, back)
    Below(base, back, gap=8)
    AlignLeft(base, back)

    # assembled: base on z = 0, the back behind the front, both standing in the mortise
    Place(base, position=(0, 0, 0))
    Place(back, rotation=(90 deg, 0, 0), position=(0, 3 mm, base_t))
    Place(front, rotation=(90 deg, 0, 0), position=(0, 0, base_t))

    # the request's numbers
    assert front.plate.bb.width == 200 mm and front.plate.bb.height == 120 mm, "200 x 120"
    assert abs(names.sam.position.y - front.plate.bb.bottom - 75 mm) < 0.01 mm, "names 75 mm up"
    assert names.sam.size == 22 mm and names.alex.size == 22 mm, "names 22 mm"
    assert abs(words.coords.position.y - front.plate.bb.bottom - 40 mm) < 0.01 mm, "coordinates 40 mm up"
    assert abs(words.est.position.y - front.plate.bb.bottom - 25 mm) < 0.01 mm, "date 25 mm up"
    assert words.coords.size == 7 mm and words.est.size == 5 mm, "text sizes"
    assert abs(front.plate.bb.right - words.border.bb.right - 6 mm) < 0.01 mm, "border 6 mm in"
    assert names.bb.width < plaque_w - 2 * 12 mm, "the names clear the border"
    assert abs(names.bb.center_x - front.plate.bb.center_x) < 3 mm, "the names roughly centred"
    assert front.tenon.bb.width == 180 mm, "tenon 180"
    assert base.mortise.m.bb.width == 180.2 mm and base.mortise.m.bb.height == 6.2 mm, "mortise 180.2 x 6.2"
    assert base.slab.bb.width == 220 mm and base.slab.bb.height == 50 mm, "base 220 x 50"
    assert abs(base.motto.t.position.y - base.mortise.m.center.y + 14 mm) < 0.01 mm, "motto 14 mm in front"
}
