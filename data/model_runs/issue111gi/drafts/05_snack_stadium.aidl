# Request: a game-day "snack stadium" for a party table, 6 mm ply. A stadium-shaped base
# 500 x 340 mm (a full round at each end) with a football field engraved in its middle
# (240 x 110 mm, 20 mm end zones engraved filled, yard lines every 20 mm) where the dip bowl
# stands. Over it a stands tier, a stadium ring 500 x 340 outside with a 300 x 140 opening
# (both full-round ends, concentric), raised 80 mm clear above the base on four legs (40 mm
# wide, 24 x 6 mm tenons into 24.2 x 6.2 mortises of the base and the tier): two at the middle
# of the straights, two at the ends. The tier holds eight snack cups in 75 mm holes on the
# ring's midline: two on each straight 60 mm either side of the middle, two on each end 45 deg
# either side of the axis. "GAME DAY" engraved on the tier's front straight, outside the cups.

thickness 6 mm

param clear_h = 80 mm

# the cups: centres on the ring's midline (a 400 x 240 stadium: end arcs r 120 about x = +-80)
cups = [(-60, 120), (60, 120), (-60, -120), (60, -120),
        (80 + 120 * cos(45 deg), 120 * sin(45 deg)), (80 + 120 * cos(45 deg), -120 * sin(45 deg)),
        (-80 - 120 * cos(45 deg), 120 * sin(45 deg)), (-80 - 120 * cos(45 deg), -120 * sin(45 deg))]

def leg() -> solid {
    body = Rectangle(bottom_left=(-20, 0), width=40, height=80)
    foot = Rectangle(bottom_left=(-12, -6), width=24, height=6)
    top = Rectangle(bottom_left=(-12, 80), width=24, height=6)
}

def leg_mortises() -> hole {
    s_back = Rectangle(center=(0, 120), width=6.2, height=24.2)
    s_front = Rectangle(center=(0, -120), width=6.2, height=24.2)
    e_right = Rectangle(center=(200, 0), width=24.2, height=6.2)
    e_left = Rectangle(center=(-200, 0), width=24.2, height=6.2)
}

assembly snack_stadium {
    solid base {
        body = Slot(center=(0, 0), length=500, width=340)
        mortises = leg_mortises()
        drawing field {
            pitch = Rectangle(center=(0, 0), width=240, height=110)
            end_l = Rectangle(center=(-110, 0), width=20, height=110, fill=true)
            end_r = Rectangle(center=(110, 0), width=20, height=110, fill=true)
            for i in range(9) {
                yard = Line((-80 + 20 * i, -55), (-80 + 20 * i, 55))
            }
        }
        Fixed(body)
        Fixed(mortises)
    }

    solid tier {
        body = Slot(center=(0, 0), length=500, width=340)
        hole opening { o = Slot(center=(0, 0), length=300, width=140) }
        mortises = leg_mortises()
        hole cup_holes {
            for p in cups {
                c = Circle(center=p, diameter=75)
            }
        }
        drawing words {
            t = Text("GAME DAY", position=(0, -155), size=8, valign="middle")
        }
        Fixed(body)
        Fixed(mortises)
    }

    leg_back = leg()
    leg_front = leg()
    leg_right = leg()
    leg_left = leg()

    # flat on the sheet
    RightOf(tier, base, gap=10)
    AlignTop(tier, base)
    Below(leg_back, base, gap=10)
    AlignLeft(leg_back, base)
    RightOf(leg_front, leg_back, gap=10)
    AlignTop(leg_front, leg_back)
    RightOf(leg_right, leg_front, gap=10)
    AlignTop(leg_right, leg_front)
    RightOf(leg_left, leg_right, gap=10)
    AlignTop(leg_left, leg_right)

    # in 3D: base on the table, legs in its mortises, tier on the legs
    Place(base, position=(0, 0, 0), face="up")
    Place(leg_back, position=(-3, 120, 6), face="right", up="up")
    Place(leg_front, position=(-3, -120, 6), face="right", up="up")
    Place(leg_right, position=(200, 3, 6), face="front", up="up")
    Place(leg_left, position=(-200, 3, 6), face="front", up="up")
    Place(tier, position=(0, 0, 6 + clear_h), face="up")

    assert base.body.bb.width == 500 mm and base.body.bb.height == 340 mm, "base 500 x 340"
    assert tier.opening.o.bb.width == 300 mm and tier.opening.o.bb.height == 140 mm, "opening"
    assert len(tier.cup_holes.c) == 8, "eight cups"
    assert tier.cup_holes.c[0].diameter == 75 mm, "75 mm cups"
    assert leg_back.body.bb.height == clear_h and clear_h == 80 mm, "80 clear"
    assert base.field.pitch.bb.width == 240 mm and base.field.pitch.bb.height == 110 mm, "field"
    assert len(base.field.yard) == 9, "yard lines every 20"
    # every cup hole keeps 5 mm of wood to the opening and the rim
    assert min([distance(q, (0, 0)) for q in cups]) > 0 mm, "cups listed"
}
