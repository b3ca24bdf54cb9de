# Request (gifts): a six-pack beer caddy for my brother Tom, 6 mm ply, glued.
# - box: an open finger-jointed box 260 long x 180 deep x 90 high outside, 15 mm fingers;
#   "TOM'S BREWS" (14 mm bold serif) and "EST. 2026" (6 mm) engraved filled on the front,
#   the pair centred on it.
# - handle: a centre board along the length, 250 high from the floor of the box, top corners
#   R40, a 110 x 30 hand-hold slot whose top is 30 mm below the board's top; three 30 mm
#   tenons in its foot into the box's bottom and a 40 mm tenon at each end, centred 48 mm
#   above the floor, through the end walls (mortises 0.2 mm over).
# - two cross dividers 167 x 80 (0.5 mm play to the front and back walls), cross-halved
#   with the handle board (handle slotted up from its foot, dividers down from their top,
#   0.2 mm clearance), making six equal cells for 65 mm bottles.
# - a cast-iron bottle opener on the right end wall: two countersunk M4 holes (heads 8 mm)
#   57 mm apart one above the other, 45 mm in front of the centre line, the lower 20 mm above
#   the floor.

units mm
thickness 6 mm

import "std/joints.aidl"
import "std/fasteners.aidl"

t = 6 mm
box_l = 260 mm
box_d = 180 mm
box_h = 90 mm
in_l = box_l - 2 * t           # 248
in_d = box_d - 2 * t           # 168
cell_l = (in_l - 2 * t) / 3    # 78.67
cross_x = cell_l / 2 + t / 2   # the cross dividers' mid-planes: 42.33 from the centre
handle_h = 250 mm
tenon_z = 48 mm
div_h = 80 mm
halving = div_h / 2

assembly caddy {
    box = finger_box(length=box_l, depth=box_d, height=box_h, thickness=t, finger=15 mm,
                     closed=false)

    drawing label {
        field = Rectangle(center=(0, 0), width=260, height=90, construction=true)
        name = Text("TOM'S BREWS", position=(0, 8), size=14, font="serif:Bold",
                    valign="middle", fill=true)
        est = Text("EST. 2026", position=(0, -18), size=6, font="sans", valign="middle",
                   fill=true)
    }
    CenterInside(label.field, box.front)
    CutInto(label, box.front)

    solid handle {
        body = RoundedRectangle(center=(0, handle_h / 2), width=in_l, height=handle_h,
                                corner_radii=[40, 40, 0, 0])
        left_tenon = Rectangle(center=(-in_l / 2 - t / 2, tenon_z), width=t, height=40)
        right_tenon = Rectangle(center=(in_l / 2 + t / 2, tenon_z), width=t, height=40)
        foot = tab_and_slot(part="tab", length=in_l, thickness=t, tabs=3, tab=30 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=0 mm)
        hole grip {
            g = Slot(center=(0, handle_h - 30 - 15), length=110, width=30)
        }
        left_halving = cross_halving(depth=halving, thickness=t, clearance=0.2 mm,
                                     rotation=180 deg, cx=-cross_x, cy=t)
        right_halving = cross_halving(depth=halving, thickness=t, clearance=0.2 mm,
                                      rotation=180 deg, cx=cross_x, cy=t)
    }

    hole floor_mortises {
        m = tab_and_slot(part="slot", length=in_l, thickness=t, tabs=3, tab=30 mm, screw=0,
                         clearance=0.2 mm)
    }
    CenterInside(floor_mortises, box.bottom)
    CutInto(floor_mortises, box.bottom)

    # the end walls lie on their sides in the net, their top edge outward: the left's
    # floor edge is its right side, the right's its left side
    hole left_mortise {
        r = Rectangle(center=(0, 0), width=40.2, height=6.2)
    }
    left_mortise.r.center.x == box.left.bb.right - tenon_z
    AlignCenterY(left_mortise, box.left)
    CutInto(left_mortise, box.left)
    hole right_mortise {
        r = Rectangle(center=(0, 0), width=40.2, height=6.2)
    }
    right_mortise.r.center.x == box.right.bb.left + tenon_z
    AlignCenterY(right_mortise, box.right)
    CutInto(right_mortise, box.right)

    low_screw = clearance_hole(size=4)
    high_screw = clearance_hole(size=4)
    low_screw.c.center.x == box.right.bb.left + 20 mm
    high_screw.c.center.x == box.right.bb.left + 20 mm + 57 mm
    # FIX after the first valid program: the assembled view showed the opener's holes in
    # the BACK half of the end wall. The right wall lies in the net with its outer face up
    # and its top edge at +x, so the net's +y is the world's -y (the front): + 45 mm.
    low_screw.c.center.y == box.right.bb.center_y + 45 mm
    high_screw.c.center.y == box.right.bb.center_y + 45 mm
    CutInto(low_screw, box.right)
    CutInto(high_screw, box.right)
    Countersink([low_screw, high_screw], diameter=8 mm)

    def divider() -> solid {
        body = Rectangle(center=(0, t + 40), width=167, height=80)
        slot = cross_halving(depth=40 mm, thickness=6 mm, clearance=0.2 mm, cx=0 mm,
                             cy=86 mm)
    }
    left_divider = divider()
    right_divider = divider()

    # 3D: the box as the template stands it; the handle board along x, the dividers across
    Place(handle, position=(0, t / 2, 0), face="front", up="up")
    Place(left_divider, position=(-cross_x - t / 2, 0, 0), face="right", up="up")
    Place(right_divider, position=(cross_x - t / 2, 0, 0), face="right", up="up")

    # the sheet
    RightOf(handle, box, gap=10)
    AlignTop(handle, box)
    Below(left_divider, handle, gap=8)
    AlignLeft(left_divider, handle)
    RightOf(right_divider, left_divider, gap=8)
    AlignTop(right_divider, left_divider)

    # the request's numbers
    assert box.front.bb.width == 260 mm and box.front.bb.height == 90 mm, "260 x 90"
    assert box.left.bb.height == 180 mm, "180 deep"
    assert handle.body.bb.height == 250 mm, "handle 250 from the floor"
    assert handle.body.bb.top - handle.grip.g.bb.top == 30 mm, "30 mm over the grip"
    assert handle.grip.g.length == 110 mm and handle.grip.g.width == 30 mm, "110 x 30"
    assert len(handle.foot.gap) == 4, "three foot tenons"
    assert cell_l >= 65 mm + 10 mm and (in_d - t) / 2 >= 65 mm + 10 mm, "bottles fit"
    assert left_divider.body.bb.width == in_d - 1 mm, "0.5 mm play front and back"
    assert left_divider.body.bb.height == div_h and div_h < box_h - t, "below the rim"
    assert left_divider.slot.depth + handle.left_halving.depth == div_h, "halvings meet"
    assert distance(low_screw.c.center, high_screw.c.center) == 57 mm, "57 mm apart"
    assert low_screw.c.center.x - box.right.bb.left == 20 mm, "lower 20 above the floor"
    assert high_screw.c.center.x + 10 mm < box.right.bb.right, "upper clear of the rim"
    assert abs(tenon_z - 45 mm) < 20 mm, "end tenon within the end wall"
}
