# Request (toys): a doll's bed for a 45 cm doll, 6 mm ply, for a 480 x 240 mm mattress.
# Headboard 272 mm wide, 300 mm tall in the middle of an arched top that comes down to 240 mm
# at its sides; footboard the same width, 200 mm in the middle, 160 mm at its sides. Both
# stand on two 40 mm legs with an arch between them, 40 mm high in the middle. Each has a
# heart cut out (headboard's 68 mm wide, footboard's 51 mm wide) above the side rails. Two
# side rails 480 x 80 mm (plus 6 mm tenons, two 20 mm tenons each end) join the boards, their
# underside 60 mm off the floor, 240 mm apart inside and each 10 mm in from the boards'
# edges. The bed base, 480 x 240 mm, sits in the rails by four 40 mm tabs a side, 15 mm above
# their bottom edge. The doll's name "LOTTIE" is engraved filled (18 mm, bold) along the
# headboard's arch, 32 mm below its edge.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
inner_w = 240 mm
bed_len = 480 mm
half_w = inner_w / 2 + t + 10 mm        # 136: board half-width
rail_x = inner_w / 2 + t / 2            # rail's middle plane
rail_h = 80 mm
rail_low = 60 mm
base_up = 15 mm

def arch_centre(top_h, edge_h) = (top_h ** 2 - edge_h ** 2 - half_w ** 2) / (2 * (top_h - edge_h))

def end_board(top_h=300 mm, edge_h=240 mm, heart_y=200 mm, k=2, name="") -> solid {
    l1 = Line((-half_w, 0), (-half_w, edge_h))
    a1 = Arc(start=(-half_w, edge_h), through=(0, top_h), end=(half_w, edge_h))
    l2 = Line((half_w, edge_h), (half_w, 0))
    l3 = Line((half_w, 0), (half_w - 40 mm, 0))
    a2 = Arc(start=(half_w - 40 mm, 0), through=(0, 40 mm), end=(-half_w + 40 mm, 0))
    l4 = Line((-half_w + 40 mm, 0), (-half_w, 0))
    hole heart {
        h1 = Hull(Circle(center=(-8 * k, heart_y + 5 * k), radius=9 * k), Point(0, heart_y - 16 * k))
        h2 = Hull(Circle(center=(8 * k, heart_y + 5 * k), radius=9 * k), Point(0, heart_y - 16 * k))
    }
    ml = tab_and_slot(part="slot", length=rail_h, thickness=t, tabs=2, tab=20 mm, screw=0,
                      rotation=90 deg, cx=-rail_x, cy=rail_low + rail_h / 2)
    mr = tab_and_slot(part="slot", length=rail_h, thickness=t, tabs=2, tab=20 mm, screw=0,
                      rotation=90 deg, cx=rail_x, cy=rail_low + rail_h / 2)
    if name != "" {
        drawing label {
            ring = Circle(center=(0, arch_centre(top_h, edge_h)),
                          radius=top_h - arch_centre(top_h, edge_h) - 32 mm, construction=true)
            n = Text(name, along=ring, size=18, font="sans:Bold", fill=true)
        }
    }
    Fixed(l1)
    Fixed(l2)
    Fixed(l3)
    Fixed(l4)
    assert heart.bb.bottom > rail_low + rail_h, "heart above the rails"
}

def side_rail() -> solid {
    body = Rectangle(center=(0, 0), width=bed_len, height=rail_h)
    end_r = Rectangle(center=(bed_len / 2 + t / 2, 0), width=t, height=rail_h)
    end_l = Rectangle(center=(-bed_len / 2 - t / 2, 0), width=t, height=rail_h)
    ten_r = tab_and_slot(part="tab", length=rail_h, thickness=t, tabs=2, tab=20 mm, screw=0,
                         rotation=-90 deg, cx=bed_len / 2 + t, cy=0)
    ten_l = tab_and_slot(part="tab", length=rail_h, thickness=t, tabs=2, tab=20 mm, screw=0,
                         rotation=90 deg, cx=-bed_len / 2 - t, cy=0)
    mb = tab_and_slot(part="slot", length=bed_len, thickness=t, tabs=4, tab=40 mm, screw=0,
                      cx=0, cy=-rail_h / 2 + base_up + t / 2)
    Fixed(body)
    Fixed(end_r)
    Fixed(end_l)
}

assembly doll_bed {
    head = end_board(top_h=300 mm, edge_h=240 mm, heart_y=200 mm, k=2, name="LOTTIE")
    foot = end_board(top_h=200 mm, edge_h=160 mm, heart_y=170 mm, k=1.5)
    left = side_rail()
    right = side_rail()

    solid base {
        board = Rectangle(center=(0, 0), width=bed_len, height=inner_w)
        s1 = Rectangle(center=(0, inner_w / 2 + t / 2), width=bed_len, height=t)
        s2 = Rectangle(center=(0, -inner_w / 2 - t / 2), width=bed_len, height=t)
        tb = tab_and_slot(part="tab", length=bed_len, thickness=t, tabs=4, tab=40 mm, screw=0,
                          cx=0, cy=inner_w / 2 + t)
        tf = tab_and_slot(part="tab", length=bed_len, thickness=t, tabs=4, tab=40 mm, screw=0,
                          rotation=180 deg, cx=0, cy=-inner_w / 2 - t)
        Fixed(board)
        Fixed(s1)
        Fixed(s2)
        assert board.bb.width == 480 mm and board.bb.height == 240 mm
    }

    # the request's sizes
    assert head.bb.width == 272 mm and head.bb.height == 300 mm
    assert foot.bb.width == 272 mm and foot.bb.height == 200 mm
    assert head.mr.slot[0].bb.left - head.ml.slot[0].bb.right == 240 mm, "240 mm inside"
    assert head.bb.right - head.mr.slot[0].bb.right == 10 mm, "rails 10 mm in"
    assert head.heart.bb.width > 67 mm and head.heart.bb.width < 69 mm
    assert foot.heart.bb.width > 50 mm and foot.heart.bb.width < 52 mm

    # flat on the sheet
    RightOf(foot, head, gap=8)
    AlignBottom(foot, head)
    Below(left, head, gap=8)
    AlignLeft(left, head)
    Below(right, left, gap=8)
    AlignLeft(right, left)
    Below(base, right, gap=8)
    AlignLeft(base, right)

    # assembled: head at the back (+y), foot at the front, rails between, base in the rails
    Place(head, position=(0, bed_len / 2 + t, 0), face="front", up="up")
    Place(foot, position=(0, -bed_len / 2, 0), face="front", up="up")
    Place(left, position=(-rail_x - t / 2, 0, rail_low + rail_h / 2), face="right", up="up")
    Place(right, position=(rail_x - t / 2, 0, rail_low + rail_h / 2), face="right", up="up")
    Place(base, position=(0, 0, rail_low + base_up), face="up", up="left")
}
