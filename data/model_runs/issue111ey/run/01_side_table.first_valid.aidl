# Request (home): a flat-pack round side table in 9 mm birch ply, no glue, no screws.
# The top is 440 mm round; my sheet is only 400 mm deep, so the top is cut as two halves
# joined along the seam by a sliding dovetail: 3 tails, 300 mm long, 12 mm deep, 10 deg,
# 0.2 mm clearance. The table stands 500 mm tall on two legs of the same outline, crossed
# in an X (a cross-halving, 0.2 mm clearance) that is turned 45 deg to the seam. Each leg is
# a trapezoid 380 mm wide at the floor and 300 mm under the top, with a 110 mm radius arch
# cut between its feet; each leg has two 40 mm tenons, 75 mm either side of its middle,
# through mortises in the top (0.2 mm clearance), flush with the top surface.

units mm
t = 9 mm
thickness t

top_d = 440 mm
height = 500 mm
leg_bottom = 380 mm
leg_top = 300 mm
arch_r = 110 mm
tenon = 40 mm
tenon_off = 75 mm
fit = 0.2 mm
leg_h = height - t            # the top's underside
overlap = leg_h - arch_r       # where both legs have material, arch apex to underside

import "std/joints.aidl"

def leg(from_top=true) -> solid {
    body = Trapezoid(center=(0, height / 2), bottom_width=leg_bottom, top_width=leg_top,
                     height=height)
    hole arch {
        a = Sector(center=(0, 0), radius=arch_r, start_angle=0 deg, end_angle=180 deg)
    }
    # two tenons, 75 either side of the middle; the body reaches the top surface (500)
    ten_r = tab_and_slot(part="tab", length=leg_top / 2, thickness=t, tabs=1, tab=tenon,
                         screw=0, cx=tenon_off, cy=height)
    ten_l = tab_and_slot(part="tab", length=leg_top / 2, thickness=t, tabs=1, tab=tenon,
                         screw=0, cx=-tenon_off, cy=height)
    if from_top {
        x = cross_halving(depth=overlap / 2, thickness=t, clearance=fit, cx=0, cy=leg_h)
    } else {
        x = cross_halving(depth=overlap / 2, thickness=t, clearance=fit, rotation=180 deg,
                          cx=0, cy=arch_r)
    }
}

# tenon centres in the top's frame (seam along x through (0, 0))
m = tenon_off * cos(45 deg)

def mortise(ang, px, py) -> hole {
    s = Rectangle(center=(px, py), width=tenon + fit, height=t + fit, rotation=ang)
}

assembly side_table {
    solid top_back {
        half = Sector(center=(0, 0), radius=top_d / 2, start_angle=0 deg, end_angle=180 deg)
        dt = dovetail(part="socket", length=300 mm, depth=12 mm, tails=3, angle=10 deg,
                      clearance=fit, cx=0, cy=0)
        ma = mortise(45 deg, m, m)
        mb = mortise(135 deg, -m, m)
    }
    solid top_front {
        half = Sector(center=(0, 0), radius=top_d / 2, start_angle=180 deg, end_angle=360 deg)
        band = Rectangle(center=(0, 6), width=300, height=12)
        dt = dovetail(part="tail", length=300 mm, depth=12 mm, tails=3, angle=10 deg,
                      clearance=fit, cx=0, cy=0)
        ma = mortise(45 deg, -m, -m)
        mb = mortise(135 deg, m, -m)
    }
    leg_a = leg(from_top=false)
    leg_b = leg(from_top=true)

    # flat on the sheet: halves one above the other, legs to the right
    Below(top_front, top_back, gap=10)
    AlignCenterX(top_front, top_back)
    RightOf(leg_a, top_back, gap=10)
    AlignTop(leg_a, top_back)
    RightOf(leg_b, leg_a, gap=10)
    AlignTop(leg_b, leg_a)

    # assembled: legs stand crossed at 45 deg to the seam, thickness centred on their plane
    Place(leg_a, position=(-t / 2 * sin(45 deg), t / 2 * cos(45 deg), 0),
          rotation=(90 deg, 0, 45 deg))
    Place(leg_b, position=(-t / 2 * sin(135 deg), t / 2 * cos(135 deg), 0),
          rotation=(90 deg, 0, 135 deg))
    Place(top_back, position=(0, 0, leg_h), face="up")
    Place(top_front, position=(0, 0, leg_h), face="up")

    assert top_back.half.radius * 2 == 440 mm, "the top is 440 mm round"
    assert leg_a.body.bb.height == 500 mm, "the table stands 500 mm tall"
    assert leg_a.body.bottom_width == 380 mm and leg_a.body.top_width == 300 mm,
        "legs 380 at the floor, 300 under the top"
    assert leg_a.x.depth + leg_b.x.depth == leg_h - 110 mm, "halvings meet"
    assert top_back.half.bb.height <= 400 mm and top_front.bb.height <= 400 mm,
        "each half fits the 400 mm sheet"
    assert leg_b.bb.height <= 600 mm, "a leg fits the sheet"
}
