# Request: a control plate for a T-style electric guitar I am building, 3 mm black acrylic: a
# 150 x 35 mm plate with fully rounded ends. On its centre line: a 20 x 4 mm slot for the
# 3-way blade switch centred 40 mm left of the plate's middle, with the switch's two 2.5 mm
# screw holes 38 mm apart centred on it; two 9.5 mm holes for the volume and tone pots, the
# volume pot 5 mm right of the middle and the tone pot 38 mm further; two 3.2 mm mounting holes
# 8 mm in from the ends, countersunk 6.5 mm for the plate's oval-head screws. Engraved: a
# pinstripe 2.5 mm inside the edge, and "N", "M", "B" (3 mm) above the slot's ends and middle
# for the switch positions.

units mm
thickness 3 mm

L = 150 mm
WID = 35 mm
SWITCH_X = -40 mm
VOL_X = 5 mm
POT_PITCH = 38 mm

solid plate {
    body = Slot(center=(0, 0), length=L, width=WID)
    Fixed(body)

    hole switch {
        blade = Slot(center=(SWITCH_X, 0), length=20, width=4)
    }
    hole switch_screws {
        a = Circle(center=(SWITCH_X - 19, 0), diameter=2.5)
        b = Circle(center=(SWITCH_X + 19, 0), diameter=2.5)
    }
    hole pots {
        vol = Circle(center=(VOL_X, 0), diameter=9.5)
        tone = Circle(center=(VOL_X + POT_PITCH, 0), diameter=9.5)
    }
    hole mount {
        a = Circle(center=(-L / 2 + 8, 0), diameter=3.2)
        b = Circle(center=(L / 2 - 8, 0), diameter=3.2)
    }
    Countersink(mount, diameter=6.5 mm)

    drawing marks {
        edge = Slot(center=(0, 0), length=L, width=WID, construction=true)
        stripe = Inset(edge, 2.5)
        n = Text("N", position=(SWITCH_X - 8, 6), size=3)
        m = Text("M", position=(SWITCH_X, 6), size=3)
        b = Text("B", position=(SWITCH_X + 8, 6), size=3)
    }

    assert body.length == 150 mm and body.width == 35 mm, "plate 150 x 35"
    assert body.center.x - switch.blade.center.x == 40 mm, "switch 40 mm left of the middle"
    assert switch.blade.length == 20 mm and switch.blade.width == 4 mm, "switch slot 20 x 4"
    assert switch_screws.b.center.x - switch_screws.a.center.x == 38 mm, "switch screws 38 apart"
    assert pots.vol.center.x - body.center.x == 5 mm, "volume 5 mm right of the middle"
    assert pots.tone.center.x - pots.vol.center.x == 38 mm, "tone 38 mm further"
    assert pots.vol.diameter == 9.5 mm, "9.5 mm pot holes"
    assert mount.a.center.x - body.bb.left == 8 mm and body.bb.right - mount.b.center.x == 8 mm,
        "mounting holes 8 mm in from the ends"
    # the switch screw must clear the mounting hole's countersink
    assert switch_screws.a.left.x - (mount.a.center.x + 6.5 mm / 2) >= 2 mm, "screws apart"
    # the tone knob (about 24 mm across) must clear the mounting screw's head
    assert mount.b.center.x - pots.tone.center.x >= 12 mm + 3.25 mm, "knob clears the screw"
}
