# Request: a stair basket for our carpeted stairs (rise 190 mm, going 230 mm). It stands on two
# treads: a lower compartment on the lower tread, an upper one on the next tread. 380 mm wide
# overall, 6 mm birch ply, glued tab-and-mortise joints. The side walls run 150 mm above each
# floor at the front and at the back (a straight sloping top between). A riser panel between
# the two compartments rises into a carry handle with a 110 x 32 mm hand hole. "UPSTAIRS"
# engraved (filled bold letters) on the front wall.

import "std/joints.aidl"

units mm
thickness 6 mm
kerf 0.15 mm

t = 6 mm
rise = 190 mm
going = 230 mm
width = 380 mm
wall = 150 mm

# side profile (x: front to back, y: up); floors stand 8 mm above the treads on the sides
lo_floor_y = 8 mm          # bottom of the lower floor
up_floor_y = rise + 8 mm   # bottom of the upper floor
front_x = 8 mm             # front wall's outer face
riser_x = 218 mm           # riser panel's front face
back_x = 426 mm            # back wall's front face
step_x = going + 2 mm      # the side's step edge, 2 mm behind the stair's riser... (clearance below)

def side() -> solid {
    body = Polygon([(0, 0), (going - 6, 0), (going - 6, rise), (440, rise), (440, up_floor_y + t + wall),
                    (0, lo_floor_y + t + wall)])
    # mortises for the two floors, the front and back walls and the riser panel
    m_lo = tab_and_slot(part="slot", length=riser_x - (front_x + t), thickness=t, tabs=3, tab=40,
                        screw=0, cx=(front_x + t + riser_x) / 2, cy=lo_floor_y + t / 2)
    m_up = tab_and_slot(part="slot", length=back_x - (riser_x + t), thickness=t, tabs=3, tab=40,
                        screw=0, cx=(riser_x + t + back_x) / 2, cy=up_floor_y + t / 2)
    m_front = tab_and_slot(part="slot", length=156, thickness=t, tabs=2, tab=40, screw=0,
                           rotation=90, cx=front_x + t / 2, cy=lo_floor_y + 156 / 2)
    m_back = tab_and_slot(part="slot", length=146, thickness=t, tabs=2, tab=40, screw=0,
                          rotation=90, cx=back_x + t / 2, cy=up_floor_y + 146 / 2)
    m_riser = tab_and_slot(part="slot", length=236, thickness=t, tabs=3, tab=40, screw=0,
                           rotation=90, cx=riser_x + t / 2, cy=lo_floor_y + t + 236 / 2)
    # the step in the side is the stair's rise; walls 150 above each floor
    assert body.points[2].y - body.points[1].y == 190 mm, "step = rise"
    assert body.points[5].y - (lo_floor_y + t) == 150 mm, "front wall 150 above the lower floor"
    assert body.points[4].y - (up_floor_y + t) == 150 mm, "back wall 150 above the upper floor"
    assert body.points[1].x <= 230 mm, "lower part fits the going"
}

# a panel whose left and right edges carry glued tabs into the sides' mortises
def tabbed(w=380 mm, h=100 mm, n=2) -> solid {
    body = Rectangle(center=(0, 0), width=w, height=h)
    left = tab_and_slot(part="tab", length=h, thickness=6 mm, tabs=n, tab=40, screw=0,
                        rotation=90, cx=-w / 2, cy=0)
    right = tab_and_slot(part="tab", length=h, thickness=6 mm, tabs=n, tab=40, screw=0,
                         rotation=-90, cx=w / 2, cy=0)
}

assembly stair_basket {
    side_a = side()
    side_b = side()
    RightOf(side_b, side_a, gap=10)
    AlignBottom(side_b, side_a)

    lower_floor = tabbed(w=width, h=riser_x - (front_x + t), n=3)
    upper_floor = tabbed(w=width, h=back_x - (riser_x + t), n=3)
    front = tabbed(w=width, h=156, n=2)
    back = tabbed(w=width, h=146, n=2)

    drawing label {
        word = Text("UPSTAIRS", position=(0, 0), size=40, font="sans:Bold", valign="middle", fill=true)
    }
    CutInto(label, front)
    CenterInside(label, front.body)

    solid riser {
        lower = Rectangle(center=(0, 0), width=width, height=236)
        left = tab_and_slot(part="tab", length=236, thickness=6 mm, tabs=3, tab=40, screw=0,
                            rotation=90, cx=-width / 2, cy=0)
        right = tab_and_slot(part="tab", length=236, thickness=6 mm, tabs=3, tab=40, screw=0,
                             rotation=-90, cx=width / 2, cy=0)
        handle = RoundedRectangle(center=(0, 118 + 45), width=300, height=110,
                                  corner_radii=[20, 20, 0, 0])
        hole grip {
            s = Slot(center=(0, 118 + 70), length=110, width=32)
        }
    }

    # lay the flat parts out for the sheet
    Below(lower_floor, side_a, gap=10)
    AlignLeft(lower_floor, side_a)
    RightOf(upper_floor, lower_floor, gap=10)
    AlignTop(upper_floor, lower_floor)
    Below(front, lower_floor, gap=10)
    AlignLeft(front, lower_floor)
    RightOf(back, front, gap=10)
    AlignTop(back, front)
    Below(riser, front, gap=10)
    AlignLeft(riser, front)

    assert lower_floor.body.bb.width == 380 mm, "380 wide overall"
    assert riser.grip.s.length == 110 mm and riser.grip.s.width == 32 mm, "hand hole 110 x 32"
    assert riser.bb.top - riser.lower.bb.top > 32 mm, "handle stands above the sides"
}
