# Request: a toddler's "car dashboard" busy board for the wall, 6 mm birch ply, four parts.
# The panel: 400 wide, sides 180 tall, the top one arc rising to 250 in the middle, bottom
# corners R15, hung on two keyholes (8 mm head, 4 mm slot 10 long) at x = -60 and 60, 228 up.
# A steering wheel 200 across (rim 20 wide, hub 50 across, three spokes 20 wide at 90, 210
# and 330 deg) turns on an M8 bolt (8.5 mm holes) at (-90, 110). A speedometer engraved
# round (100, 150): ring R55, a tick every 10 km/h from 0 at 210 deg clockwise to 120 at -30
# deg (every 20: longer and numbered), "KM/H" under the centre, and a pointer 50 long on an
# M4 bolt (4.5 mm holes) at the centre. Three 28 mm holes for 30 mm arcade buttons at
# x = 20, 65, 110, 45 up. A gear "H-gate" for an M8 carriage bolt: two upright slots 8.5
# wide at x = 150 and 180 (bolt centres from 30 to 80 up) joined at 55 up, gears 1-4 engraved
# beside it, and a knob disc 40 across that slides on the bolt.

units mm
thickness 6 mm
import "std/plates.aidl"

SPEEDO = (100 mm, 150 mm)
def dial(v) = 210 deg - v * 2 deg        # km/h to the angle on the dial

assembly dashboard {
    solid panel {
        bottom = Line((-200 mm, 0), (200 mm, 0))
        right = Line((200 mm, 0), (200 mm, 180 mm))
        top = Arc(start=(200 mm, 180 mm), through=(0, 250 mm), end=(-200 mm, 180 mm))
        left = Line((-200 mm, 180 mm), (-200 mm, 0))
        Fillet([bottom.start, bottom.end], 15 mm)

        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=-60 mm, cy=228 mm)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=60 mm, cy=228 mm)
        hole axle { c = Circle(center=(-90 mm, 110 mm), diameter=8.5 mm) }
        hole needle_pin { c = Circle(center=SPEEDO, diameter=4.5 mm) }
        for x in [20 mm, 65 mm, 110 mm] {
            hole button { c = Circle(center=(x, 45 mm), diameter=28 mm) }
        }
        hole gate {
            a = Slot(start=(150 mm, 30 mm), end=(150 mm, 80 mm), width=8.5 mm)
            b = Slot(start=(180 mm, 30 mm), end=(180 mm, 80 mm), width=8.5 mm)
            c = Slot(start=(150 mm, 55 mm), end=(180 mm, 55 mm), width=8.5 mm)
        }
        drawing speedo {
            ring = Circle(center=SPEEDO, radius=55 mm)
            for v in range(0, 130, 10) {
                tick = Line(polar(SPEEDO, (44 mm if v % 20 == 0 else 48 mm), dial(v)), polar(SPEEDO, 55 mm, dial(v)))
            }
            for v in range(0, 130, 20) {
                num = Text(str(v), position=polar(SPEEDO, 36 mm, dial(v)), size=5 mm, valign="middle")
            }
            unit = Text("KM/H", position=(100 mm, 128 mm), size=4 mm, valign="middle")
        }
        drawing gears {
            g1 = Text("1", position=(139 mm, 80 mm), size=5 mm, valign="middle")
            g2 = Text("2", position=(139 mm, 30 mm), size=5 mm, valign="middle")
            g3 = Text("3", position=(191 mm, 80 mm), size=5 mm, valign="middle")
            g4 = Text("4", position=(191 mm, 30 mm), size=5 mm, valign="middle")
        }
    }

    solid wheel {
        solid rim {
            outer = Circle(center=(0, 0), diameter=200 mm)
            hole inside { c = Circle(center=(0, 0), diameter=160 mm) }
        }
        hub = Circle(center=(0, 0), diameter=50 mm)
        for a in [90 deg, 210 deg, 330 deg] {
            spoke = Rectangle(center=polar((0, 0), 52.5 mm, a), width=65 mm, height=20 mm, rotation=a)
        }
        hole axle { c = Circle(center=(0, 0), diameter=8.5 mm) }
    }

    solid pointer {
        blade = Hull(Circle(center=(0, 0), radius=8 mm), Point(50 mm, 0))
        hole pin { c = Circle(center=(0, 0), diameter=4.5 mm) }
    }

    solid knob {
        disc = Circle(center=(0, 0), diameter=40 mm)
        hole bolt { c = Circle(center=(0, 0), diameter=8.5 mm) }
    }

    # flat, for cutting
    RightOf(wheel, panel, gap=10 mm)
    AlignBottom(wheel, panel)
    Above(pointer, wheel, gap=10 mm)
    AlignLeft(pointer, wheel)
    RightOf(knob, pointer, gap=10 mm)
    AlignBottom(knob, pointer)

    # assembled: the panel on the wall, its face to the front; the others lie on its face
    Place(panel, position=(0, 0, 0), face="front", up="up")
    Place(wheel, position=(-90 mm, -6 mm, 110 mm), face="front", up="up")
    Place(pointer, position=(100 mm, -6 mm, 150 mm), face="front", up="left")    # at 60 km/h
    Place(knob, position=(150 mm, -6 mm, 80 mm), face="front", up="up")          # in first gear

    assert panel.bb.width == 400 mm, "panel 400 wide"
    assert panel.top.through.y - panel.bottom.start.y == 250 mm, "250 tall in the middle"
    assert panel.right.end.y - panel.right.start.y == 180 mm, "sides 180"
    assert wheel.rim.outer.diameter == 200 mm and wheel.rim.inside.c.diameter == 160 mm, "rim 20 wide"
    assert len(wheel.spoke) == 3, "three spokes"
    assert len(panel.button) == 3 and panel.button[0].c.diameter == 28 mm, "three 28 mm button holes"
    assert len(panel.speedo.tick) == 13 and len(panel.speedo.num) == 7, "ticks 0..120 every 10, numbers every 20"
    assert distance(panel.axle.c.center, (-90 mm, 110 mm)) == 0 mm, "wheel axle at (-90, 110)"
    assert panel.gate.b.start.x - panel.gate.a.start.x == 30 mm, "gate slots 30 apart"
    assert distance(panel.axle.c.center, panel.button[0].c.center) >= 100 mm + 14 mm + 3 mm, "the wheel clears the buttons"
}
