# Request: the rotor of a cup anemometer for our school weather station, 3 mm acrylic.
# A 60 mm hub disc with a 22 mm bore for a 608 bearing and three M3 holes (3.4 mm) on a
# 32 mm circle, at 60, 180 and 300 degrees, for a clamp ring. Three arms 10 mm wide at 0,
# 120 and 240 degrees, each ending in a 22 mm round pad 80 mm from the centre with a 3.4 mm
# hole for the screw that holds a half ping-pong-ball cup, and a 6.2 mm pocket for a 6 mm
# magnet 45 mm from the centre (three pulses a turn for the Hall sensor, and balanced).
# "WIND 3/REV" engraved round the hub, 3.5 mm letters, centred at 60 degrees.

thickness 3 mm

import "std/shapes.aidl"

hub_d = 60 mm
bore_d = 22 mm
arm_w = 10 mm
cup_r = 80 mm
magnet_r = 45 mm

solid rotor {
    hub = Circle(center=(0, 0), diameter=hub_d)
    hole bore {
        c = Circle(center=(0, 0), diameter=bore_d)
    }
    clamp = bolt_circle(count=3, pcd=32 mm, hole_d=3.4 mm, start=60 deg)
    Concentric(clamp.pitch, hub)

    solid arm {
        bar = Rectangle(bottom_left=(hub_d / 2 - 5 mm, -arm_w / 2), width=cup_r - hub_d / 2 + 5 mm,
                        height=arm_w)
        pad = Circle(center=(cup_r, 0), diameter=22 mm)
        hole screw {
            c = Circle(center=(cup_r, 0), diameter=3.4 mm)
        }
        hole magnet {
            c = Circle(center=(magnet_r, 0), diameter=6.2 mm)
        }
    }
    arms = CircularPattern(arm, 3, hub.center)

    drawing label {
        ring = Circle(center=(0, 0), radius=21 mm, construction=true)
        word = Text("WIND 3/REV", along=ring, angle=60 deg, size=3.5 mm)
    }

    # the request's numbers
    assert len(arms) == 3, "three arms"
    assert hub.diameter == 60 mm and bore.c.diameter == 22 mm, "60 mm hub, 22 mm bore"
    assert distance(arm.pad.center, hub.center) == 80 mm, "cups 80 from the centre"
    assert distance(arm.magnet.c.center, hub.center) == 45 mm, "magnet 45 from the centre"
    assert arm.magnet.c.diameter == 6.2 mm, "6.2 mm magnet pocket"
    assert clamp.pcd == 32 mm and len(clamp.bolt) == 3, "three M3 on a 32 mm circle"
    assert arm.bar.height == 10 mm, "arms 10 wide"
}
