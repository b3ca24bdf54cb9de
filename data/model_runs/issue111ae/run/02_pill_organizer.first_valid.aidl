# Request (bathroom cabinet): a weekly pill organizer in 3 mm ply. A finger-jointed open tray
# 203 x 70 x 30 mm outside, split into 7 days x 2 rows (AM at the front, PM at the back) =
# 14 equal compartments; the dividers stop 7 mm below the rim so a lid can sit on top.
# The front wall carries the day names MON ... SUN engraved 5 mm high, each centred over its
# compartment, at mid-height. A lift-off lid: a 203 x 70 plate with R4 corners and a lip plate
# glued under it that fits inside the walls with 0.3 mm clearance all round; the lid is
# engraved "AM" near its front edge and "PM" near its back edge (8 mm, bold, filled) and has a
# 20 mm finger hole in its middle.

units mm
thickness 3 mm

import "std/boxes.aidl"

param t = 3 mm, min = 3 mm, max = 4 mm
param length = 203 mm, min = 150 mm, max = 260 mm
param width = 70 mm, min = 50 mm, max = 100 mm
param height = 30 mm, min = 20 mm, max = 50 mm
clearance = 0.3 mm
days = 7
names = ["MON", "TUE", "WED", "THU", "FRI", "SAT", "SUN"]

# compartment width along the length and the centre of day c, from the tray's centre
cw = (length - 2 * t - (days - 1) * t) / days
def col_x(c) = -(length - 2 * t) / 2 + c * (cw + t) + cw / 2

assembly pill_organizer {
    tray = divider_tray(length=length, width=width, height=height, rows=2, cols=days,
                        thickness=t, clearance=clearance, divider_height=height - t - 7 mm)

    drawing day_names {
        for i in range(days) {
            d = Text(names[i], position=(col_x(i), 0), size=5, valign="middle")
        }
    }
    CutInto(day_names, tray.body.front)
    # day i's name over compartment i: the names' frame centred on the front panel
    day_names.d[0].position.x == tray.body.front.bb.center_x + col_x(0)
    day_names.d[0].position.y == tray.body.front.bb.center_y

    solid lid {
        plate = RoundedRectangle(center=(0, 0), width=length, height=width, corner_radius=4)
        hole grip { c = Circle(center=(0, 0), diameter=20) }
        Concentric(grip.c, plate)
    }
    solid lip {
        plate = Rectangle(center=(0, 0), width=length - 2 * t - 2 * clearance,
                          height=width - 2 * t - 2 * clearance)
        hole grip { c = Circle(center=(0, 0), diameter=20) }
        Concentric(grip.c, plate)
    }
    drawing lid_marks {
        am = Text("AM", position=(0, -22), size=8, font="sans:Bold", valign="middle",
                  fill=true)
        pm = Text("PM", position=(0, 22), size=8, font="sans:Bold", valign="middle",
                  fill=true)
    }
    CutInto(lid_marks, lid)
    AlignCenterX(lid_marks, lid)
    lid_marks.am.position.y == lid.plate.bb.bottom + 13
    lid_marks.pm.position.y == lid.plate.bb.top - 13

    Above(lid, tray, gap=10)
    AlignCenterX(lid, tray)
    Above(lip, lid, gap=10)
    AlignCenterX(lip, lid)

    # the request's numbers
    assert tray.rows * tray.cols == 14, "7 days x 2 rows = 14 compartments"
    assert tray.length == 203 mm and tray.width == 70 mm and tray.height == 30 mm,
        "tray 203 x 70 x 30 outside"
    assert tray.height - t - tray.divider_height == 7 mm, "dividers 7 mm below the rim"
    assert len(day_names.d) == 7, "seven day names"
    assert lid.plate.bb.width == 203 mm and lid.plate.bb.height == 70 mm, "lid 203 x 70"
    assert lip.plate.bb.width == 203 mm - 6 mm - 0.6 mm, "lip 0.3 mm clear of 3 mm walls"
    assert day_names.bb.width < tray.body.front.bb.width - 8 mm, "names fit on the front"
}
