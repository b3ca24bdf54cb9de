# Request: a small Bluetooth speaker box, 3 mm plywood, finger-jointed (10 mm fingers), 160 x 70
# x 70 mm outside. Front: two 36 mm cut-outs for 40 mm full-range drivers, their centres 80 mm
# apart at mid-height, each with four 2.5 mm screw holes on a 45 mm circle at 45 deg (the
# driver frames' corners). Back: a 10 x 4 mm USB-C slot, a 12 mm hole for the push switch and a
# 7 mm hole for the volume pot, 40 mm apart in a row at mid-height. Lid: "SOUNDBOX" engraved
# filled in 12 mm bold letters in the middle.

units mm
thickness 3 mm
import "std/joints.aidl"
import "std/shapes.aidl"

DRIVER_CUT = 36 mm
DRIVER_SPACING = 80 mm

assembly speaker {
    box = finger_box(length=160 mm, depth=70 mm, height=70 mm, thickness=3 mm, finger=10 mm)

    hole drivers {
        left = Circle(center=(-DRIVER_SPACING / 2, 0), diameter=DRIVER_CUT)
        right = Circle(center=(DRIVER_SPACING / 2, 0), diameter=DRIVER_CUT)
    }
    CenterInside(drivers, box.front)
    CutInto(drivers, box.front)

    screws_l = bolt_circle(count=4, pcd=45 mm, hole_d=2.5 mm, start=45 deg)
    screws_r = bolt_circle(count=4, pcd=45 mm, hole_d=2.5 mm, start=45 deg)
    Concentric(screws_l.pitch, drivers.left)
    Concentric(screws_r.pitch, drivers.right)
    CutInto(screws_l, box.front)
    CutInto(screws_r, box.front)

    hole ports {
        usb = Slot(center=(-40, 0), length=10, width=4)
        switch = Circle(center=(0, 0), diameter=12)
        pot = Circle(center=(40, 0), diameter=7)
    }
    CenterInside(ports, box.back)
    CutInto(ports, box.back)

    drawing badge {
        word = Text("SOUNDBOX", position=(0, 0), size=12, font="sans:Bold", valign="middle",
                    fill=true)
    }
    CenterInside(badge, box.lid)
    CutInto(badge, box.lid)

    assert box.front.bb.width == 160 mm and box.front.bb.height == 70 mm, "front 160 x 70"
    assert box.left.bb.width == 70 mm and box.left.bb.height == 70 mm, "sides 70 x 70"
    assert drivers.right.center.x - drivers.left.center.x == 80 mm, "drivers 80 mm apart"
    assert drivers.left.diameter == 36 mm, "36 mm driver cut-outs"
    assert abs(drivers.left.center.y - box.front.bb.center_y) < 0.01 mm, "drivers at mid-height"
    assert screws_l.pitch.diameter == 45 mm and len(screws_l.bolt) == 4, "4 screws on 45 mm"
    assert ports.pot.center.x - ports.switch.center.x == 40 mm and
        ports.switch.center.x - ports.usb.center.x == 40 mm, "back holes 40 mm apart"
    assert ports.usb.length == 10 mm and ports.usb.width == 4 mm, "USB-C slot 10 x 4"
    assert badge.word.size == 12 mm, "12 mm letters"
}
