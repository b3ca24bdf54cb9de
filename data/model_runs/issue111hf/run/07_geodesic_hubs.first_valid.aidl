# Request (science): the hubs for a classroom 2V geodesic dome (a hemisphere), whose struts
# are 12 mm card strips bolted to the hubs with M4 bolts; cut from 3 mm ply.
# - every hub: a 24 mm disc at its centre and arms 14 mm wide with round ends, each with an
#   M4 clearance hole (4.5 mm) 26 mm from the hub's centre;
# - 6 five-way hubs (arms 72 degrees apart), 10 six-way hubs (60 degrees apart) and 10
#   four-way base hubs (arms at 0, 60, 120 and 180 degrees);
# - engraved 15 mm out along each arm, 4 mm tall and upright along the arm, the letter of the
#   strut it takes, counter-clockwise from the arm at 0 degrees: five-way A A A A A,
#   six-way A B B A B B, four-way B A B B; the hub's number of arms engraved 6 mm tall in
#   its centre;
# - laid out for cutting in rows 70 mm apart (hubs 70 mm apart in a row, five to a row
#   except the six five-way hubs), the four-way rows 50 mm apart, all within 600 x 400 mm.

units mm
thickness 3 mm

reach = 26 mm

def hub(n=5, step=72 deg, names=["A", "A", "A", "A", "A"], kind="5") -> solid {
    core = Circle(center=(0, 0), diameter=24)
    for i in range(n) {
        arm = Slot(start=(0, 0), end=(reach * cos(i * step), reach * sin(i * step)), width=14)
    }
    hole bolts {
        for i in range(n) {
            b = Circle(center=(reach * cos(i * step), reach * sin(i * step)), diameter=4.5)
        }
    }
    drawing letters {
        for i in range(n) {
            l = Text(names[i], position=(15 * cos(i * step), 15 * sin(i * step)), size=4,
                     valign="middle", rotation=i * step - 90 deg)
        }
        k = Text(kind, position=(0, 0), size=6, valign="middle")
    }
    assert len(arm) == n and len(names) == n, "one letter per arm"
    assert distance(bolts.b[0].center, core.center) == 26 mm, "holes 26 mm out"
    assert bolts.b[0].diameter == 4.5 mm and arm[0].width == 14 mm
    assert distance(letters, bolts) >= 1.5 mm, "letters clear the bolt holes"
}

assembly dome_hubs {
    for i in range(6) {
        five = hub(n=5, step=72 deg, names=["A", "A", "A", "A", "A"], kind="5")
        five.core.center == (i * 70 mm, 0 mm)
    }
    for i in range(10) {
        six = hub(n=6, step=60 deg, names=["A", "B", "B", "A", "B", "B"], kind="6")
        six.core.center == ((i % 5) * 70 mm, -70 mm - (i // 5) * 70 mm)
    }
    for i in range(10) {
        four = hub(n=4, step=60 deg, names=["B", "A", "B", "B"], kind="4")
        four.core.center == ((i % 5) * 70 mm, -210 mm - (i // 5) * 50 mm)
    }

    assert len(five) == 6 and len(six) == 10 and len(four) == 10, "6 + 10 + 10 hubs"
    assert self.bb.width <= 600 mm and self.bb.height <= 400 mm, "fits a 600 x 400 sheet"
}
