# Request (electronics bench): a rest that holds a hot-air / heat gun lying down, 6 mm ply.
# Two saddles 120 wide x 100 tall, top corners R10, each with a half-round cradle of R30 (a 58 mm
# barrel with room) centred on its top edge, the cradle's edges rounded R3. Two rails 220 long x
# 30 tall join the saddles by cross halvings: the saddles slotted 15 mm up from their bottom
# edge at 40 mm each side of their centre, the rails 15 mm down from their top edge 80 mm each
# side of their centre, so the saddles stand 160 mm apart. The front saddle is engraved "HOT"
# (bold, filled, 14 mm tall) centred under its cradle, 48 mm above its bottom edge.

units mm
thickness 6 mm

import "std/joints.aidl"

saddle_w = 120 mm
saddle_h = 100 mm
cradle_r = 30 mm
rail_l = 220 mm
rail_h = 30 mm
halving = 15 mm
rail_y = 40 mm
saddle_x = 80 mm

def saddle(label="") -> solid {
    body = RoundedRectangle(center=(0, saddle_h / 2), width=saddle_w, height=saddle_h,
                            corner_radii=[10, 10, 0, 0])
    hole cradle { c = Circle(center=(0, saddle_h), radius=cradle_r) }
    Fillet([body, cradle.c], 3)
    for s in [-1, 1] {
        h = cross_halving(depth=halving, thickness=6 mm, rotation=180 deg, cx=s * rail_y, cy=0)
    }
    if label != "" {
        drawing mark {
            t = Text(label, position=(0, 48), size=14, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
}

def rail() -> solid {
    body = Rectangle(center=(0, rail_h / 2), width=rail_l, height=rail_h)
    for s in [-1, 1] {
        h = cross_halving(depth=halving, thickness=6 mm, cx=s * saddle_x, cy=rail_h)
    }
}

assembly heat_gun_rest {
    front = saddle(label="HOT")
    back = saddle()
    left_rail = rail()
    right_rail = rail()

    # flat on the sheet
    RightOf(back, front, gap=10)
    AlignBottom(back, front)
    Below(left_rail, front, gap=10)
    AlignLeft(left_rail, front)
    Below(right_rail, left_rail, gap=10)
    AlignLeft(right_rail, left_rail)

    # assembled: saddles across, rails along x, each halving over the other
    # FIX after the first valid program: the front saddle's engraved face looked inward (+x);
    # it faces out, to the nozzle end (-x): bottom face at -77, top face at -83
    Place(front, position=(-saddle_x + 3, 0, 0), face="left", up="up")
    Place(back, position=(saddle_x - 3, 0, 0), face="right", up="up")
    Place(left_rail, position=(0, -rail_y + 3, 0), face="front", up="up")
    Place(right_rail, position=(0, rail_y + 3, 0), face="front", up="up")

    # the request's numbers
    assert front.body.bb.width == 120 mm and front.body.bb.height == 100 mm, "saddle 120 x 100"
    assert front.cradle.c.radius == 30 mm, "cradle R30"
    assert front.body.bb.top - front.cradle.c.center.y == 0 mm, "cradle centred on the top edge"
    assert front.h[1].cut.bb.height == 15 mm and left_rail.h[1].cut.bb.height == 15 mm, "halvings 15"
    assert front.h[1].cut.bb.center_x - front.body.bb.center_x == 40 mm, "saddle slots 40 off centre"
    assert left_rail.h[1].cut.bb.center_x - left_rail.body.bb.center_x == 80 mm, "rail slots 80 off centre"
    assert left_rail.body.bb.width == 220 mm and left_rail.body.bb.height == 30 mm, "rails 220 x 30"
    assert front.mark.t.position.y - front.body.bb.bottom == 48 mm, "HOT 48 above the bottom"
}
