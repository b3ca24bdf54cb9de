# Request (electronics): a light gate to time a dynamics trolley on the school track, in
# 3 mm ply. A 120 x 60 mm base with two M4 slots (4.5 x 14 mm, at x = +-45 mm) to bolt it
# to the track. Two uprights, 60 mm wide and standing 100 mm above the base, glued into
# the base with two 15 mm tabs each, with 50 mm clear between them for the 40 mm trolley.
# Each upright has a 5.1 mm hole for a 5 mm LED 40 mm above the base (the IR emitter in
# one, the phototransistor in the other: the two holes must line up) and a 6 mm hole for
# the wires 12 mm above the base, 20 mm off centre. Engraved: "IR LED" on one upright and
# "SENSOR" on the other, 5 mm high, above the LED hole; on the base, between the uprights,
# an arrow along the direction of travel.

units mm
thickness 3 mm

import "std/joints.aidl"

t = 3 mm
gap = 50 mm
rise = 100 mm        # above the base's top face
led_h = 40 mm
wire_h = 12 mm

def upright(label="IR LED") -> solid {
    body = Rectangle(bottom_left=(-30, 0), width=60, height=rise + t)
    j = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                     rotation=180 deg, cx=0 mm, cy=0 mm)
    hole led {
        c = Circle(center=(0, t + led_h), diameter=5.1)
    }
    hole wire {
        c = Circle(center=(20, t + wire_h), diameter=6)
    }
    drawing name {
        w = Text(label, (0, t + led_h + 12), size=5)
    }
}

assembly light_gate {
    solid base {
        body = Rectangle(center=(0, 0), width=120, height=60)
        sa = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                          rotation=90 deg, cx=-(gap / 2 + t / 2), cy=0 mm)
        sb = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                          rotation=90 deg, cx=gap / 2 + t / 2, cy=0 mm)
        hole mount {
            l = Slot(center=(-45, 0), length=14, width=4.5, rotation=90)
            r = Slot(center=(45, 0), length=14, width=4.5, rotation=90)
        }
        drawing arrow {
            shaft = Line((0, -20), (0, 14))
            head = Polygon([(0, 22), (-4, 14), (4, 14)], fill=true)
        }
        Fixed(body)
    }

    emitter = upright(label="IR LED")
    sensor = upright(label="SENSOR")
    RightOf(emitter, base, gap=10)
    AlignBottom(emitter, base)
    RightOf(sensor, emitter, gap=10)
    AlignBottom(sensor, emitter)

    # standing in the base's slots, top faces (the engraving) outward
    Place(emitter, on=base, position=(-gap / 2, 0, 0), face="left", up="up")
    Place(sensor, on=base, position=(gap / 2, 0, 0), face="right", up="up")

    # the request's numbers
    assert base.body.width == 120 mm and base.body.height == 60 mm, "base 120 x 60"
    assert base.sb.slot[0].bb.left - base.sa.slot[0].bb.right == 50 mm, "50 mm clear between the uprights"
    assert emitter.body.height - t == 100 mm, "uprights stand 100 mm above the base"
    assert emitter.led.c.center.y - (emitter.body.bb.bottom + t) == 40 mm, "LED 40 mm above the base"
    assert sensor.led.c.center.y - (sensor.body.bb.bottom + t) == 40 mm, "LED 40 mm above the base"
    assert emitter.wire.c.center.y - (emitter.body.bb.bottom + t) == 12 mm, "wire hole 12 mm above the base"
    assert len(emitter.j.gap) == 3 and len(base.sa.slot) == 2, "two tabs in two slots"
    assert distance(emitter.name, emitter.led) >= 2 mm, "label clear of the LED hole"
    assert distance(base.arrow, base.sa) >= 2 mm and distance(base.arrow, base.sb) >= 2 mm, "arrow between the uprights"
}
