# Request (camping): a flat-pack stand that lifts a cool box (footprint 540 x 330 mm) 300 mm
# off the ground at camp, from 9 mm ply, no glue or screws: it slots together. Two end
# frames 380 mm wide and 300 mm tall, with an arched opening (260 mm wide, 230 mm high,
# elliptical top) between 60 mm legs, a 100 x 30 mm carrying slot centred 35 mm below the
# top, and a 20 x 20 mm stop post at each top corner that keeps the box from sliding
# sideways. Two rails 590 mm long and 80 mm tall, 120 mm either side of the centre, each with
# a 20 x 20 mm stop post at each end, a shallow elliptical arch (340 x 30 mm) cut from the
# middle of the bottom edge, and "BASE CAMP" engraved filled (bold sans, 20 mm) on its outer
# face. Rails and frames cross-halve 40 mm each, 0.2 mm clearance, the frames 75 mm in from
# the rails' ends; the tops finish flush.

import "std/joints.aidl"

thickness 9 mm

t = 9 mm
box_l = 540 mm
box_w = 330 mm
end_w = 380 mm
end_h = 300 mm
rail_l = 590 mm
rail_h = 80 mm
post = 20 mm
rail_y = 120 mm       # rails either side of the centre (across)
end_x = rail_l / 2 - 75 mm   # frames along the rails: 220
half = 40 mm

def end_frame() -> solid {
    body = Rectangle(corner=(-end_w / 2, 0), opposite=(end_w / 2, end_h))
    post_l = RoundedRectangle(corner=(-end_w / 2, end_h - 10 mm), opposite=(-end_w / 2 + post, end_h + post),
                              corner_radii=[5 mm, 5 mm, 0 mm, 0 mm])
    post_r = RoundedRectangle(corner=(end_w / 2 - post, end_h - 10 mm), opposite=(end_w / 2, end_h + post),
                              corner_radii=[5 mm, 5 mm, 0 mm, 0 mm])
    hole arch {
        r = Rectangle(corner=(-130, -5), opposite=(130, 150))
        e = Ellipse(center=(0, 150), rx=130, ry=80)
    }
    hole handle {
        s = Slot(center=(0, end_h - 35 mm), length=100, width=30)
    }
    left_slot = cross_halving(depth=half, thickness=t, clearance=0.2 mm, rotation=0 deg,
                              cx=-rail_y, cy=end_h)
    right_slot = cross_halving(depth=half, thickness=t, clearance=0.2 mm, rotation=0 deg,
                               cx=rail_y, cy=end_h)
}

def rail() -> solid {
    body = Rectangle(corner=(-rail_l / 2, 0), opposite=(rail_l / 2, rail_h))
    post_l = RoundedRectangle(corner=(-rail_l / 2, rail_h - 10 mm), opposite=(-rail_l / 2 + post, rail_h + post),
                              corner_radii=[5 mm, 5 mm, 0 mm, 0 mm])
    post_r = RoundedRectangle(corner=(rail_l / 2 - post, rail_h - 10 mm), opposite=(rail_l / 2, rail_h + post),
                              corner_radii=[5 mm, 5 mm, 0 mm, 0 mm])
    hole arch {
        e = Ellipse(center=(0, 0), rx=170, ry=30)
    }
    left_slot = cross_halving(depth=half, thickness=t, clearance=0.2 mm, rotation=180 deg,
                              cx=-end_x, cy=0 mm)
    right_slot = cross_halving(depth=half, thickness=t, clearance=0.2 mm, rotation=180 deg,
                               cx=end_x, cy=0 mm)
    drawing word {
        w = Text("BASE CAMP", position=(0, 52), size=20, font="sans:Bold", valign="middle",
                 fill=true)
    }
}

assembly stand {
    left_end = end_frame()
    right_end = end_frame()
    front_rail = rail()
    back_rail = rail()

    # flat on the sheet
    RightOf(right_end, left_end, gap=10)
    AlignBottom(right_end, left_end)
    Above(front_rail, left_end, gap=10)
    AlignLeft(front_rail, left_end)
    Above(back_rail, front_rail, gap=10)
    AlignLeft(back_rail, front_rail)

    # assembled: x along the rails, y across, z up; engraved faces outward
    Place(left_end, position=(-end_x - t / 2, 0, 0), face="right", up="up")
    Place(right_end, position=(end_x - t / 2, 0, 0), face="right", up="up")
    Place(front_rail, position=(0, -rail_y + t / 2, end_h - rail_h), face="front", up="up")
    Place(back_rail, position=(0, rail_y - t / 2, end_h - rail_h), face="back", up="up")

    assert left_end.body.bb.width == 380 mm and left_end.body.bb.height == 300 mm, "frame 380 x 300"
    assert left_end.arch.r.bb.width == 260 mm, "arch 260 wide"
    assert left_end.arch.e.bb.top - left_end.body.bb.bottom == 230 mm, "arch 230 high"
    assert (left_end.body.bb.width - left_end.arch.r.bb.width) / 2 == 60 mm, "60 mm legs"
    assert left_end.body.bb.top - left_end.handle.s.center.y == 35 mm, "handle 35 below the top"
    assert front_rail.body.bb.width == 590 mm and front_rail.body.bb.height == 80 mm, "rail 590 x 80"
    assert left_end.left_slot.cut.bb.height == 40 mm and front_rail.left_slot.cut.bb.height == 40 mm,
        "halvings 40 each"
    assert front_rail.left_slot.cut.bb.height + left_end.left_slot.cut.bb.height == rail_h,
        "tops flush"
    assert front_rail.right_slot.cut.bb.center_x - front_rail.body.bb.center_x == 220 mm,
        "frames 75 in from the rail ends"
    # the box fits between the posts with 5 mm to spare each way
    assert (left_end.post_r.bb.left - left_end.post_l.bb.right) - box_w >= 10 mm, "box fits across"
    assert (front_rail.post_r.bb.left - front_rail.post_l.bb.right) - box_l >= 10 mm, "box fits along"
    assert front_rail.arch.e.bb.width == 340 mm, "rail arch 340"
    assert distance(front_rail.word, front_rail.arch) >= 3 mm, "word clear of the arch"
}
