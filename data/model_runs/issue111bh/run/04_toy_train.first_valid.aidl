# Request (toys): a push-along toy steam locomotive from 6 mm ply. Two side frames, mirror
# images, 180 mm long with a 16 mm cowcatcher at the front: a 30 mm chassis band, a
# boiler 100 x 40 with its top front corner rounded r10, a flared chimney (14 mm at the
# boiler, 22 mm at the top, 20 mm tall), a steam dome r9, a cab 70 mm long rising to 105
# mm with an 82 x 6 mm roof and a 36 x 24 window (r4 corners) cut through; "No.7"
# engraved filled, bold 12 mm, under the window on each outer face. The frames stand
# 50 mm apart, held by two 62 x 50 spacers (front and back) with one 30 mm tenon per
# side through a mortise. Two 6 mm dowel axles, 100 mm apart, 12 mm above the frames'
# bottom, turn in 6.5 mm holes; four 40 mm wheels are glued on the dowels (6 mm holes),
# each with five 8 mm lightening holes on a 24 mm circle.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
inner = 50 mm        # between the frames
axle_y = 12 mm
rear_x = -55 mm
front_x = 45 mm
front_spacer = 75 mm  # the spacers' rear faces along the frame
back_spacer = -80 mm
sp_h = 50 mm
sp_y = 10 mm          # the spacers' bottom above the frames' bottom
sp_tab = 30 mm

# a side frame; s = 1: front towards +x, s = -1: the mirror image
def frame(s=1) -> solid {
    chassis = Rectangle(bottom_left=(-90, 0), width=180, height=30)
    boiler = RoundedRectangle(center=(s * 30, 50), width=100, height=40,
                              corner_radii=[0 if s > 0 else 10, 10 if s > 0 else 0, 0, 0])
    chimney = Trapezoid(center=(s * 60, 80), bottom_width=14, top_width=22, height=20)
    dome = Circle(center=(s * 25, 70), radius=9)
    cab = Rectangle(center=(s * -55, 67.5), width=70, height=75)
    roof = Rectangle(center=(s * -55, 108), width=82, height=6)
    catcher = Polygon([(s * 90, 2), (s * 90, 22), (s * 106, 2)])
    hole window { w = RoundedRectangle(center=(s * -55, 85), width=36, height=24, corner_radius=4) }
    hole axles {
        a1 = Circle(center=(s * rear_x, axle_y), diameter=6.5)
        a2 = Circle(center=(s * front_x, axle_y), diameter=6.5)
    }
    front_m = tab_and_slot(part="slot", length=sp_h, thickness=t, tabs=1, tab=sp_tab, screw=0,
                           rotation=90 deg, cx=s * (front_spacer + t / 2), cy=sp_y + sp_h / 2)
    back_m = tab_and_slot(part="slot", length=sp_h, thickness=t, tabs=1, tab=sp_tab, screw=0,
                          rotation=90 deg, cx=s * (back_spacer + t / 2), cy=sp_y + sp_h / 2)
    drawing number {
        n = Text("No.7", position=(s * -55, 45), size=12, font="sans:Bold", valign="middle",
                 fill=true)
    }
}

def spacer() -> solid {
    body = Rectangle(bottom_left=(-inner / 2 - t, sp_y), width=inner + 2 * t, height=sp_h)
    l = tab_and_slot(part="tab", length=sp_h, thickness=t, tabs=1, tab=sp_tab, screw=0,
                     rotation=90 deg, cx=-inner / 2 - t, cy=sp_y + sp_h / 2)
    r = tab_and_slot(part="tab", length=sp_h, thickness=t, tabs=1, tab=sp_tab, screw=0,
                     rotation=-90 deg, cx=inner / 2 + t, cy=sp_y + sp_h / 2)
}

def wheel() -> solid {
    rim = Circle(center=(0, 0), diameter=40)
    hole axle { c = Circle(center=(0, 0), diameter=6) }
    hole light { c = Circle(center=(12, 0), diameter=8) }
    CircularPattern(light, 5, rim.center)
}

assembly loco {
    near = frame(s=1)
    far = frame(s=-1)
    sp_front = spacer()
    sp_back = spacer()
    w0 = wheel()
    w1 = wheel()
    w2 = wheel()
    w3 = wheel()

    # flat on the sheet
    Above(far, near, gap=8)
    AlignLeft(far, near)
    RightOf(sp_front, near, gap=8)
    AlignBottom(sp_front, near)
    RightOf(sp_back, sp_front, gap=8)
    AlignBottom(sp_back, near)
    Above(w0, sp_front, gap=8)
    AlignLeft(w0, sp_front)
    RightOf(w1, w0, gap=6)
    AlignBottom(w1, w0)
    Above(w2, w0, gap=6)
    AlignLeft(w2, w0)
    RightOf(w3, w2, gap=6)
    AlignBottom(w3, w2)

    # assembled: X along the train (front +X), Y across, Z up; frames' bottom at z = 0
    Place(near, position=(0, -inner / 2, 0), rotation=(90 deg, 0, 0))
    Place(far, position=(0, inner / 2, 0), rotation=(90 deg, 0, 180 deg))
    Place(sp_front, position=(front_spacer, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(sp_back, position=(back_spacer, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(w0, position=(rear_x, -inner / 2 - t - 1, axle_y), rotation=(90 deg, 0, 0))
    Place(w1, position=(front_x, -inner / 2 - t - 1, axle_y), rotation=(90 deg, 0, 0))
    Place(w2, position=(rear_x, inner / 2 + t + 1 + t, axle_y), rotation=(90 deg, 0, 0))
    Place(w3, position=(front_x, inner / 2 + t + 1 + t, axle_y), rotation=(90 deg, 0, 0))

    assert near.chassis.bb.width == 180 mm, "180 mm long"
    assert near.catcher.bb.right - near.chassis.bb.right == 16 mm, "16 mm cowcatcher"
    assert near.roof.bb.bottom - near.chassis.bb.bottom == 105 mm, "cab rises to 105 mm"
    assert near.axles.a2.center.x - near.axles.a1.center.x == 100 mm, "axles 100 mm apart"
    assert near.axles.a1.center.y - near.chassis.bb.bottom == 12 mm, "axles 12 mm up"
    assert w0.rim.diameter == 40 mm, "40 mm wheels"
    assert w0.rim.radius > axle_y, "the wheels reach below the frames"
    assert sp_front.body.bb.width == 62 mm and sp_front.body.bb.height == 50 mm, "62 x 50 spacers"
    assert near.window.w.bb.width == 36 mm and near.window.w.bb.height == 24 mm, "36 x 24 window"
}
