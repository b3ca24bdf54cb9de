# Request: a pinout overlay for a Raspberry Pi Pico on a breadboard, cut from 2 mm clear
# acrylic: a 48 x 62 mm plate (R3 corners) that slips over the Pico's two header rows. It has
# 2 x 20 holes of 1.1 mm for the 0.64 mm square header pins, 2.54 mm (0.1 in) pitch along each
# row, the rows 17.78 mm (0.7 in) apart; four 2.2 mm holes over the Pico's M2 mounting holes
# (11.4 mm apart across, 47 mm apart along); every pin's name engraved beside its hole on the
# outside of the row (left: pins 1-20 top to bottom, right: pins 40-21 top to bottom); a small
# filled triangle marking pin 1, "USB" at the top edge and "RASPBERRY PI PICO" along the bottom.

units mm
thickness 2 mm

pitch = 2.54 mm
row_gap = 17.78 mm
pins = 20

left_names = ["GP0", "GP1", "GND", "GP2", "GP3", "GP4", "GP5", "GND", "GP6", "GP7",
              "GP8", "GP9", "GND", "GP10", "GP11", "GP12", "GP13", "GND", "GP14", "GP15"]
right_names = ["VBUS", "VSYS", "GND", "3V3_EN", "3V3(OUT)", "ADC_VREF", "GP28", "AGND",
               "GP27", "GP26", "RUN", "GP22", "GND", "GP21", "GP20", "GP19", "GP18", "GND",
               "GP17", "GP16"]

top_y = (pins - 1) * pitch / 2

solid overlay {
    plate = RoundedRectangle(center=(0, 0), width=48, height=62, corner_radius=3)

    hole header {
        for i in range(pins) {
            l = Circle(center=(-row_gap / 2, top_y - i * pitch), diameter=1.1)
            r = Circle(center=(row_gap / 2, top_y - i * pitch), diameter=1.1)
        }
    }

    hole mounts {
        for sx in [-1, 1] {
            for sy in [-1, 1] {
                m = Circle(center=(sx * 11.4 / 2, sy * 47 / 2), diameter=2.2)
            }
        }
    }

    drawing labels {
        for i in range(pins) {
            tl = Text(left_names[i], position=(-row_gap / 2 - 1.6, top_y - i * pitch), size=1.5,
                      anchor="end", valign="middle")
            tr = Text(right_names[i], position=(row_gap / 2 + 1.6, top_y - i * pitch), size=1.5,
                      anchor="start", valign="middle")
        }
        pin1 = Triangle(center=(-row_gap / 2 - 14, top_y), base=1.6, height=1.6, rotation=-90 deg,
                        fill=true)
        usb = Text("USB", position=(0, 28), size=2.5, valign="middle")
        title = Text("RASPBERRY PI PICO", position=(0, -28.3), size=2.5, valign="middle")
    }

    assert len(header.l) == 20 and len(header.r) == 20, "20 pins a side"
    assert header.r[0].center.x - header.l[0].center.x == 17.78 mm, "rows 0.7 in apart"
    assert header.l[0].center.y - header.l[1].center.y == 2.54 mm, "0.1 in pitch"
    assert header.l[0].center.y - header.l[19].center.y == 19 * 2.54 mm, "20 pins in a row"
    assert header.l[0].diameter == 1.1 mm, "pin holes 1.1"
    assert plate.bb.width == 48 mm and plate.bb.height == 62 mm, "plate 48 x 62"
    assert mounts.m[3].center.x - mounts.m[0].center.x == 11.4 mm, "mounts 11.4 across"
    assert mounts.m[3].center.y - mounts.m[0].center.y == 47 mm, "mounts 47 along"
    assert labels.bb.left >= plate.bb.left + 1 mm and labels.bb.right <= plate.bb.right - 1 mm,
        "labels on the plate"
    assert labels.bb.bottom >= plate.bb.bottom + 1 mm and labels.bb.top <= plate.bb.top - 1 mm,
        "labels on the plate"
    assert distance(labels, header) >= 0.4 mm, "labels clear of the pin holes"
    assert distance(labels, mounts) >= 0.4 mm, "labels clear of the mounting holes"
}
