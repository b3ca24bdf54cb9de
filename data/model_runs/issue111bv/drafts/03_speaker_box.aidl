# Request: a desk speaker for a 2-inch full-range driver and a small Bluetooth amp board: a
# finger-jointed box of 6 mm MDF, 120 wide, 100 deep and 140 tall outside, 12 mm fingers.
# Front baffle: a 50 mm cut-out for the driver's basket, its centre 90 mm up from the bottom
# and centred across; four 3.2 mm screw holes for the driver's flange on a 50 mm square
# (70.7 mm pitch circle, at 45 deg); a 25 mm bass-reflex port centred 35 mm up from the
# bottom. Back: a 10 x 4 mm USB-C slot, a 6.5 mm hole for the power toggle and a 6 mm hole
# for the 3.5 mm aux jack, in a row 30 mm apart, 30 mm up from the bottom, each labelled
# below ("USB", "ON", "AUX", 5 mm). The lid is engraved "BOOM" (filled bold, 20 mm) in its
# middle.

import "std/joints.aidl"
import "std/shapes.aidl"

thickness 6 mm

assembly speaker {
    box = finger_box(length=120 mm, depth=100 mm, height=140 mm, thickness=6 mm, finger=12 mm)

    # --- front baffle
    hole driver { c = Circle(center=(0, 0), diameter=50 mm) }
    AlignCenterX(driver, box.front)
    driver.c.center.y == box.front.bb.bottom + 90 mm
    CutInto(driver, box.front)

    screws = bolt_circle(count=4, pcd=70.7 mm, hole_d=3.2 mm, start=45 deg)
    Concentric(screws.pitch, driver.c)
    CutInto(screws, box.front)

    hole port { c = Circle(center=(0, 0), diameter=25 mm) }
    AlignCenterX(port, box.front)
    port.c.center.y == box.front.bb.bottom + 35 mm
    CutInto(port, box.front)

    # --- back panel: ports in a row, labels below
    hole ports {
        usb = Slot(center=(-30, 0), length=10 mm, width=4 mm)
        sw = Circle(center=(0, 0), diameter=6.5 mm)
        aux = Circle(center=(30, 0), diameter=6 mm)
    }
    AlignCenterX(ports.sw, box.back)
    ports.sw.center.y == box.back.bb.bottom + 30 mm
    CutInto(ports, box.back)

    drawing labels {
        l_usb = Text("USB", position=(-30, -9), size=5, valign="top")
        l_sw = Text("ON", position=(0, -9), size=5, valign="top")
        l_aux = Text("AUX", position=(30, -9), size=5, valign="top")
    }
    At(labels.l_sw.position, ports.sw.center, dy=-6 mm)
    CutInto(labels, box.back)

    # --- lid
    drawing brand {
        t = Text("BOOM", position=(0, 0), size=20, font="sans:Bold", fill=true, valign="middle")
    }
    CenterInside(brand, box.lid)
    CutInto(brand, box.lid)

    assert box.front.bb.width == 120 mm and box.front.bb.height == 140 mm, "120 x 140 front"
    assert box.left.bb.height == 100 mm, "100 deep"
    assert driver.c.center.y - box.front.bb.bottom == 90 mm, "driver centre 90 mm up"
    assert port.c.center.y - box.front.bb.bottom == 35 mm, "port centre 35 mm up"
    assert ports.aux.center.x - ports.sw.center.x == 30 mm, "jacks 30 mm apart"
    assert ports.sw.center.x - ports.usb.center.x == 30 mm, "jacks 30 mm apart"
    assert port.c.bb.top < driver.c.bb.bottom - 10 mm, "port clear of the driver"
}
