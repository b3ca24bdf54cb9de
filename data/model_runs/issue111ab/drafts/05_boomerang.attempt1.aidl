# Request (sport): an indoor three-blade boomerang, 3 mm birch ply, right-handed (turns
# counter-clockwise seen from the top). A hub disc 60 mm across; three curved blades 30 mm
# wide with round tips (R15), 120 deg apart; each blade follows an arc of radius 150 mm
# that starts at the hub's centre and sweeps 45 deg, curving back against the turn. Tip
# centres about 115 mm from the centre. Inside corners between blades and hub rounded R8.
# Engraved: "UP" (10 mm) on the hub, and along each blade's leading (outer) edge a line 5 mm
# in, from the hub to 15 mm short of the tip, to mark where to sand the bevel.

units mm
thickness 3 mm
kerf 0.15 mm

blade_r = 150 mm
blade_w = 30 mm
sweep = 45 deg

solid boomerang {
    hub = Circle(center=(0, 0), diameter=60)
    solid blade {
        b = ArcSlot(center=(0, -blade_r), radius=blade_r, start_angle=90 deg - sweep,
                    end_angle=90 deg, width=blade_w)
    }
    blades = CircularPattern(blade, 3, hub.center)

    drawing lead {
        a = Arc(center=(0, -blade_r), radius=blade_r + blade_w / 2 - 5 mm,
                start_angle=90 deg - sweep + 8 deg, end_angle=90 deg - 12 deg)
    }
    leads = CircularPattern(lead, 3, hub.center)

    drawing mark {
        t = Text("UP", position=(0, 0), size=10, valign="middle")
    }

    Fillet([hub, blade.b], 8)

    assert len(blades) == 3, "three blades"
    assert abs(distance(blade.b.start, hub.center) - 115 mm) < 2 mm, "tips about 115 out"
    assert abs(blade.b.width - 30 mm) < 0.01, "blades 30 wide"
    assert abs(hub.diameter - 60 mm) < 0.01, "hub 60"
}
