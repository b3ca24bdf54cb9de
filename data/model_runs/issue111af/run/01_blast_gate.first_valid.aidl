# Request (workshop): a sliding blast gate for a 4-inch dust-collection line, cut from 6 mm
# plywood and stacked with M5 bolts. Four parts:
# - front and back plates, 150 x 150 mm with 6 mm corner radius, each with a 102 mm port
#   hole in the middle (a 4" hose cuff is pressed in), the front one engraved "4 IN DUST";
# - a spacer, 150 x 150 mm, with a 112 mm wide channel open at the top and ending 20 mm above
#   the bottom edge, for the gate to slide in;
# - the gate: 110 x 230 mm, 5 mm corners, a 60 x 20 mm hand slot whose centre is 20 mm below its
#   top end, engraved "PULL = OPEN" under the slot.
# All three plates share 7 M5 clearance holes (5.5 mm): at (+-65, +-65), (+-65, 0) and (0, -65)
# from the plate centre, so the bolts stay in the spacer's 19 mm side walls and bottom bar.

units mm
thickness 6 mm

param plate = 150 mm, min = 140 mm, max = 200 mm
param port_d = 102 mm, min = 60 mm, max = 110 mm
param channel_w = 112 mm, min = 70 mm, max = 120 mm
bolt_d = 5.5 mm
bolt_pts = [(-65, -65), (0, -65), (65, -65), (-65, 0), (65, 0), (-65, 65), (65, 65)]

def bolts() -> hole {
    for p in bolt_pts {
        b = Circle(center=p, diameter=bolt_d)
    }
}

def face(label="") -> solid {
    body = RoundedRectangle(center=(0, 0), width=plate, height=plate, corner_radius=6)
    hole port { c = Circle(center=(0, 0), diameter=port_d) }
    holes = bolts()
    drawing mark { t = Text(label, position=(0, -60), size=6, valign="middle") }
    Fixed(body)
    Concentric(port.c, body)
}

assembly blast_gate {
    front = face(label="4 IN DUST")
    back = face()

    solid spacer {
        body = RoundedRectangle(center=(0, 0), width=plate, height=plate, corner_radius=6)
        hole channel {
            r = Rectangle(center=(0, 10), width=channel_w, height=plate - 20 + 20, overrun=true)
        }
        holes = bolts()
        Fixed(body)
        AlignCenterX(channel, body)
        channel.r.bottom.midpoint.y == body.bb.bottom + 20
    }

    solid gate {
        body = RoundedRectangle(center=(0, 0), width=channel_w - 2, height=230, corner_radius=5)
        hole grip { s = Slot(center=(0, 95), length=60, width=20) }
        drawing note { t = Text("PULL = OPEN", position=(0, 70), size=6, valign="middle") }
        Fixed(body)
        AlignCenterX(grip, body)
        grip.s.center.y == body.bb.top - 20
        AlignCenterX(note, body)
        note.t.position.y == grip.s.center.y - 25
    }

    RightOf(spacer, front, gap=10)
    RightOf(gate, spacer, gap=10)
    RightOf(back, gate, gap=10)
    AlignBottom(spacer, front)
    AlignBottom(gate, front)
    AlignBottom(back, front)

    assert front.port.c.diameter == 102 mm, "4-inch port"
    assert front.body.width == 150 mm and front.body.height == 150 mm, "plate 150 x 150"
    assert spacer.body.bb.width == 150 mm, "spacer 150 wide"
    assert spacer.channel.r.width == 112 mm, "channel 112 wide"
    assert gate.body.width == 110 mm and gate.body.height == 230 mm, "gate 110 x 230"
    assert len(front.holes.b) == 7, "7 bolts"
    assert gate.body.bb.top - gate.grip.s.center.y == 20 mm, "slot 20 below the top"
    assert spacer.channel.r.bb.bottom - spacer.body.bb.bottom == 20 mm, "channel ends 20 above the bottom"
}
