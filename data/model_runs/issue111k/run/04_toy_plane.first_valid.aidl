# Toy glider kit, 3 mm plywood, three parts. Fuselage: a 170 x 30 mm body with 12 mm rounded
# corners, the nose at the right; a tail fin at the left end: a quadrilateral rising to 50 mm
# above the body's centre line, 17 mm wide at its top, 40 mm wide at the centre line. Through
# slots (mortises) for the flat pieces, 3.2 mm high, on the centre line: the wing slot 40.4 mm
# long centred 25 mm right of the body's centre, the tailplane slot 25.4 mm long centred 70 mm
# left of it. Three 6 mm round windows 8 mm above the centre line, at 10, 25 and 40 mm right of
# centre. Wing: 160 x 40 mm, 8 mm rounded corners. Tailplane: 70 x 25 mm, 5 mm rounded corners.
# Laid out with the wing 10 mm below the fuselage and the tailplane 10 mm right of the wing.

thickness 3 mm

assembly glider {
    solid fuselage {
        body = RoundedRectangle(center=(0, 0), width=170, height=30, corner_radius=12)
        fin = Polygon([(-85, 0), (-85, 50), (-68, 50), (-45, 0)])
        hole wing_slot {
            s = Rectangle(center=(25, 0), width=40.4, height=3.2)
        }
        hole tail_slot {
            s = Rectangle(center=(-70, 0), width=25.4, height=3.2)
        }
        hole windows {
            for i in range(3) {
                w = Circle(center=(10 + 15 * i, 8), diameter=6)
            }
        }
    }

    solid wing {
        plate = RoundedRectangle(center=(0, -60), width=160, height=40, corner_radius=8)
    }

    solid tailplane {
        plate = RoundedRectangle(center=(110, -60), width=70, height=25, corner_radius=5)
    }

    Below(wing, fuselage, gap=10)
    AlignLeft(wing, fuselage)
    RightOf(tailplane, wing, gap=10)
    AlignCenterY(tailplane, wing)

    assert fuselage.body.width == 170 mm and fuselage.body.height == 30 mm, "body 170 x 30"
    assert fuselage.bb.top - fuselage.body.center.y == 50 mm, "fin 50 mm above the centre line"
    assert fuselage.wing_slot.s.width == 40.4 mm and fuselage.wing_slot.s.height == 3.2 mm, "wing slot"
    assert fuselage.wing_slot.s.center.x - fuselage.body.center.x == 25 mm, "wing slot 25 mm right"
    assert fuselage.wing_slot.s.center.y == fuselage.body.center.y, "slots on the centre line"
    assert fuselage.tail_slot.s.width == 25.4 mm, "tailplane slot 25.4"
    assert fuselage.body.center.x - fuselage.tail_slot.s.center.x == 70 mm, "tail slot 70 mm left"
    assert len(fuselage.windows.w) == 3, "three windows"
    assert fuselage.windows.w[0].diameter == 6 mm, "6 mm windows"
    assert fuselage.windows.w[2].center.x - fuselage.body.center.x == 40 mm, "last window 40 mm right"
    assert fuselage.windows.w[1].center.y - fuselage.body.center.y == 8 mm, "windows 8 mm up"
    assert wing.plate.width == 160 mm and wing.plate.height == 40 mm, "wing 160 x 40"
    assert tailplane.plate.width == 70 mm and tailplane.plate.height == 25 mm, "tailplane 70 x 25"
    assert fuselage.wing_slot.s.width - wing.plate.height == 0.4 mm, "wing slides in with 0.4 mm"
    assert fuselage.bb.bottom - wing.bb.top == 10 mm, "wing 10 mm below"
    assert tailplane.bb.left - wing.bb.right == 10 mm, "tailplane 10 mm right of the wing"
}
