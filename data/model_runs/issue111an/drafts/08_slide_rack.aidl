# Request (science): a microscope-slide drying rack, 3 mm ply, for 10 slides
# (75 x 25 x 1 mm). Two combs 100 long x 30 tall, each with ten 1.4 mm wide x 12 mm
# deep slots down from the top edge, 8 mm pitch, the row centred; each comb glued by
# two 10 mm tabs into a 110 x 70 base, the combs 50 mm apart (inside faces), so a
# slide spans them; "SLIDES" engraved 6 mm tall on the base between them.
import "std/joints.aidl"
thickness 3 mm
kerf 0.15 mm

def comb() -> solid {
    body = Rectangle(center=(0, 15), width=100, height=30)
    hole slots {
        for i in range(10) {
            s = Rectangle(center=(-36 + i * 8, 25), width=1.4, height=12, overrun=false)
        }
    }
    t = tab_and_slot(part="tab", length=100 mm, thickness=3 mm, tabs=2, screw=0,
                     rotation=180 deg, cx=0 mm, cy=0 mm)
}

assembly rack {
    front = comb()
    back = comb()
    solid base {
        body = Rectangle(center=(0, -80), width=110, height=70)
        m1 = tab_and_slot(part="slot", length=100 mm, thickness=3 mm, tabs=2, screw=0,
                          cx=0 mm, cy=-80 mm - 26.5 mm)
        m2 = tab_and_slot(part="slot", length=100 mm, thickness=3 mm, tabs=2, screw=0,
                          cx=0 mm, cy=-80 mm + 26.5 mm)
        drawing word { t = Text("SLIDES", position=(0, -80), size=6, valign="middle") }
    }
    Above(back, front, gap=6)
    AlignCenterX(back, front)
    assert base.m2.cy - base.m1.cy == 50 mm + 3 mm, "combs 50 apart inside"
    assert len(front.slots.s) == 10, "ten slides"
}
