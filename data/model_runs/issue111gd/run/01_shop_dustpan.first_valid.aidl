# Request (workshop): a shop dustpan from 3 mm birch ply. A flat pan 250 mm wide x 200 mm
# deep, its front edge straight with sharp corners, the back corners rounded R10. A back wall
# 90 mm tall above the pan across the full width, standing 5 mm in from the pan's back edge,
# with a 90 x 28 mm hand hole centred 25 mm below its top (it also hangs the pan on a hook)
# and "SHOP" engraved filled (bold serif, 14 mm) on its front face. Two sides standing 5 mm
# in from the pan's side edges, 8 mm tall at the front, rising on a smooth curve to 90 mm at
# the back wall. All glued: tabs in closed slots, 3 along each side's bottom, 4 along the back
# wall's bottom, 2 up each side's back edge.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
pan_w = 250 mm
pan_d = 200 mm
wall_h = 90 mm        # above the pan
front_h = 8 mm        # side height at the front, above the pan
inset = 5 mm          # sides and back wall in from the pan's edges
side_len = pan_d - inset - t   # front edge to the back wall's front face: 192
side_x = pan_w / 2 - inset - t / 2   # centre plane of a side: 118.5
back_y = pan_d - inset - t / 2       # centre plane of the back wall: 193.5

# the side's top edge above the pan, x from the front
def top_h(x) = front_h + (wall_h - front_h) * (x / side_len) ** 2

def side() -> solid {
    # drawn with the pan's underside at y = 0 (the tabs' tips) and the front at x = 0
    profile = Polygon([(0, 0), (side_len, 0), (side_len, t), (side_len + t, t),
                       (side_len + t, t + wall_h)] +
                      [(side_len * (1 - k / 24), t + top_h(side_len * (1 - k / 24)))
                       for k in range(25)])
    bottom = tab_and_slot(part="tab", length=side_len, thickness=t, tabs=3, tab=30 mm,
                          screw=0, rotation=180 deg, cx=side_len / 2, cy=0 mm)
    backedge = tab_and_slot(part="tab", length=wall_h, thickness=t, tabs=2, tab=20 mm,
                            screw=0, rotation=-90 deg, cx=side_len + t, cy=t + wall_h / 2)
}

assembly dustpan {
    solid base {
        pan = RoundedRectangle(corner=(-pan_w / 2, 0), opposite=(pan_w / 2, pan_d),
                               corner_radii=[10 mm, 10 mm, 0 mm, 0 mm])
        ls = tab_and_slot(part="slot", length=side_len, thickness=t, tabs=3, tab=30 mm,
                          screw=0, rotation=90 deg, cx=-side_x, cy=side_len / 2)
        rs = tab_and_slot(part="slot", length=side_len, thickness=t, tabs=3, tab=30 mm,
                          screw=0, rotation=90 deg, cx=side_x, cy=side_len / 2)
        bs = tab_and_slot(part="slot", length=pan_w, thickness=t, tabs=4, tab=30 mm,
                          screw=0, rotation=0 deg, cx=0 mm, cy=back_y)
    }

    solid back {
        wall = Rectangle(corner=(-pan_w / 2, 0), opposite=(pan_w / 2, t + wall_h))
        feet = tab_and_slot(part="tab", length=pan_w, thickness=t, tabs=4, tab=30 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
        ls = tab_and_slot(part="slot", length=wall_h, thickness=t, tabs=2, tab=20 mm,
                          screw=0, rotation=90 deg, cx=-side_x, cy=t + wall_h / 2)
        rs = tab_and_slot(part="slot", length=wall_h, thickness=t, tabs=2, tab=20 mm,
                          screw=0, rotation=90 deg, cx=side_x, cy=t + wall_h / 2)
        hole grip {
            s = Slot(center=(0, t + wall_h - 25 mm), length=90, width=28)
        }
        drawing label {
            word = Text("SHOP", position=(0, t + 22 mm), size=14, font="serif:Bold",
                        valign="middle", fill=true)
        }
    }

    left = side()
    right = side()

    # flat on the sheet: the back wall right of the pan, the sides above it
    RightOf(back, base, gap=10)
    AlignBottom(back, base)
    Above(left, back, gap=10)
    AlignLeft(left, back)
    Above(right, left, gap=10)
    AlignLeft(right, left)

    # assembled
    Place(base, position=(0, 0, 0), face="up")
    Place(back, position=(0, pan_d - inset, 0), face="front", up="up")
    Place(right, position=(side_x - t / 2, 0, 0), face="right", up="up")
    Place(left, position=(-side_x - t / 2, 0, 0), face="right", up="up")

    assert base.pan.bb.width == 250 mm, "pan 250 wide"
    assert base.pan.bb.height == 200 mm, "pan 200 deep"
    assert back.wall.bb.height - t == 90 mm, "back wall 90 above the pan"
    assert back.wall.bb.top - back.grip.s.center.y == 25 mm, "hand hole 25 below the top"
    assert back.grip.s.length == 90 mm and back.grip.s.width == 28 mm, "hand hole 90 x 28"
    assert left.profile.bb.height - t == 90 mm, "side 90 tall at the back"
    assert left.profile.points[29].y - t == 8 mm, "side 8 tall at the front"
    assert base.pan.bb.right - base.rs.slot[0].bb.right == 5 mm, "side 5 in from the edge"
    assert base.pan.bb.top - base.bs.slot[0].bb.top == 5 mm, "back wall 5 in from the edge"
    assert len(base.ls.slot) == 3 and len(base.bs.slot) == 4 and len(back.ls.slot) == 2,
        "3 / 4 / 2 tabs"
}
