# Request: a desk stand for a 24-LED WS2812 ("NeoPixel") ring (PCB 65.6 mm across), made a
# 24-hour clock face, cut from 3 mm ply. Three 110 mm discs stacked: a front with 24
# round windows 5 mm across on a 59 mm circle (the LEDs' circle, one at the top) and the
# hours 0, 3, 6 ... 21 engraved upright (5 mm) on a 90 mm circle, 0 at the top, clockwise;
# a spacer whose 67 mm pocket holds the ring; a back with a 12 x 6 mm wire slot 29 mm
# below the centre (behind the ring's pads). Four M3 holes (3.4 mm) on a 98 mm circle,
# 22.5 deg off the hour marks, bolt the stack. Each disc has a 40 mm wide tab that reaches
# 3 mm below the disc into a 3 mm foot 130 x 50 mm (R5) through a 40.2 x 9.2 mm slot (the
# three tabs, 0.2 mm clearance), the slot in the middle of the foot.

units mm
thickness 3 mm
import "std/shapes.aidl"

def layer() -> solid {
    disc = Circle(center=(0, 0), diameter=110)
    tab = Rectangle(center=(0, -50), width=40, height=16)
    m3 = bolt_circle(count=4, pcd=98, hole_d=3.4, start=22.5 deg)
    Concentric(m3.pitch, disc)
    Rigid(self)
}

assembly clock {
    front = layer()
    spacer = layer()
    back = layer()

    solid foot {
        body = RoundedRectangle(center=(0, 0), width=130, height=50, corner_radius=5)
        hole slot {
            r = Rectangle(center=(0, 0), width=40.2, height=9.2)
        }
        CenterInside(slot, body)
        Rigid(self)
    }

    hole windows {
        w = Circle(center=(0, 29.5), diameter=5)
        leds = CircularPattern(w, 24, (0, 0))
    }
    CutInto(windows, front)
    CenterInside(windows, front.disc)

    drawing hours {
        for i in range(8) {
            t = Text(str(3 * i), position=polar((0, 0), 45, 90 deg - i * 45 deg), size=5,
                     valign="middle")
        }
    }
    CutInto(hours, front)
    Rigid(hours, front)

    hole pocket {
        c = Circle(center=(0, 0), diameter=67)
    }
    CutInto(pocket, spacer)
    CenterInside(pocket, spacer.disc)

    hole wire {
        s = Slot(center=(0, -29), length=12, width=6)
    }
    CutInto(wire, back)
    At(wire.s.center, back.disc.center, dy=-29)

    # flat on the sheet
    RightOf(spacer, front, gap=5)
    AlignTop(spacer, front)
    RightOf(back, spacer, gap=5)
    AlignTop(back, spacer)
    Below(foot, front, gap=5)
    AlignLeft(foot, front)

    # assembled: the foot flat, the stack standing in its slot, faces to the front
    Place(foot, position=(0, 0, 0), rotation=(0, 0, 0))
    Place(front, position=(0, -1.5, 58), face="front", up="up")
    Place(spacer, position=(0, 1.5, 58), face="front", up="up")
    Place(back, position=(0, 4.5, 58), face="front", up="up")

    # the request's numbers
    assert front.disc.diameter == 110 mm, "110 mm discs"
    assert len(windows.leds) == 24, "24 LED windows"
    assert windows.w.diameter == 5 mm, "5 mm windows"
    assert norm(windows.w.center - front.disc.center) == 29.5 mm, "windows on a 59 mm circle"
    assert windows.w.center.y > front.disc.center.y and windows.w.center.x == front.disc.center.x, "one window at the top"
    assert len(hours.t) == 8, "hours 0, 3, ... 21"
    assert front.m3.bolt[0].diameter == 3.4 mm and front.m3.pcd == 98 mm, "M3 on 98 mm"
    assert pocket.c.diameter == 67 mm, "67 mm pocket"
    assert back.disc.center.y - wire.s.center.y == 29 mm, "wire slot 29 below centre"
    assert wire.s.length == 12 mm and wire.s.width == 6 mm, "wire slot 12 x 6"
    assert front.tab.bb.width == 40 mm, "40 mm tab"
    assert front.disc.bb.bottom - front.tab.bb.bottom == 3 mm, "tab 3 mm below the disc"
    assert foot.body.bb.width == 130 mm and foot.body.bb.height == 50 mm, "foot 130 x 50"
    assert foot.slot.r.bb.width == 40.2 mm and foot.slot.r.bb.height == 9.2 mm, "slot for three tabs"
    assert distance(hours, front.m3) >= 2 mm, "hours clear of the bolts"
    assert distance(hours, windows) >= 2 mm, "hours clear of the windows"
}
