# Request (sport): a windmill obstacle for a garden mini-golf course, 3 mm plywood (for the
# test build; 6 mm later), 4 parts. Tower: a trapezoid 120 mm wide at the ground, 70 mm at the
# top, 130 mm tall, under a triangular roof 90 mm wide and 40 mm tall; a tunnel for the 42.7 mm
# golf ball centred at the bottom, 50 mm wide, straight sides 30 mm tall under a semicircular
# top (55 mm to its crown); a 6.2 mm axle hole on the centre line 100 mm above the ground; two
# 15 mm deep cross-halving slots up from the bottom edge, 45 mm either side of the centre, for
# the feet; "HOLE 7" engraved on the roof as filled bold letters, 7 mm tall (at most 40 mm
# wide), 8 mm above the roof's base. Rotor: a 30 mm hub with a 6.4 mm bore (spins free on a
# 6 mm dowel) and four blades, each a trapezoid 14 mm wide at the hub and 30 mm at its tip,
# running from 10 to 90 mm from the centre, so the tips sweep to 10 mm above the ground and
# block the ball now and then. Two feet, each 100 x 30 mm with 5 mm radii on the top corners, a
# 15 mm cross-halving slot down from the middle of the top edge and "PAR 2" engraved (5 mm,
# single stroke) 25 mm left of the middle. Parts laid flat, 6 mm apart.

import "std/joints.aidl"

thickness 3 mm
t = 3 mm

param axle_h = 100 mm, min = 90 mm, max = 110 mm
param blade_len = 90 mm, min = 70 mm, max = 95 mm

def foot() -> solid {
    bar = RoundedRectangle(center=(0, 15), width=100, height=30, corner_radii=[5, 5, 0, 0])
    slot = cross_halving(depth=15 mm, thickness=t, cx=0 mm, cy=30 mm)
    drawing par {
        label = Text("PAR 2", (-25, 12), size=5, valign="middle")
    }
}

assembly windmill {
    solid tower {
        wall = Trapezoid(center=(0, 65), bottom_width=120, top_width=70, height=130)
        roof = Triangle(center=(0, 150), base=90, height=40)
        hole tunnel {
            mouth = Rectangle(center=(0, 14), width=50, height=32, overrun=true)
            arch = Circle(center=(0, 30), radius=25)
        }
        hole axle {
            c = Circle(center=(0, axle_h), diameter=6.2)
        }
        left_slot = cross_halving(depth=15 mm, thickness=t, rotation=180 deg, cx=-45 mm, cy=0 mm)
        right_slot = cross_halving(depth=15 mm, thickness=t, rotation=180 deg, cx=45 mm, cy=0 mm)
        drawing sign {
            name = Text("HOLE 7", (0, 138), size=7, font="sans:Bold", fill=true, max_width=40 mm)
        }
        Fixed(wall)
    }
    solid rotor {
        hub = Circle(center=(0, 0), diameter=30)
        blade = Trapezoid(center=(10 + (blade_len - 10) / 2, 0), bottom_width=14, top_width=30,
                          height=blade_len - 10, rotation=-90 deg)
        blades = CircularPattern(blade, 4, hub.center)
        hole bore {
            c = Circle(center=(0, 0), diameter=6.4)
        }
    }
    front_foot = foot()
    back_foot = foot()

    RightOf(rotor, tower, gap=6)
    AlignTop(rotor, tower)
    Below(front_foot, tower, gap=6)
    AlignLeft(front_foot, tower)
    RightOf(back_foot, front_foot, gap=6)
    AlignTop(back_foot, front_foot)

    # the request's numbers
    assert abs(tower.wall.bottom_width - 120 mm) < 0.01 mm and abs(tower.wall.top_width - 70 mm) < 0.01 mm and abs(tower.wall.height - 130 mm) < 0.01 mm, "tower 120 / 70 x 130"
    assert abs(tower.roof.bb.bottom - tower.wall.bb.top) < 0.01 mm and abs(tower.roof.height - 40 mm) < 0.01 mm and abs(tower.roof.base - 90 mm) < 0.01 mm, "roof 90 x 40 on the wall"
    assert abs(tower.tunnel.bb.width - 50 mm) < 0.01 mm, "tunnel 50 wide"
    assert abs(tower.tunnel.arch.top.y - tower.wall.bb.bottom - 55 mm) < 0.01 mm, "tunnel crown 55 up"
    assert tower.tunnel.bb.width > 42.7 mm + 5 mm and tower.tunnel.arch.top.y - tower.wall.bb.bottom > 42.7 mm + 5 mm, "the ball passes"
    assert abs(tower.axle.c.center.y - tower.wall.bb.bottom - 100 mm) < 0.01 mm, "axle 100 up"
    assert abs(tower.right_slot.cut.bb.center_x - tower.left_slot.cut.bb.center_x - 90 mm) < 0.01 mm, "feet 45 either side"
    assert abs(tower.left_slot.cut.bb.height + front_foot.slot.cut.bb.height - front_foot.bar.height) < 0.01 mm, "halvings add up to the foot's height"
    assert tower.left_slot.cut.bb.right < tower.tunnel.bb.left - 10 mm, "slots clear of the tunnel"
    assert len(rotor.blades) == 4, "four blades"
    assert abs(axle_h - blade_len - 10 mm) < 0.01 mm, "tips 10 mm above the ground"
    assert axle_h - blade_len < 42.7 mm, "the blades can block the ball"
    assert abs(rotor.hub.diameter - 30 mm) < 0.01 mm and abs(rotor.bore.c.diameter - 6.4 mm) < 0.01 mm, "hub 30, bore 6.4"
    assert tower.sign.bb.bottom > tower.roof.bb.bottom + 5 mm and tower.sign.bb.top < tower.roof.bb.top - 10 mm, "HOLE 7 on the roof"
    assert abs(front_foot.bar.width - 100 mm) < 0.01 mm and abs(front_foot.bar.height - 30 mm) < 0.01 mm, "feet 100 x 30"
}
