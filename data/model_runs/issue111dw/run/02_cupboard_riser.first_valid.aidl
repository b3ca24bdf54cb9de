# Request (kitchen): a cupboard shelf riser in 6 mm plywood, to stack plates under and mugs on.
# A 300 x 140 shelf with R5 corners whose top is 110 mm above the cupboard floor, on two side
# panels set 15 mm in from its ends; each side goes through the shelf with two 30 mm tenons.
# Each side has a half-elliptical arch 90 wide and 50 tall cut from its bottom edge, so it
# stands on two feet. A 40 mm tall back stretcher, 10 mm below the shelf and 5 mm in from the
# back edge, goes through both sides with one 20 mm tenon at each end (through tenons, glued).

import "std/joints.aidl"

thickness 6 mm
t = 6 mm

shelf_w = 300 mm
depth = 140 mm
height = 110 mm
inset = 15 mm
arch_w = 90 mm
arch_h = 50 mm
str_h = 40 mm
str_drop = 10 mm
str_in = 5 mm

# x of a side's outer face from the middle
side_x = shelf_w / 2 - inset

def side() -> solid {
    # frame: x along the depth (front at -depth / 2), y up from the cupboard floor
    body = Rectangle(bottom_left=(-depth / 2, 0), width=depth, height=height)
    tenons = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=30 mm, screw=0,
                          cx=0 mm, cy=height)
    hole arch {
        a = Intersect(Ellipse(center=(0, 0), rx=arch_w / 2, ry=arch_h),
                      Rectangle(bottom_left=(-arch_w / 2, -1), width=arch_w, height=arch_h + 1))
    }
    # the stretcher's mortise: its middle 5 mm + t / 2 in from the back edge
    mort = tab_and_slot(part="slot", length=str_h, thickness=t, tabs=1, tab=20 mm, screw=0,
                        rotation=90 deg, cx=depth / 2 - str_in - t / 2,
                        cy=height - t - str_drop - str_h / 2)
}

assembly cupboard_riser {
    solid shelf {
        top = RoundedRectangle(center=(0, 0), width=shelf_w, height=depth, corner_radius=5)
        ml = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=30 mm, screw=0,
                          rotation=90 deg, cx=-side_x + t / 2, cy=0 mm)
        mr = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=30 mm, screw=0,
                          rotation=90 deg, cx=side_x - t / 2, cy=0 mm)
    }

    left = side()
    right = side()

    solid stretcher {
        body = Rectangle(center=(0, 0), width=2 * side_x, height=str_h)
        tl = tab_and_slot(part="tab", length=str_h, thickness=t, tabs=1, tab=20 mm, screw=0,
                          rotation=90 deg, cx=-side_x, cy=0 mm)
        tr = tab_and_slot(part="tab", length=str_h, thickness=t, tabs=1, tab=20 mm, screw=0,
                          rotation=-90 deg, cx=side_x, cy=0 mm)
    }

    # flat on the sheet
    Below(left, shelf, gap=10)
    AlignLeft(left, shelf)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    Below(stretcher, left, gap=10)
    AlignLeft(stretcher, shelf)

    # in 3D: both sides face right, their drawing's +x toward the back
    Place(shelf, position=(0, 0, height - t))
    Place(left, position=(-side_x, 0, 0), face="right", up="up")
    Place(right, position=(side_x - t, 0, 0), face="right", up="up")
    Place(stretcher, position=(0, depth / 2 - str_in, height - t - str_drop - str_h / 2),
          face="front", up="up")

    assert shelf.top.bb.width == 300 mm and shelf.top.bb.height == 140 mm, "shelf 300 x 140"
    assert left.body.bb.height == 110 mm, "shelf top 110 above the floor"
    assert shelf.top.bb.right - shelf.mr.slot[0].bb.right == 15 mm, "sides 15 mm in"
    assert shelf.ml.slot[0].bb.left - shelf.top.bb.left == 15 mm, "sides 15 mm in (left)"
    assert len(shelf.ml.slot) == 2 and shelf.ml.slot[0].bb.height == 30 mm, "two 30 mm tenons"
    assert left.arch.bb.width == 90 mm, "arch 90 wide"
    assert left.arch.bb.top - left.body.bb.bottom == 50 mm, "arch 50 tall"
    assert stretcher.body.bb.height == 40 mm, "stretcher 40 tall"
    assert stretcher.bb.width == shelf.mr.slot[0].bb.right - shelf.ml.slot[0].bb.left,
        "stretcher tenons end flush with the sides' outer faces"
    assert left.body.bb.top - 6 mm - left.mort.slot[0].bb.top == 10 mm + 10 mm,
        "stretcher 10 below the shelf (its 20 mm tenon centred on its 40 mm end)"
    assert left.body.bb.right - left.mort.slot[0].bb.right == 5 mm, "stretcher 5 mm in"
}
