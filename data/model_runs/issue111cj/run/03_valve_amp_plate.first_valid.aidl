# Request: the top plate of a small 5 W single-ended valve guitar amp, 4 mm birch ply (the
# chassis sides are bought). Plate 260 x 150 mm, corners r 6, fixed to the chassis by four M4
# countersunk screws (9 mm heads) 8 mm in from both edges. A row of three noval (9-pin) socket
# holes, 22 mm, their centres 30 mm above the plate's centre line: V1 at 90 mm left of centre,
# V2 50 mm right of V1, V3 (the EL84 power valve) 60 mm right of V2; each socket has two M3
# screw holes 28 mm apart, either side of it along the row. Around V3 a ring of eight 6 mm vent
# holes on a 44 mm circle, turned 22.5 deg off the row. The output transformer sits 85 mm right
# of centre on the row: a 30 x 20 lead hole with four M4 holes on a 57 x 48 mm rectangle round
# it. A 35 mm hole for the filter-capacitor can at (80, -40) from the centre. Labels engraved
# 4 mm under each: "V1 ECC83", "V2 ECC83", "V3 EL84", "OT", "C1"; and "SPARROW 5W" engraved
# filled in 12 mm bold letters in the lower left.

units mm
thickness 4 mm
import "std/shapes.aidl"
import "std/fasteners.aidl"

row_y = 30 mm
v1_x = -90 mm
v2_x = v1_x + 50 mm
v3_x = v2_x + 60 mm
ot_x = 85 mm

def noval(x=0 mm) -> hole {
    bore = Circle(center=(x, 30 mm), diameter=22 mm)
    screw_l = Circle(center=(x - 14 mm, 30 mm), diameter=3.4 mm)
    screw_r = Circle(center=(x + 14 mm, 30 mm), diameter=3.4 mm)
}

solid plate {
    body = RoundedRectangle(center=(0, 0), width=260, height=150, corner_radius=6)
    Fixed(body)

    v1 = noval(x=v1_x)
    v2 = noval(x=v2_x)
    v3 = noval(x=v3_x)
    vents = bolt_circle(count=8, pcd=44 mm, hole_d=6 mm, start=22.5 deg, cx=v3_x, cy=row_y)

    hole ot {
        leads = Rectangle(center=(ot_x, row_y), width=30, height=20)
    }
    m4 = clearance_hole(size=4, cx=ot_x - 28.5 mm, cy=row_y - 24 mm)
    ot_screws = CornerPattern(m4, at=[(ot_x - 28.5, row_y - 24), (ot_x + 28.5, row_y - 24),
                                      (ot_x + 28.5, row_y + 24), (ot_x - 28.5, row_y + 24)])

    hole cap {
        can = Circle(center=(80, -40), diameter=35)
    }

    hole corner {
        c = Circle(center=(-122, -67), diameter=4.5)
    }
    corners = CornerPattern(corner, body, inset=8)
    Countersink(corners, diameter=9)

    drawing labels {
        l1 = Text("V1 ECC83", position=(v1_x, row_y - 15 - 4), size=4, valign="top")
        l2 = Text("V2 ECC83", position=(v2_x, row_y - 15 - 4), size=4, valign="top")
        l3 = Text("V3 EL84", position=(v3_x, row_y - 25 - 4), size=4, valign="top")
        l4 = Text("OT", position=(ot_x, row_y - 24 - 6), size=4, valign="top")
        l5 = Text("C1", position=(80, -40 - 17.5 - 4), size=4, valign="top")
    }
    drawing brand {
        name = Text("SPARROW 5W", position=(-65, -45), size=12, font="sans:Bold",
                    valign="middle", fill=true)
    }

    assert body.width == 260 mm and body.height == 150 mm
    assert v2.bore.center.x - v1.bore.center.x == 50 mm
    assert v3.bore.center.x - v2.bore.center.x == 60 mm
    assert v1.bore.center.x - body.center.x == -90 mm
    assert v1.bore.center.y - body.center.y == 30 mm
    assert v1.screw_r.center.x - v1.screw_l.center.x == 28 mm
    assert len(vents.bolt) == 8 and vents.pcd == 44 mm
    assert ot.leads.center.x - body.center.x == 85 mm
    assert ot_screws[2].c.center.x - ot_screws[0].c.center.x == 57 mm
    assert ot_screws[2].c.center.y - ot_screws[0].c.center.y == 48 mm
    assert corners[0].c.center.x - body.bb.left == 8 mm
    assert corners[2].c.center.y - body.bb.top == -8 mm
    assert cap.can.diameter == 35 mm
}
