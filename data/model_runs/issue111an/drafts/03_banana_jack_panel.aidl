# Request (electronics): front panel for a bench power supply breakout, 3 mm acrylic.
# 120 x 60 mm, corners R4; four M3 mounting holes 5 mm in from each corner; three
# pairs of 8 mm banana-jack holes (red/black), pairs 35 mm apart centre to centre,
# the two jacks of a pair 19 mm apart vertically (the standard 3/4 in spacing), the
# row centred; a 12 mm hole for a panel voltmeter switch? no: a 7 mm toggle-switch
# hole left of the jacks is not wanted. Labels "12V", "5V", "3V3" engraved 5 mm tall
# above each pair, "+" beside each upper jack and "-" beside each lower one.
import "std/fasteners.aidl"
thickness 3 mm
kerf 0.15 mm

solid panel {
    body = RoundedRectangle(center=(0, 0), width=120, height=60, corner_radius=4)
    m = clearance_hole(size=3)
    CornerPattern(m, body, inset=5 mm)
    labels = ["12V", "5V", "3V3"]
    for i in range(3) {
        hole jack {
            up = Circle(center=(-35 + i * 35, 9.5 - 4), diameter=8)
            dn = Circle(center=(-35 + i * 35, -9.5 - 4), diameter=8)
        }
        drawing lab {
            t = Text(labels[i], position=(-35 + i * 35, 14), size=5)
            p = Text("+", position=(-35 + i * 35 + 9, 5.5), size=4, valign="middle")
            n = Text("-", position=(-35 + i * 35 + 9, -13.5), size=4, valign="middle")
        }
    }
    assert len(jack) == 3, "three pairs"
    assert jack[1].up.center.x - jack[0].up.center.x == 35 mm, "pairs 35 apart"
    assert jack[0].up.center.y - jack[0].dn.center.y == 19 mm, "19 mm jack spacing"
}
