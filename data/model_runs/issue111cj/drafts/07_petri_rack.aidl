# Request: a bench rack that stores ten 90 mm petri dishes (15 mm tall) stood on edge, 3 mm
# clear acrylic, glued. A base 240 x 90 mm. Two combs (front and back) standing 40 mm above
# the base, their centre planes 60 mm apart, each with ten slots 16 mm wide and 30 mm deep
# from the top at a 22 mm pitch, centred along the comb. Two end walls 90 mm wide and 40 mm
# tall, 113 mm either side of the centre, cross-halved onto the combs. Combs and end walls are
# tabbed into mortises in the base. The slots' numbers 1-10 engraved 4 mm tall on the front
# comb's outside, centred under each slot; "PETRI 90" engraved on the outside of the right end.

units mm
thickness 3 mm
import "std/joints.aidl"

t = 3 mm
L = 240 mm          # base and comb length
D = 90 mm           # base depth and end wall width
H = 40 mm           # comb and end wall height above the base
comb_y = 30 mm      # each comb's centre plane from the middle
end_x = 113 mm      # each end wall's centre plane from the middle
pitch = 22 mm
n = 10

def comb(numbered=false) -> solid {
    # x along the rack, y up from the base's top face; the tabs run down through the base
    body = Rectangle(bottom_left=(-L / 2, -t), width=L, height=H + t)
    feet = tab_and_slot(part="tab", length=L, thickness=t, tabs=3, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0, cy=-t)
    for i in range(n) {
        hole bay {
            r = Rectangle(center=((i - (n - 1) / 2) * pitch, H - 14), width=16, height=32)
        }
    }
    left_halving = cross_halving(depth=H / 2 + t, thickness=t, rotation=180 deg, cx=-end_x,
                                 cy=-t)
    right_halving = cross_halving(depth=H / 2 + t, thickness=t, rotation=180 deg, cx=end_x,
                                  cy=-t)
    if numbered {
        drawing numbers {
            for i in range(n) {
                k = Text(str(i + 1), position=((i - (n - 1) / 2) * pitch, 5), size=4,
                         valign="middle")
            }
        }
    }
}

def end_wall(label="") -> solid {
    # x across the rack (front at -x), y up from the base's top face
    body = Rectangle(bottom_left=(-D / 2, -t), width=D, height=H + t)
    foot = tab_and_slot(part="tab", length=D, thickness=t, tabs=1, tab=30 mm, screw=0,
                        rotation=180 deg, cx=0, cy=-t)
    front_halving = cross_halving(depth=H / 2, thickness=t, cx=-comb_y, cy=H)
    back_halving = cross_halving(depth=H / 2, thickness=t, cx=comb_y, cy=H)
    if label != "" {
        drawing name {
            word = Text(label, position=(0, 10), size=6, valign="middle")
        }
    }
}

assembly petri_rack {
    solid base {
        board = Rectangle(center=(0, 0), width=L, height=D)
        front_slots = tab_and_slot(part="slot", length=L, thickness=t, tabs=3, tab=20 mm,
                                   screw=0, cx=0, cy=-comb_y)
        back_slots = tab_and_slot(part="slot", length=L, thickness=t, tabs=3, tab=20 mm,
                                  screw=0, cx=0, cy=comb_y)
        left_slot = tab_and_slot(part="slot", length=D, thickness=t, tabs=1, tab=30 mm,
                                 screw=0, rotation=90 deg, cx=-end_x, cy=0)
        right_slot = tab_and_slot(part="slot", length=D, thickness=t, tabs=1, tab=30 mm,
                                  screw=0, rotation=90 deg, cx=end_x, cy=0)
    }
    front = comb(numbered=true)
    back = comb()
    left_end = end_wall()
    right_end = end_wall(label="PETRI 90")

    # flat on the sheet
    Above(front, base, gap=10)
    AlignLeft(front, base)
    Above(back, front, gap=10)
    AlignLeft(back, front)
    RightOf(left_end, base, gap=10)
    AlignBottom(left_end, base)
    Above(right_end, left_end, gap=10)
    AlignLeft(right_end, left_end)

    # in 3D: x along the rack, y from front (-) to back, z up; the base's top at z = 3
    Place(base, position=(0, 0, 0))
    Place(front, rotation=(90 deg, 0, 0), position=(0, -comb_y + t / 2, t))
    Place(back, rotation=(90 deg, 0, 0), position=(0, comb_y + t / 2, t))
    Place(left_end, rotation=(90 deg, 0, 90 deg), position=(-end_x - t / 2, 0, t))
    Place(right_end, rotation=(90 deg, 0, 90 deg), position=(end_x - t / 2, 0, t))

    assert base.board.width == 240 mm and base.board.height == 90 mm
    assert len(front.bay) == 10
    assert front.bay[1].r.center.x - front.bay[0].r.center.x == 22 mm
    assert front.bay[0].r.width == 16 mm
    assert front.body.bb.top - front.bay[0].r.bb.bottom == 30 mm, "slots 30 deep"
    assert abs(front.bay[0].r.center.x + front.bay[9].r.center.x) < 0.001 mm, "centred"
    assert front.body.bb.top - front.feet.bb.top == 40 mm, "40 mm above the base"
    assert base.back_slots.slot[0].bb.center_y - base.front_slots.slot[0].bb.center_y == 60 mm
    assert base.right_slot.slot[0].bb.center_x - base.board.center.x == 113 mm
    assert left_end.body.width == 90 mm
    assert len(front.numbers.k) == 10
}
