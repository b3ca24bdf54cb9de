# Request (garden): a crevice bat box, 6 mm exterior ply, glued, open at the bottom.
# - a crevice 20 mm deep between back and front;
# - back 200 wide x 400 tall; its lower 100 mm hang below the front as the landing strip;
#   horizontal grip grooves engraved 10 mm apart over its inner face, 156 mm long, centred;
#   two 6 mm screw holes in the landing strip, 20 mm above its bottom edge, 88 mm either
#   side of the centre line;
# - front 200 wide x 290 tall, a 120 x 6 mm ventilation slot centred across it, 180 mm
#   above its bottom edge;
# - two sides 10 mm in from the side edges of back and front (their outer faces), 300 mm
#   tall at the back and 290 mm at the front (a sloping top); 3 tabs 40 mm wide into back
#   and front each, and a 16 mm tenon on the sloping top into the roof;
# - roof 220 wide, its back edge flush with the back's back face, overhanging the front
#   by 30 mm measured along the slope, 10 mm past the side edges;
# - joints 0.2 mm loose.

import "std/joints.aidl"

units mm
thickness 6 mm

T = 6 mm
fit = 0.2 mm
crevice = 20 mm
width = 200 mm
back_h = 400 mm
landing = 100 mm
front_h = 290 mm
side_back_h = 300 mm
side_in = 10 mm
groove_pitch = 10 mm
groove_len = 156 mm

side_x = width / 2 - side_in - T / 2          # the sides' middle planes, from the centre line
side_d = crevice + 2 * T                       # a side's depth, tabs included
drop = side_back_h - front_h                   # the roof's fall over the side's depth
edge_len = sqrt(side_d ** 2 + drop ** 2)       # the side's sloping top edge
slope = atan2(-drop, side_d)
roof_d = edge_len + 30 mm
n_grooves = floor((back_h - 10 mm) / groove_pitch)

def side_panel() -> solid {
    # x: 0 at the back's front face (tab into the back from -T), y: 0 at the bottom
    shape = Polygon([(-T, 0), (crevice + T, 0), (crevice + T, front_h), (-T, side_back_h)])
    Fixed(shape)
    to_back = tab_and_slot(part="tab", length=side_back_h, thickness=T, tabs=3, tab=40 mm,
                           screw=0, rotation=90 deg, cx=-T, cy=side_back_h / 2)
    to_front = tab_and_slot(part="tab", length=front_h, thickness=T, tabs=3, tab=40 mm,
                            screw=0, rotation=-90 deg, cx=crevice + T, cy=front_h / 2)
    to_roof = tab_and_slot(part="tab", length=edge_len, thickness=T, tabs=1, tab=16 mm,
                           screw=0, rotation=slope, cx=crevice / 2,
                           cy=(side_back_h + front_h) / 2)
}

assembly bat_box {
    solid back {
        # y: 0 at the sides' bottom (the crevice's mouth)
        body = Rectangle(center=(0, side_back_h - back_h / 2), width=width, height=back_h)
        Fixed(body)
        sl = tab_and_slot(part="slot", length=side_back_h, thickness=T, tabs=3, tab=40 mm,
                          screw=0, clearance=fit, rotation=90 deg, cx=-side_x, cy=side_back_h / 2)
        sr = tab_and_slot(part="slot", length=side_back_h, thickness=T, tabs=3, tab=40 mm,
                          screw=0, clearance=fit, rotation=90 deg, cx=side_x, cy=side_back_h / 2)
        hole screw_l {
            c = Circle(center=(-88, -landing + 20), diameter=6)
        }
        hole screw_r {
            c = Circle(center=(88, -landing + 20), diameter=6)
        }
        drawing grooves {
            for i in range(n_grooves) {
                g = Line((-groove_len / 2, -landing + 5 mm + i * groove_pitch),
                         (groove_len / 2, -landing + 5 mm + i * groove_pitch))
            }
        }
    }

    solid front {
        body = Rectangle(center=(0, front_h / 2), width=width, height=front_h)
        Fixed(body)
        sl = tab_and_slot(part="slot", length=front_h, thickness=T, tabs=3, tab=40 mm,
                          screw=0, clearance=fit, rotation=90 deg, cx=-side_x, cy=front_h / 2)
        sr = tab_and_slot(part="slot", length=front_h, thickness=T, tabs=3, tab=40 mm,
                          screw=0, clearance=fit, rotation=90 deg, cx=side_x, cy=front_h / 2)
        hole vent {
            s = Slot(center=(0, 180), length=120, width=6)
        }
    }

    left = side_panel()
    right = side_panel()

    solid roof {
        # y: the back edge on top, the slope running down the page to the front
        body = Rectangle(center=(0, 0), width=width + 20 mm, height=roof_d)
        Fixed(body)
        sl = tab_and_slot(part="slot", length=edge_len, thickness=T, tabs=1, tab=16 mm,
                          screw=0, clearance=fit, rotation=90 deg, cx=-side_x,
                          cy=roof_d / 2 - edge_len / 2)
        sr = tab_and_slot(part="slot", length=edge_len, thickness=T, tabs=1, tab=16 mm,
                          screw=0, clearance=fit, rotation=90 deg, cx=side_x,
                          cy=roof_d / 2 - edge_len / 2)
    }

    Fixed(back)
    RightOf(front, back, gap=10)
    AlignTop(front, back)
    RightOf(left, front, gap=10)
    AlignTop(left, front)
    RightOf(right, left, gap=10)
    AlignTop(right, left)
    Below(roof, front, gap=10)
    AlignLeft(roof, front)

    assert back.body.bb.width == 200 mm and back.body.bb.height == 400 mm, "back 200 x 400"
    assert front.body.bb.width == 200 mm and front.body.bb.height == 290 mm, "front 200 x 290"
    assert back_h - side_back_h == 100 mm, "100 mm landing strip below the front"
    assert left.shape.bb.height == 300 mm, "sides 300 tall at the back"
    assert side_d - 2 * T == 20 mm, "20 mm crevice"
    assert roof.body.bb.width == 220 mm, "roof 220 wide"
    assert abs(roof_d - edge_len - 30 mm) < 0.01 mm, "30 mm overhang"
    assert abs(back.grooves.g[1].start.y - back.grooves.g[0].start.y - 10 mm) < 0.01 mm, "grooves 10 apart"
    assert back.grooves.bb.top < back.body.bb.top and back.grooves.bb.bottom > back.body.bb.bottom, "grooves on the back"
    assert abs(front.vent.s.center.y - front.body.bb.bottom - 180 mm) < 0.01 mm, "vent 180 up"
    assert abs(back.screw_r.c.center.y - back.body.bb.bottom - 20 mm) < 0.01 mm, "screws 20 up"
    assert width / 2 - (side_x + T / 2) == 10 mm, "sides 10 mm in"
}
