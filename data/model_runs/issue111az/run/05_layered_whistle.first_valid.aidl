# Request: a referee's whistle glued up from three layers of 3 mm acrylic, 65 mm long.
# All three layers share one outline: a 30 mm round chamber end (its centre 50 mm from the
# mouth end) drawn into a mouthpiece 40 mm long and 18 mm tall (its top edge 14 mm above
# the chamber's centre line, so the windway runs along the top like a Thunderer), plus a
# 12 mm lug for the lanyard at the chamber's top back, with a 3.5 mm lanyard hole.
# - Bottom layer: plain.
# - Middle layer: a 22 mm round chamber and a 6 mm windway (from 5 to 11 mm above the
#   centre line, tangent to the chamber's top) open at the mouth end.
# - Top layer: an 8 x 8 mm window over the windway's end (from 40 to 48 mm from the mouth
#   end, 4 to 12 mm above the centre line): its back edge over the chamber is the blade.
#   "REF" engraved on the top layer over the chamber, 5 mm letters.

thickness 3 mm

cx0 = 50 mm      # chamber centre from the mouth end
outer_r = 15 mm
chamber_d = 22 mm

def layer(kind="bottom") -> solid {
    body = Hull(Rectangle(bottom_left=(0, -4 mm), width=40 mm, height=18 mm),
                Circle(center=(cx0, 0), radius=outer_r))
    lug = Circle(center=(cx0 + 12 mm, 12 mm), diameter=12 mm)
    hole lanyard {
        c = Circle(center=(cx0 + 12 mm, 12 mm), diameter=3.5 mm)
    }
    if kind == "middle" {
        hole air {
            chamber = Circle(center=(cx0, 0), diameter=chamber_d)
            windway = Rectangle(bottom_left=(-1 mm, 5 mm), width=cx0 - 5 mm, height=6 mm)
        }
    }
    if kind == "top" {
        hole window {
            r = Rectangle(bottom_left=(40 mm, 4 mm), width=8 mm, height=8 mm)
        }
        drawing mark {
            word = Text("REF", position=(cx0, -6 mm), size=5 mm, valign="middle")
        }
    }
}

assembly whistle {
    bottom = layer(kind="bottom")
    middle = layer(kind="middle")
    top = layer(kind="top")

    # flat on the sheet
    RightOf(middle, bottom, gap=4 mm)
    AlignBottom(middle, bottom)
    RightOf(top, middle, gap=4 mm)
    AlignBottom(top, middle)

    # in 3D: stacked
    Place(bottom, position=(0, 0, 0))
    Place(middle, position=(0, 0, 3 mm))
    Place(top, position=(0, 0, 6 mm))

    # the request's numbers
    assert bottom.body.bb.width == 65 mm, "65 mm long"
    assert bottom.body.bb.top - bottom.body.bb.bottom == 30 mm, "30 mm round chamber end"
    assert middle.air.chamber.diameter == 22 mm, "22 mm chamber"
    assert middle.air.windway.height == 6 mm, "6 mm windway"
    assert middle.air.windway.bb.top - middle.air.chamber.center.y == 11 mm, "windway tangent to the chamber's top"
    assert middle.air.windway.bb.left < middle.body.bb.left, "windway open at the mouth"
    assert top.window.r.bb.left - top.body.bb.left == 40 mm and top.window.r.bb.right - top.body.bb.left == 48 mm,
           "window 40 to 48 from the mouth end"
    assert top.window.r.bb.right - top.body.bb.left > cx0 - chamber_d / 2, "the blade is over the chamber"
    assert bottom.lanyard.c.diameter == 3.5 mm, "3.5 mm lanyard hole"
}
