# Request (electronics): an under-desk holder for a 6-way power strip 280 x 55 x 40 mm, 6 mm ply.
# A top plate 300 x 70 mm (corners r5) screws to the underside of the desk with four M4
# countersunk screws (clearance holes, 9 mm countersinks) at x = +-100 mm, y = +-20 mm from the
# plate's centre. Two loop hangers hang from it, 15 mm in from the strip's ends (250 mm apart,
# centre to centre); each is a frame 68 mm wide x 53 mm tall (bottom corners r3) around a
# 56 x 41 mm window (the strip plus 1 mm play; window corners r2), so the strip slides in from
# one end. Hangers glued into the top plate with two 15 mm tabs (slots 0.15 mm clearance).
# "POWER 230 V" engraved 8 mm tall in the middle of the top plate's face.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

t = 6 mm
strip_l = 280 mm
strip_w = 55 mm
strip_h = 40 mm
play = 1 mm
win_w = strip_w + play
win_h = strip_h + play
hang_w = win_w + 2 * t
hang_h = win_h + 2 * t
hang_x = strip_l / 2 - 15 mm
xs = [-100, -100, 100, 100]
ys = [-20, 20, -20, 20]

def hanger() -> solid {
    body = RoundedRectangle(bottom_left=(-hang_w / 2, -hang_h / 2), width=hang_w,
                            height=hang_h + t, corner_radii=[0, 0, 3, 3])
    hole window {
        w = RoundedRectangle(center=(0, 0), width=win_w, height=win_h, corner_radius=2)
    }
    tabs = tab_and_slot(part="tab", length=hang_w, thickness=t, tabs=2, tab=15, screw=0,
                        cx=0, cy=hang_h / 2 + t)
}

solid top_plate() {
    body = RoundedRectangle(center=(0, 0), width=300, height=70, corner_radius=5)
    left = tab_and_slot(part="slot", length=hang_w, thickness=t, tabs=2, tab=15, screw=0,
                        clearance=0.15, rotation=90, cx=-hang_x, cy=0)
    right = tab_and_slot(part="slot", length=hang_w, thickness=t, tabs=2, tab=15, screw=0,
                         clearance=0.15, rotation=90, cx=hang_x, cy=0)
    for i in range(4) {
        screw = clearance_hole(size=4, cx=xs[i], cy=ys[i])
    }
    Countersink(screw, diameter=9 mm)
    drawing label { txt = Text("POWER 230 V", position=(0, 0), size=8, valign="middle") }
}

assembly holder {
    plate = top_plate()
    hang_a = hanger()
    hang_b = hanger()

    Above(hang_a, plate, gap=5)
    AlignLeft(hang_a, plate)
    RightOf(hang_b, hang_a, gap=5)
    AlignBottom(hang_b, hang_a)

    # assembled upside down as it hangs: the plate on top, the hangers below it
    Place(plate, position=(0, 0, hang_h))
    Place(hang_a, rotation=(90 deg, 0, 90 deg), position=(-hang_x - t / 2, 0, hang_h / 2))
    Place(hang_b, rotation=(90 deg, 0, 90 deg), position=(hang_x - t / 2, 0, hang_h / 2))

    # the request's numbers
    assert plate.body.bb.width == 300 mm and plate.body.bb.height == 70 mm, "plate size"
    assert len(plate.screw) == 4, "four screws"
    assert plate.screw[3].c.center.x - plate.body.bb.center_x == 100 mm, "screw at x 100"
    assert plate.screw[3].c.center.y - plate.body.bb.center_y == 20 mm, "screw at y 20"
    assert plate.right.bb.center_x - plate.left.bb.center_x == 280 mm - 2 * 15 mm, "hangers"
    assert hang_a.window.w.bb.width == 55 mm + 1 mm and hang_a.window.w.bb.height == 40 mm + 1 mm,
        "window: strip plus 1 mm play"
    assert hang_a.body.bb.width == 68 mm, "hanger 68 wide"
    assert hang_a.tabs.gap[0].bb.bottom - hang_a.body.bb.bottom == 53 mm, "hanger 53 tall"
}
