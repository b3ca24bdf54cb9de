# Request (pets): a stand for a 20 litre nano aquarium (tank footprint 400 x 250 mm) in
# 9 mm birch ply, glued together with tabs in mortises, no screws. A top 420 x 270 mm,
# 300 mm above the floor; two sides 250 mm deep standing under the tank's two ends (the
# tank's ends bear on them), each with an arched foot cut-out 160 mm wide and 40 mm high
# and a fish-shaped window; a back panel set 11 mm in from the sides' back edge, with two
# 50 mm holes for the filter hose and the heater cable 40 mm under the top; a shelf for
# the fish food 80 mm above the floor, between the sides and stopping at the back panel.
# Two 40 mm tabs per joint (three on the back), mortises at least 10 mm from any edge.

import "std/joints.aidl"

t = 9 mm
thickness t

tank_w = 400 mm
tank_d = 250 mm
top_w = 420 mm
top_d = 270 mm
h = 300 mm            # floor to the top's upper face
side_d = 250 mm
side_x = tank_w / 2   # the sides' outer faces under the tank's ends
inner = 2 * (side_x - t)
shelf_z = 80 mm       # the shelf's underside
back_y = side_d / 2 - 11 mm - t   # the back panel's front face (world y)
side_h = h - t        # a side's body under the top

def side() -> solid {
    body = Rectangle(bottom_left=(-side_d / 2, 0), width=side_d, height=h)
    # tabs up through the top, flush with its upper face
    up = tab_and_slot(part="tab", length=side_d, thickness=t, tabs=2, tab=40 mm, screw=0,
                      cx=0 mm, cy=h)
    shelf_m = tab_and_slot(part="slot", length=back_y + side_d / 2, thickness=t, tabs=2,
                           tab=40 mm, screw=0, cx=(back_y - side_d / 2) / 2, cy=shelf_z + t / 2)
    back_m = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=3, tab=40 mm, screw=0,
                          rotation=90 deg, cx=back_y + t / 2, cy=side_h / 2)
    hole foot {
        arch = Ellipse(center=(0, 0), rx=80, ry=40)
    }
    hole fish {
        belly = Ellipse(center=(-10, 200), rx=45, ry=24)
        tail = Polygon([(28, 200), (62, 226), (62, 174)])
    }
}

assembly stand {
    solid top {
        plate = Rectangle(center=(0, 0), width=top_w, height=top_d)
        l = tab_and_slot(part="slot", length=side_d, thickness=t, tabs=2, tab=40 mm, screw=0,
                         rotation=90 deg, cx=-side_x + t / 2, cy=0 mm)
        r = tab_and_slot(part="slot", length=side_d, thickness=t, tabs=2, tab=40 mm, screw=0,
                         rotation=90 deg, cx=side_x - t / 2, cy=0 mm)
        drawing tank {
            outline = Rectangle(center=(0, 0), width=tank_w, height=tank_d)
        }
    }
    left = side()
    right = side()
    solid shelf {
        board = Rectangle(center=(0, 0), width=inner + 2 * t, height=back_y + side_d / 2)
        l = tab_and_slot(part="tab", length=back_y + side_d / 2, thickness=t, tabs=2, tab=40 mm,
                         screw=0, rotation=90 deg, cx=-inner / 2 - t, cy=0 mm)
        r = tab_and_slot(part="tab", length=back_y + side_d / 2, thickness=t, tabs=2, tab=40 mm,
                         screw=0, rotation=-90 deg, cx=inner / 2 + t, cy=0 mm)
    }
    solid back {
        panel = Rectangle(bottom_left=(-inner / 2 - t, 0), width=inner + 2 * t, height=side_h)
        l = tab_and_slot(part="tab", length=side_h, thickness=t, tabs=3, tab=40 mm, screw=0,
                         rotation=90 deg, cx=-inner / 2 - t, cy=side_h / 2)
        r = tab_and_slot(part="tab", length=side_h, thickness=t, tabs=3, tab=40 mm, screw=0,
                         rotation=-90 deg, cx=inner / 2 + t, cy=side_h / 2)
        hole hose {
            a = Circle(center=(-120, side_h - 40), diameter=50)
            b = Circle(center=(120, side_h - 40), diameter=50)
        }
    }

    # sheet layout
    RightOf(right, left, gap=6)
    AlignBottom(right, left)
    Above(top, left, gap=6)
    AlignLeft(top, left)
    RightOf(back, right, gap=6)
    AlignBottom(back, right)
    Above(shelf, back, gap=6)
    AlignLeft(shelf, back)

    # 3D: x across, y to the back, z up
    Place(top, position=(0, 0, h - t))
    Place(left, position=(-side_x, 0, 0), face="right", up="up")
    Place(right, position=(side_x - t, 0, 0), face="right", up="up")
    Place(shelf, position=(0, (back_y - side_d / 2) / 2, shelf_z))
    Place(back, position=(0, back_y + t, 0), face="front", up="up")

    assert top.plate.width == 420 mm and top.plate.height == 270 mm
    assert h == 300 mm, "300 mm high"
    assert left.body.width == 250 mm, "sides 250 deep"
    assert side_x - t < tank_w / 2 and tank_w / 2 <= side_x, "the tank's ends bear on the sides"
    assert top_w / 2 - side_x >= 10 mm, "top's mortises 10 mm from its ends"
    assert side_d / 2 - (back_y + t) == 11 mm, "back set 11 mm in"
    assert left.foot.arch.rx * 2 == 160 mm and left.foot.arch.ry == 40 mm
    assert back.hose.a.diameter == 50 mm and back.panel.bb.top - back.hose.a.center.y == 40 mm
    assert shelf_z == 80 mm
    assert len(back.l.gap) == 4 and len(shelf.l.gap) == 3, "3 tabs on the back, 2 on the shelf"
}
