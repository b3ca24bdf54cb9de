# Request: a necklace stand as a birthday gift for my sister Anna: a bust 200 mm tall
# made of two crossed pieces (a front view 150 mm wide at the bottom with shoulders
# and a neck, and a side view 80 mm deep) cross-halved into each other, standing in an
# oval base 180 x 120 mm on tenons glued in mortises. Three 2.5 mm earring holes on
# each side of the chest, and ANNA engraved in filled bold letters 10 mm tall on the
# front of the base. 4 mm walnut ply.

import "std/joints.aidl"

units mm
thickness 4 mm

param t = 4 mm, min = 3 mm, max = 6 mm
param H = 200 mm, min = 150 mm, max = 260 mm
param fit = 0.1 mm, min = 0 mm, max = 0.3 mm       # halving clearance

tenon_w = 30 mm
front_tenon_x = 45 mm
bust_pts = [(-75, 0), (75, 0), (75, 60), (70, 95), (55, 118), (35, 128), (24, 140),
            (22, 175), (18, 194), (0, 200), (-18, 194), (-22, 175), (-24, 140),
            (-35, 128), (-55, 118), (-70, 95), (-75, 60)]
side_pts = [(-40, 0), (40, 0), (40, 60), (34, 100), (22, 128), (16, 145), (15, 175),
            (12, 194), (0, 200), (-12, 194), (-15, 175), (-16, 145), (-22, 128),
            (-34, 100), (-40, 60)]
earrings = [(40, 80), (55, 68), (62, 50), (-40, 80), (-55, 68), (-62, 50)]

assembly necklace_stand {
    solid front {
        body = Spline(bust_pts, closed=true, corners=[0, 1])
        tl = Rectangle(corner=(-front_tenon_x - tenon_w / 2, -t),
                       opposite=(-front_tenon_x + tenon_w / 2, 0.5))
        tr = Rectangle(corner=(front_tenon_x - tenon_w / 2, -t),
                       opposite=(front_tenon_x + tenon_w / 2, 0.5))
        # slot from the bottom edge up to half height (the side piece slots from the top)
        half = cross_halving(depth=H / 2, thickness=t, clearance=fit, rotation=180 deg,
                             cx=0, cy=0)
        hole ear {
            for p in earrings {
                c = Circle(center=p, diameter=2.5)
            }
        }
    }

    solid side {
        body = Spline(side_pts, closed=true, corners=[0, 1])
        tn = Rectangle(corner=(-tenon_w / 2, -t), opposite=(tenon_w / 2, 0.5))
        half = cross_halving(depth=H / 2, thickness=t, clearance=fit, cx=0, cy=H)
    }

    solid base {
        oval = Ellipse(center=(0, 0), rx=90, ry=60)
        hole mortises {
            ml = Rectangle(center=(-front_tenon_x, 0), width=tenon_w, height=t)
            mr = Rectangle(center=(front_tenon_x, 0), width=tenon_w, height=t)
            ms = Rectangle(center=(0, 0), width=t, height=tenon_w)
        }
        drawing name {
            n = Text("ANNA", position=(0, -50), size=10, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    # on the sheet
    RightOf(side, front, gap=6)
    AlignBottom(side, front)
    RightOf(base, side, gap=6)
    AlignBottom(base, side)

    # assembled: the base on the table, the front piece across it facing front (-y),
    # the side piece along y, both with their bottom edge on the base's top
    Place(base, position=(0, 0, 0))
    Place(front, position=(0, t / 2, t), face="front", up="up")
    Place(side, position=(-t / 2, 0, t), face="right", up="up")

    # the request's numbers
    assert front.body.bb.height == 200 mm and side.body.bb.height == 200 mm, "200 mm tall"
    assert front.body.points[1].x - front.body.points[0].x == 150 mm, "150 mm wide at the bottom"
    assert side.body.points[1].x - side.body.points[0].x == 80 mm, "80 mm deep"
    assert base.oval.rx * 2 == 180 mm and base.oval.ry * 2 == 120 mm, "180 x 120 base"
    assert front.half.depth + side.half.depth == 200 mm, "halvings meet"
    assert len(front.ear.c) == 6 and front.ear.c[0].diameter == 2.5 mm, "six 2.5 mm earring holes"
    assert base.name.n.size == 10 mm, "10 mm letters"
    assert base.name.bb.top < base.mortises.ms.bb.bottom - 3 mm, "name clear of the side piece"
}
